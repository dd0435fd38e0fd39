#include "gpm/truncation.hpp"

#include <chrono>
#include <cmath>

#include "gpm/domain.hpp"
#include "gpm/error.hpp"
#include "gpm/study.hpp"
#include "gpm/norms.hpp"
#include "gpm/testfunctions.hpp"
#include "gpm/voronoi.hpp"
#include "gpm/weights.hpp"

namespace gpm {

Operator parse_operator(const std::string& s) {
  if (s == "interp") return Operator::interp;
  if (s == "grad") return Operator::grad;
  if (s == "lap") return Operator::lap;
  throw InputError("unknown operator '" + s + "'; valid: interp, grad, lap");
}

Volumes parse_volumes(const std::string& s) {
  if (s == "uniform") return Volumes::uniform;
  if (s == "voronoi") return Volumes::voronoi;
  throw InputError("unknown volume choice '" + s + "'; valid: uniform, voronoi");
}

std::string operator_name(Operator op) {
  return op == Operator::interp ? "interp" : op == Operator::grad ? "grad" : "lap";
}

std::string volumes_name(Volumes v) { return v == Volumes::uniform ? "uniform" : "voronoi"; }

TruncationResult truncation_error(const TruncationSetting& s) {
  const auto t0 = std::chrono::steady_clock::now();
  require_positive(s.h, "h");
  const Domain dom;
  const TestFunction& f = test_function(s.function);
  const WeightFunction& w = weight(s.weight);

  // Particles and volumes: |Ω_H|/N (imoto §5, thesis (A.10)) or Voronoi cell areas.
  const Particles p = jittered_grid(s.dx, s.seed, s.jitter);
  std::vector<double> V;
  if (s.volumes == Volumes::uniform)
    V = uniform_volumes(p, dom);
  else
    V = voronoi_cells(p, dom).area;

  const auto e = fused_errors(p, V, s.h, {ErrorRequest{w.name, s.op}}, {f.name});
  TruncationResult out;
  out.n = p.size();
  out.n_in_omega = p.count_in_omega();
  out.pairs = e.pairs;
  out.rel_error = e.errors.at(0).rel_error;
  out.h_exceeds_H = s.h >= dom.H;
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace gpm
