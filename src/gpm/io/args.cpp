#include "gpm/io/args.hpp"
#include "gpm/io/text_format.hpp"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <iostream>
#include <set>
#include <sstream>

#include "gpm/error.hpp"
#include "gpm/io/command_line.hpp"
#include "gpm/io/provenance.hpp"
#include "gpm/io/tsv.hpp"

namespace gpm {

Args::Args(std::string program, std::string summary)
    : program_(std::move(program)), summary_(std::move(summary)) {}

Args& Args::opt(const std::string& name, const std::string& def, const std::string& help) {
  order_.push_back(name);
  opts_[name] = Opt{def, help, def, false, false};
  return *this;
}

Args& Args::flag(const std::string& name, const std::string& help) {
  order_.push_back(name);
  opts_[name] = Opt{"", help, "", true, false};
  return *this;
}

Args& Args::output(const std::string& name, const std::string& def, const std::string& help) {
  opt(name, def, help);
  opts_[name].is_output = true;
  return *this;
}

Args& Args::store_output(const std::string& name, const std::string& def, const std::string& help) {
  output(name, def, help);
  opts_[name].is_store = true;
  return *this;
}

std::string Args::usage() const {
  std::ostringstream s;
  s << "usage: " << program_ << " [options]\n" << summary_ << "\n\noptions:\n";
  for (auto& n : order_) {
    auto& o = opts_.at(n);
    s << "  --" << n << (o.is_flag ? "" : o.is_output ? " PATH" : " VALUE");
    s << "\n      " << o.help;
    if (!o.is_flag && !o.def.empty()) s << " (default: " << o.def << ")";
    s << "\n";
  }
  s << "  --help\n      print this help and exit\n";
  return s.str();
}

void Args::parse(int argc, char** argv, int first) {
  std::set<std::string> named;
  for (int k = first; k < argc; ++k) {
    std::string a = argv[k];
    if (a == "--help" || a == "-h") {
      // A help text lost to a full disk is an error like any other lost output.
      if (!(std::cout << usage() << std::flush) || std::fflush(stdout) != 0) {
        std::fprintf(stderr, "%s: error: cannot write to standard output: %s\n",
                     program_.c_str(), std::strerror(errno));
        std::exit(1);
      }
      std::exit(0);
    }
    if (a.rfind("--", 0) != 0) throw InputError("unexpected argument '" + a + "' (see --help)");
    std::string name = a.substr(2), value;
    const auto eq = name.find('=');
    bool inline_value = eq != std::string::npos;
    if (inline_value) value = name.substr(eq + 1), name = name.substr(0, eq);
    auto it = opts_.find(name);
    if (it == opts_.end()) throw InputError("unknown option --" + name + " (see --help)");
    // An option given twice is a mistake, not an override: which one was meant?
    if (!named.insert(name).second) throw InputError("--" + name + " is given twice (see --help)");
    if (it->second.is_flag) {
      // A flag is on when named; `--polygons=no` must not turn it on, and reading "no" as
      // off would make `=yes`, `=0`, `=false` guesses: a value is refused instead.
      if (inline_value)
        throw InputError("--" + name + " is a flag and takes no value, got '" + a +
                         "' (omit it to leave it off)");
      it->second.given = true;
      continue;
    }
    if (!inline_value) {
      if (k + 1 >= argc) throw InputError("option --" + name + " needs a value");
      value = argv[++k];
    }
    it->second.value = value;
    it->second.given = true;
  }
  check_outputs();
}

bool in_result_store_folder(const std::string& path) {
  const std::filesystem::path dir = std::filesystem::absolute(path).parent_path();
  return dir.filename() == "paper" && dir.parent_path().filename() == "results";
}

namespace {
// Where no output option may point, whatever the file: a path that names a directory
// (a trailing /) or exceeds the system's limits, the documents' published values
// (tables/published/, transcribed by hand), and — for any output but a study's store file —
// the result store's folder (results/paper/: sealed study files, written through their
// store, and its logs and README, which no output replaces).
void check_output_place(const std::string& option, const std::string& path, bool store_file) {
  if (path.back() == '/')
    throw InputError(option + " '" + path.substr(0, 200) + "' ends in '/': it names a directory, give a file");
  if (path.size() > 4096)
    throw InputError(option + ": the path is " + std::to_string(path.size()) + " characters long (at most 4096)");
  for (std::size_t a = 0, b; a < path.size(); a = b + 1) {
    b = path.find('/', a);
    if (b == std::string::npos) b = path.size();
    if (b - a > 255)
      throw InputError(option + ": a name in the path is " + std::to_string(b - a) +
                       " characters long (at most 255): '" + path.substr(a, 40) + "...'");
  }
  const std::filesystem::path dir = std::filesystem::absolute(path).parent_path();
  if (dir.filename() == "published" && dir.parent_path().filename() == "tables")
    throw InputError(option + " " + path + ": tables/published holds the documents' values, transcribed "
                     "by hand; no program writes there (give another path)");
  if (!store_file && in_result_store_folder(path))
    throw InputError(option + " " + path + ": results/paper is the result store (sealed study files, "
                     "rechecks.log, verified.log, README.md); only a study's --out writes there "
                     "(give another path, e.g. data/paper/)");
}
}  // namespace

void Args::check_outputs() const {
  std::vector<std::pair<std::string, std::string>> outs;
  for (auto& n : order_) {
    const Opt& o = opts_.at(n);
    if (!o.is_output || o.value.empty()) continue;
    check_output_place("--" + n, o.value, o.is_store);
    // A program may write its own sealed files again (a study's second and third outputs are
    // sealed store files too); another program's are refused.
    if (o.is_store) check_output_path("--" + n, o.value, program_, /*writes=*/false);
    else check_output_path("--" + n, o.value, program_);
    outs.emplace_back("--" + n, o.value);
  }
  require_distinct_paths(outs);
}

void check_output_paths(const std::vector<std::pair<std::string, std::string>>& outputs,
                        const std::string& owner) {
  for (auto& [option, path] : outputs) check_output_path(option, path, owner);
  require_distinct_paths(outputs);
}

std::string Args::required(const std::string& name) const {
  const std::string v = str(name);
  if (v.empty()) throw InputError("--" + name + " PATH is required (see --help)");
  return v;
}

std::string Args::str(const std::string& name) const { return opts_.at(name).value; }
bool Args::has(const std::string& name) const { return opts_.at(name).given; }

bool read_decimal(const std::string& text, double& value) {
  // strtod alone would also take hex ("0x10"), "inf", "nan" and leading blanks.
  if (text.empty() || text.find_first_not_of("0123456789+-.eE") != std::string::npos)
    return false;
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  return end != text.c_str() && *end == '\0';
}

double parse_number(const std::string& text, const std::string& what) {
  // Accept "2^-9" and "2^k" as well as plain decimals.
  const auto caret = text.find('^');
  if (caret != std::string::npos) {
    double b = parse_number(text.substr(0, caret), what);
    double e = parse_number(text.substr(caret + 1), what);
    const double v = std::pow(b, e);
    if (!std::isfinite(v)) throw InputError(what + " must be finite, got '" + text + "'");
    return v;
  }
  if (text.empty()) throw InputError(what + ": empty value");
  double v = 0;
  if (!read_decimal(text, v)) {
    // "inf" and "nan" are numbers of a kind: say what is wrong with them.
    std::string t = text.substr(text[0] == '-' || text[0] == '+' ? 1 : 0);
    for (char& c : t) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (t == "inf" || t == "infinity" || t == "nan")
      throw InputError(what + " must be finite, got '" + text + "'");
    throw InputError(what + ": cannot parse '" + text + "' as a decimal number");
  }
  if (!std::isfinite(v)) throw InputError(what + " must be finite, got '" + text + "'");
  return v;
}

long long parse_integer(const std::string& text, const std::string& what, long long lo,
                        long long hi) {
  if (text.empty()) throw InputError(what + ": empty value");
  const std::size_t digits = text[0] == '-' || text[0] == '+' ? 1 : 0;
  if (text.size() == digits || text.find_first_not_of("0123456789", digits) != std::string::npos)
    throw InputError(what + ": cannot parse '" + text + "' as a decimal integer");
  errno = 0;
  const long long v = std::strtoll(text.c_str(), nullptr, 10);
  // ERANGE: strtoll clamps to LLONG_MAX/MIN, which would pass for the value given.
  if (errno == ERANGE || v < lo || v > hi)
    throw InputError(what + ": " + text + " is not an integer in [" + std::to_string(lo) + ", " +
                     std::to_string(hi) + "]");
  return v;
}

uint64_t parse_seed(const std::string& text, const std::string& what) {
  return static_cast<uint64_t>(parse_integer(text, what, 0, kMaxSeed));
}

double Args::num(const std::string& name) const { return parse_number(str(name), "--" + name); }

double Args::positive(const std::string& name) const {
  const double v = num(name);
  if (!(v > 0)) throw InputError("--" + name + " must be > 0, got " + str(name));
  return v;
}

double Args::tolerance(const std::string& name) const {
  // 0 would never be met; 1 or more is met before the first step (CG stops at once).
  const double v = num(name);
  if (!(v > 0 && v < 1)) throw InputError("--" + name + " must lie in (0, 1), got " + str(name));
  return v;
}

long long Args::integer(const std::string& name, long long lo, long long hi) const {
  return parse_integer(str(name), "--" + name, lo, hi);
}

uint64_t Args::seed(const std::string& name) const { return parse_seed(str(name), "--" + name); }

std::vector<uint64_t> parse_seeds(const std::string& text, const std::string& what) {
  std::vector<uint64_t> out;
  std::string item;
  std::istringstream ss(text);
  while (std::getline(ss, item, ','))
    if (!item.empty()) out.push_back(parse_seed(item, what));
  if (out.empty()) throw InputError(what + ": no seed given");
  return out;
}

std::vector<uint64_t> Args::seeds(const std::string& name) const {
  return parse_seeds(str(name), "--" + name);
}

std::vector<std::string> Args::list(const std::string& name) const {
  std::vector<std::string> out;
  std::string item;
  std::istringstream ss(str(name));
  while (std::getline(ss, item, ',')) if (!item.empty()) out.push_back(item);
  return out;
}

std::vector<double> Args::nums(const std::string& name) const {
  std::vector<double> out;
  for (auto& s : list(name)) out.push_back(parse_number(s, "--" + name));
  return out;
}

std::vector<std::pair<std::string, std::string>> Args::values() const {
  std::vector<std::pair<std::string, std::string>> v;
  for (auto& n : order_) {
    auto& o = opts_.at(n);
    v.emplace_back(n, o.is_flag ? (o.given ? "yes" : "no") : o.value);
  }
  return v;
}

namespace {

// Empty if everything written to stdout reached it; else why not.  stdout to a file or a
// pipe is block-buffered, so a full disk shows only here, at the final flush.
std::string stdout_failure() {
  errno = 0;
  std::cout.flush();
  const bool cout_bad = !std::cout;
  int err = errno;
  if (std::fflush(stdout) != 0) err = errno;
  if (!cout_bad && !std::ferror(stdout)) return "";
  return err ? std::strerror(err) : "an earlier write failed";
}

}  // namespace

int run_main(const std::string& program, int (*body)(int, char**), int argc, char** argv) {
  try {
    set_program(program);
    set_command_line(argc, argv);
    const int rc = body(argc, argv);
    const std::string lost = stdout_failure();
    if (!lost.empty()) {
      std::fprintf(stderr, "%s: error: cannot write to standard output: %s\n", program.c_str(),
                   lost.c_str());
      return 1;
    }
    return rc;
  } catch (const InputError& e) {
    std::fprintf(stderr, "%s: error: %s\n", program.c_str(), clip_long_words(e.what()).c_str());
    return 2;
  } catch (const NumericalError& e) {
    std::fprintf(stderr, "%s: numerical failure: %s\n", program.c_str(), clip_long_words(e.what()).c_str());
    return 3;
  } catch (const StoreMismatch& e) {
    std::fprintf(stderr, "%s: store check failed: %s\n", program.c_str(), clip_long_words(e.what()).c_str());
    return 4;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: error: %s\n", program.c_str(), clip_long_words(e.what()).c_str());
    return 1;
  }
}

}  // namespace gpm
