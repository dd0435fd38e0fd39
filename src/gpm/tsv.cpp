#include "gpm/tsv.hpp"

#include <omp.h>
#include <unistd.h>

#include <charconv>
#include <chrono>
#include <cmath>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "gpm/command_line.hpp"
#include "gpm/error.hpp"
#include "gpm/provenance.hpp"

namespace gpm {

void TsvTable::set(const std::string& key, const std::string& value) {
  for (auto& kv : meta)
    if (kv.first == key) {
      kv.second = value;
      return;
    }
  meta.emplace_back(key, value);
}

void TsvTable::set(const std::string& key, double value) { set(key, fmt(value)); }

std::optional<std::string> TsvTable::get(const std::string& key) const {
  for (auto& kv : meta)
    if (kv.first == key) return kv.second;
  return std::nullopt;
}

void TsvTable::add_row(std::vector<std::string> row) { rows.push_back(std::move(row)); }

int TsvTable::column(const std::string& name) const {
  for (std::size_t c = 0; c < columns.size(); ++c)
    if (columns[c] == name) return static_cast<int>(c);
  return -1;
}

void TsvTable::write(std::ostream& out) const {
  for (auto& [k, v] : meta) out << "# " << k << " = " << v << '\n';
  for (std::size_t c = 0; c < columns.size(); ++c) out << (c ? "\t" : "") << columns[c];
  out << '\n';
  for (auto& r : rows) {
    for (std::size_t c = 0; c < r.size(); ++c) out << (c ? "\t" : "") << r[c];
    out << '\n';
  }
}

void TsvTable::save(const std::string& path) const {
  namespace fs = std::filesystem;
  const fs::path p(path);
  if (p.has_parent_path()) fs::create_directories(p.parent_path());
  const std::string tmp = path + ".tmp." + std::to_string(::getpid());
  {
    std::ofstream out(tmp);
    if (!out) throw InputError("cannot write " + tmp);
    write(out);
    out.flush();
    if (!out) throw InputError("write failed: " + tmp);
  }
  fs::rename(tmp, p);
}

TsvTable TsvTable::load(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError("cannot read data file " + path);
  TsvTable t;
  std::string line;
  bool have_header = false;
  auto split = [](const std::string& s) {
    std::vector<std::string> out;
    std::string cell;
    std::istringstream ss(s);
    while (std::getline(ss, cell, '\t')) out.push_back(cell);
    return out;
  };
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    if (line.rfind("# ", 0) == 0) {
      const auto eq = line.find(" = ");
      if (eq != std::string::npos) t.meta.emplace_back(line.substr(2, eq - 2), line.substr(eq + 3));
      continue;
    }
    if (!have_header) {
      t.columns = split(line);
      have_header = true;
    } else {
      t.rows.push_back(split(line));
    }
  }
  if (!have_header) throw InputError("data file " + path + " has no column header");
  return t;
}

std::vector<std::vector<std::string>> TsvTable::load_matching(
    const std::string& path, const std::vector<std::pair<std::string, std::string>>& params) {
  if (!std::filesystem::exists(path)) return {};
  TsvTable t;
  try {
    t = load(path);
  } catch (const InputError&) {
    return {};
  }
  for (auto& [k, v] : params) {
    auto have = t.get(k);
    if (!have || *have != v) return {};
  }
  return t.rows;
}

std::string fmt(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buf[64];
  auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

std::string fmt(long long v) { return std::to_string(v); }

namespace {
std::string g_command_line;
}

void set_command_line(int argc, char** argv) {
  std::string out;
  for (int i = 0; i < argc; ++i) {
    const std::string a = argv[i];
    const bool plain = !a.empty() && a.find_first_not_of(
        "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789-_./=,:+^%@") ==
        std::string::npos;
    if (i) out += ' ';
    if (plain) {
      out += a;
    } else {
      out += '\'';
      for (char c : a) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
      out += '\'';
    }
  }
  g_command_line = out;
}

const std::string& command_line() { return g_command_line; }

void add_provenance(TsvTable& t) {
  if (!g_command_line.empty()) t.set("command", g_command_line);
  t.set("git_revision", git_revision());
  char host[256] = {0};
  ::gethostname(host, sizeof host - 1);
  t.set("host", host);
  std::time_t now = std::time(nullptr);
  char date[64];
  std::strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  t.set("written_utc", date);
  t.set("omp_threads", fmt(static_cast<long long>(omp_get_max_threads())));
}

}  // namespace gpm
