// A small command-line parser shared by every program: `--name value` options with
// defaults and help text, strict number parsing, and one-line errors naming the bad value.
// Everything a program is told is checked here, before it does any work: numbers are
// decimal (no hex, no trailing text), integers are range-checked, flags take no value,
// and output paths name a regular file or nothing yet.
#pragma once
#include <climits>
#include <cstdint>
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
  // Declare an output path (`def` may be empty).  parse() refuses a value that names
  // anything but a regular file or a new path (a directory, a device such as /dev/null, a
  // symbolic link, a path under a non-directory) and two outputs naming one file, so a
  // program fails before its work, not after it (check_output_path, tsv.hpp).
  Args& output(const std::string& name, const std::string& def, const std::string& help);
  // The data file of a study (the result store): an output that may name a sealed store file
  // of this program (check_output_path's owner) and that parse() checks for its kind only, not
  // for a writable folder: its modes that write nothing (--verify, --census) work on a
  // read-only store; the study checks the folder when it writes.
  Args& store_output(const std::string& name, const std::string& def, const std::string& help);
  // Parses argv.  On --help prints usage to stdout and exits 0; on an unknown option,
  // a missing value, a value given to a flag (`--polygons=no`) or a bad output path
  // throws InputError.
  void parse(int argc, char** argv, int first = 1);

  std::string str(const std::string& name) const;
  // The value of an option the program cannot run without (an output path, say):
  // InputError "--NAME PATH is required (see --help)" when it is empty.
  std::string required(const std::string& name) const;
  double num(const std::string& name) const;        // finite, else InputError
  double positive(const std::string& name) const;   // finite and > 0
  // Decimal integers ("0x10", "1e1", "5.5" refused); out of [lo, hi] refused naming both.
  long long integer(const std::string& name, long long lo = LLONG_MIN,
                    long long hi = LLONG_MAX) const;
  // A jitter seed: an integer in [0, kMaxSeed].
  uint64_t seed(const std::string& name = "seed") const;
  // A comma-separated list of seeds, at least one.
  std::vector<uint64_t> seeds(const std::string& name) const;
  // A relative tolerance: a number in the open interval (0, 1).
  double tolerance(const std::string& name) const;
  bool has(const std::string& name) const;           // flag given
  std::vector<double> nums(const std::string& name) const;  // comma-separated list
  std::vector<std::string> list(const std::string& name) const;
  std::string usage() const;
  // All options and their values, for the data file header.
  std::vector<std::pair<std::string, std::string>> values() const;

 private:
  struct Opt {
    std::string def, help, value;
    bool is_flag = false, given = false, is_output = false, is_store = false;
  };
  void check_outputs() const;
  std::string program_, summary_;
  std::vector<std::string> order_;
  std::map<std::string, Opt> opts_;
};

// check_output_path (tsv.hpp) for each (option, path), then require_distinct_paths over all:
// for outputs a program derives from its options (a --prefix, the siblings of --out), which
// parse() cannot know.  owner: the program running, whose own sealed store files it may
// write again (a study's --out among them); "" for a program that writes no store file.
// Whether `path` lies directly in a result store's folder (…/results/paper/), by name: where
// only a study's store file is written and no sealed file is a quick-profile cache.
bool in_result_store_folder(const std::string& path);

void check_output_paths(const std::vector<std::pair<std::string, std::string>>& outputs,
                        const std::string& owner = "");

// Strict parse of a decimal number or an expression 2^-k; throws InputError naming `what`.
double parse_number(const std::string& text, const std::string& what);
// The decimal number `text` spells, nothing else: an optional sign, digits, a point and an
// exponent ("0x10", "inf", " 1", "1x" give false).  Out-of-range values give ±inf or 0.
bool read_decimal(const std::string& text, double& value);
// Strict parse of a decimal integer in [lo, hi]; throws InputError naming `what` and `text`.
long long parse_integer(const std::string& text, const std::string& what,
                        long long lo = LLONG_MIN, long long hi = LLONG_MAX);
// Seeds are recorded as signed 64-bit integers in every data file: [0, 2^63 − 1].
constexpr long long kMaxSeed = LLONG_MAX;
uint64_t parse_seed(const std::string& text, const std::string& what);
// A comma-separated list of seeds, at least one.
std::vector<uint64_t> parse_seeds(const std::string& text, const std::string& what);

// Runs `body` and turns gpm errors into one line on stderr and an exit code: 2 bad input,
// 3 numerical failure, 4 a result store that disagrees with the code, 1 anything else —
// including a standard output that could not be written (a full disk, /dev/full).
int run_main(const std::string& program, int (*body)(int, char**), int argc, char** argv);

}  // namespace gpm
