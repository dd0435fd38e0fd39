#include "gpm/args.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <sstream>

#include "gpm/command_line.hpp"
#include "gpm/error.hpp"
#include "gpm/provenance.hpp"

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

std::string Args::usage() const {
  std::ostringstream s;
  s << "usage: " << program_ << " [options]\n" << summary_ << "\n\noptions:\n";
  for (auto& n : order_) {
    auto& o = opts_.at(n);
    s << "  --" << n << (o.is_flag ? "" : " VALUE");
    s << "\n      " << o.help;
    if (!o.is_flag && !o.def.empty()) s << " (default: " << o.def << ")";
    s << "\n";
  }
  s << "  --help\n      print this help and exit\n";
  return s.str();
}

void Args::parse(int argc, char** argv, int first) {
  for (int k = first; k < argc; ++k) {
    std::string a = argv[k];
    if (a == "--help" || a == "-h") {
      std::cout << usage();
      std::exit(0);
    }
    if (a.rfind("--", 0) != 0) throw InputError("unexpected argument '" + a + "' (see --help)");
    std::string name = a.substr(2), value;
    const auto eq = name.find('=');
    bool inline_value = eq != std::string::npos;
    if (inline_value) value = name.substr(eq + 1), name = name.substr(0, eq);
    auto it = opts_.find(name);
    if (it == opts_.end()) throw InputError("unknown option --" + name + " (see --help)");
    if (it->second.is_flag) {
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
}

std::string Args::str(const std::string& name) const { return opts_.at(name).value; }
bool Args::has(const std::string& name) const { return opts_.at(name).given; }

double parse_number(const std::string& text, const std::string& what) {
  // Accept "2^-9" and "2^k" as well as plain decimals.
  const auto caret = text.find('^');
  if (caret != std::string::npos) {
    double b = parse_number(text.substr(0, caret), what);
    double e = parse_number(text.substr(caret + 1), what);
    return std::pow(b, e);
  }
  if (text.empty()) throw InputError(what + ": empty value");
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || *end != '\0')
    throw InputError(what + ": cannot parse '" + text + "' as a number");
  if (!std::isfinite(v)) throw InputError(what + " must be finite, got '" + text + "'");
  return v;
}

double Args::num(const std::string& name) const { return parse_number(str(name), "--" + name); }

double Args::positive(const std::string& name) const {
  const double v = num(name);
  if (!(v > 0)) throw InputError("--" + name + " must be > 0, got " + str(name));
  return v;
}

long long Args::integer(const std::string& name) const {
  const std::string t = str(name);
  char* end = nullptr;
  const long long v = std::strtoll(t.c_str(), &end, 10);
  if (t.empty() || *end != '\0') throw InputError("--" + name + ": cannot parse '" + t + "' as an integer");
  return v;
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

int run_main(const std::string& program, int (*body)(int, char**), int argc, char** argv) {
  try {
    set_program(program);
    set_command_line(argc, argv);
    return body(argc, argv);
  } catch (const InputError& e) {
    std::fprintf(stderr, "%s: error: %s\n", program.c_str(), e.what());
    return 2;
  } catch (const NumericalError& e) {
    std::fprintf(stderr, "%s: numerical failure: %s\n", program.c_str(), e.what());
    return 3;
  } catch (const StoreMismatch& e) {
    std::fprintf(stderr, "%s: store check failed: %s\n", program.c_str(), e.what());
    return 4;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: error: %s\n", program.c_str(), e.what());
    return 1;
  }
}

}  // namespace gpm
