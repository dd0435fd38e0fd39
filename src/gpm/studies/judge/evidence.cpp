#include "gpm/studies/judge/evidence.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <limits>

#include "gpm/io/args.hpp"  // parse_integer
#include "gpm/operators/norms.hpp"  // two_level_rate

namespace gpm {

bool cell_number(const std::string& s, double& value) {
  std::size_t i = !s.empty() && s[0] == '-' ? 1 : 0;
  const std::size_t mantissa = i;
  while (i < s.size() && (std::isdigit(static_cast<unsigned char>(s[i])) || s[i] == '.')) ++i;
  if (i == mantissa) return false;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    const std::size_t digits = i;
    while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i;
    if (i == digits) return false;
  }
  if (i != s.size()) return false;
  value = std::strtod(s.c_str(), nullptr);
  return std::isfinite(value);
}

double cell_number_or(const std::string& s, double otherwise) {
  double v;
  return cell_number(s, v) ? v : otherwise;
}

EvidenceSeriesMap read_series(const TsvTable& t, const std::vector<std::string>& keys, const std::string& error) {
  std::vector<int> ck;
  for (auto& k : keys) ck.push_back(t.require_column(k));
  const int cl = t.require_column("level"), ch = t.require_column("h"), ce = t.require_column(error);
  EvidenceSeriesMap out;
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    double e = 0;  // NA (a blown-up series), nan, inf, 0 or below: no point
    if (!cell_number(t.text(i, ce), e) || !std::isfinite(e) || e <= 0) continue;
    std::vector<std::string> key;
    for (int c : ck) key.push_back(t.text(i, c));
    out[key][static_cast<int>(t.integer(i, cl))] = {t.number(i, ch), e};
  }
  return out;
}

std::string file_arg(const StoreFile& f, const std::string& option) {
  for (std::size_t i = 0; i + 1 < f.args.size(); i += 2)
    if (f.args[i] == option) return f.args[i + 1];
  return "";
}

int file_seed(const StoreFile& f) {
  const std::string v = file_arg(f, "--seed");
  return v.empty() ? 1 : static_cast<int>(parse_integer(v, f.name + " --seed", 1, 1 << 30));
}

std::vector<std::string> setup_args(const StoreFile& f) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i + 1 < f.args.size(); i += 2)
    if (f.args[i] != "--seed" && f.args[i] != "--solver") out.insert(out.end(), {f.args[i], f.args[i + 1]});
  return out;
}

std::string file_solver(const StoreFile& f) { return file_arg(f, "--solver"); }

std::vector<const StoreFile*> realizations_of(const RegisteredStudy& study, const StoreFile& f) {
  std::vector<const StoreFile*> out;
  for (const StoreFile& g : study.store_files)
    if (&g != &f && file_seed(g) != file_seed(f) && file_solver(g) == file_solver(f) && setup_args(g) == setup_args(f))
      out.push_back(&g);
  return out;
}

const StoreFile* seed_one_of(const RegisteredStudy& study, const StoreFile& f) {
  for (const StoreFile& g : study.store_files)
    if (file_seed(g) == 1 && file_solver(g) == file_solver(f) && setup_args(g) == setup_args(f)) return &g;
  return nullptr;
}

std::string number_cell(double v) { return std::isnan(v) ? "NA" : fmt(v); }

double point_rate(const EvidencePoint& a, const EvidencePoint& b) { return two_level_rate(a.h, a.error, b.h, b.error); }

double series_rate(const EvidenceSeries& s, int lo, int hi) {
  const auto a = s.find(lo), b = s.find(hi);
  if (a == s.end() || b == s.end()) return std::numeric_limits<double>::quiet_NaN();
  return point_rate(a->second, b->second);
}

double error_constant(const EvidencePoint& pt, double p) { return pt.error / std::pow(pt.h, p); }

}  // namespace gpm
