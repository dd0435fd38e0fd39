// A small command-line parser shared by every program: `--name value` options with
// defaults and help text, strict number parsing, and one-line errors naming the bad value.
#pragma once
#include <map>
#include <string>
#include <vector>

namespace gpm {

class Args {
 public:
  Args(std::string program, std::string summary);
  // Declare an option before parse(); `def` is its default (as text).
  Args& opt(const std::string& name, const std::string& def, const std::string& help);
  Args& flag(const std::string& name, const std::string& help);
  // Parses argv.  On --help prints usage to stdout and exits 0; on an unknown option
  // or a missing value throws InputError.
  void parse(int argc, char** argv, int first = 1);

  std::string str(const std::string& name) const;
  double num(const std::string& name) const;        // finite, else InputError
  double positive(const std::string& name) const;   // finite and > 0
  long long integer(const std::string& name) const;
  bool has(const std::string& name) const;           // flag given
  std::vector<double> nums(const std::string& name) const;  // comma-separated list
  std::vector<std::string> list(const std::string& name) const;
  std::string usage() const;
  // All options and their values, for the data file header.
  std::vector<std::pair<std::string, std::string>> values() const;

 private:
  struct Opt {
    std::string def, help, value;
    bool is_flag = false, given = false;
  };
  std::string program_, summary_;
  std::vector<std::string> order_;
  std::map<std::string, Opt> opts_;
};

// Strict parse of a decimal number or an expression 2^-k; throws InputError naming `what`.
double parse_number(const std::string& text, const std::string& what);

// Runs `body` and turns gpm errors into one line on stderr and an exit code: 2 bad input,
// 3 numerical failure, 4 a result store that disagrees with the code, 1 anything else.
int run_main(const std::string& program, int (*body)(int, char**), int argc, char** argv);

}  // namespace gpm
