// gpm — the common core on the command line, for ad hoc studies.
//
//   gpm weights     the weight-function registry with computed properties
//   gpm particles   a jittered-grid distribution
//   gpm voronoi     Voronoi cell areas and covering distances, r_c
//   gpm trunc       relative ℓ∞ error of one operator at one resolution
//   gpm poisson, gpm heat, gpm smoothing   one PDE problem or one smoothing error
//   gpm study       the study catalog: list the studies, or run one by name
//   gpm store-rates the documents' rates judged against the result store (verdicts, boards;
//                   written to the files it is given, not to stdout)
//   gpm checked-reasons  the reasons for differing rates, each checked against the store
//                   (written to the files it is given, not to stdout)
//   gpm verdicts    page one of the report: a verdict per document item (written to --out)
//   gpm decisions   the documents' open set-up questions with the store's evidence (to --out)
//
// Every subcommand writes TSV to stdout (a `# key = value` header, then columns) and
// has --help.  Errors are one line on stderr and a non-zero exit.
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <string>

#include "gpm/error.hpp"
#include "gpm/geometry/domain.hpp"
#include "gpm/geometry/influence_radius.hpp"
#include "gpm/geometry/volumes.hpp"
#include "gpm/geometry/voronoi.hpp"
#include "gpm/io/args.hpp"
#include "gpm/io/provenance.hpp"
#include "gpm/io/tsv.hpp"
#include "gpm/operators/testfunctions.hpp"
#include "gpm/operators/truncation.hpp"
#include "gpm/solvers/heat.hpp"
#include "gpm/solvers/laplacian_matrix.hpp"
#include "gpm/solvers/poisson.hpp"
#include "gpm/solvers/poisson_probes.hpp"
#include "gpm/studies/catalog.hpp"
#include "gpm/studies/checked_reasons.hpp"
#include "gpm/studies/decisions.hpp"
#include "gpm/studies/heat_tables.hpp"
#include "gpm/studies/page_verdicts.hpp"
#include "gpm/studies/profile.hpp"
#include "gpm/studies/registry.hpp"
#include "gpm/studies/rates.hpp"
#include "gpm/studies/setup_identification.hpp"
#include "gpm/studies/store.hpp"
#include "gpm/studies/verdicts.hpp"
#include "gpm/theory/smoothing.hpp"
#include "gpm/weights/weights.hpp"

using namespace gpm;

namespace {

// The table to stdout; a failed write (a full disk) stops the subcommand with the reason,
// read from errno at once, before later calls can overwrite it.
void print(const TsvTable& t) {
  t.write(std::cout);
  if (!std::cout.flush())
    throw std::runtime_error(std::string("cannot write to standard output: ") +
                             std::strerror(errno));
}

TsvTable header_from(const Args& a, const std::string& sub) {
  TsvTable t;
  t.set("program", "gpm " + sub);
  for (auto& [k, v] : a.values()) t.set(k, v);
  add_provenance(t);
  return t;
}

const char* yes(bool b) { return b ? "yes" : "no"; }

constexpr double kPi = 3.14159265358979323846;

// Refuses an influence radius a local operator cannot have: not in (0, side of Omega_H).
// Beyond the side every particle is a neighbour of every other (O(N^2) pairs); a tiny
// --m makes h non-finite through h = 2.6·2^(5/m−5)·dx^(1/m).  `opt` is what gave h.
void require_local_h(double h, const Args& a, const std::string& opt) {
  if (!(h > 0 && h < max_influence_radius()))
    throw InputError("--" + opt + " " + a.str(opt) + " gives h = " + fmt(h) + ": h must lie in (0, " +
                     fmt(max_influence_radius()) + "), the side of Omega_H being the most a " +
                     "local operator can reach");
}

// Runs `work`; the kernel's cell list has cells of size h/4, so a tiny h asks for more cells
// than it holds, and that message is re-thrown naming the option that gave h.
template <class F>
auto naming_small_h(const Args& a, const std::string& opt, F&& work) {
  try {
    return work();
  } catch (const InputError& e) {
    if (std::string(e.what()).rfind("cell list:", 0) != 0) throw;
    throw InputError("--" + opt + " " + a.str(opt) + " is too small: " + e.what());
  }
}

// Memory per particle of the subcommands that print one table row (of strings) per
// particle, or per polygon vertex: peak RSS / N measured at dx = 2^-10 (particles 286 bytes,
// voronoi 333) and 2^-9 (voronoi --polygons 1360), with half as much again to spare.
constexpr double kParticlesBytes = 450, kVoronoiBytes = 500, kPolygonsBytes = 2000;

int cmd_weights(int argc, char** argv) {
  Args a("gpm weights", "The weight registry: each weight's computed properties (TSV).");
  a.opt("name", "", "only this weight (default: all)");
  a.parse(argc, argv, 2);
  TsvTable t = header_from(a, "weights");
  t.columns = {"name", "source", "role", "constant", "norm_2d", "norm_3d", "order_k", "positive",
               "p0", "continuous", "c1", "hyp_1_2", "hyp_1_3", "imoto_hyp2_k", "inv_r2_integral",
               "admissible"};
  std::vector<std::string> names = a.str("name").empty() ? weight_names()
                                                         : std::vector<std::string>{a.str("name")};
  for (auto& n : names) {
    const auto& w = weight(n);
    const auto p = compute_properties(w);
    TsvRow row = t.named_row();
    row["name"] = w.name, row["source"] = w.source, row["role"] = w.role, row["constant"] = fmt(w.constant);
    row["norm_2d"] = fmt(p.norm_2d), row["norm_3d"] = fmt(p.norm_3d), row["order_k"] = fmt(p.order_k);
    row["positive"] = yes(p.positive), row["p0"] = fmt(p.p0), row["continuous"] = yes(p.continuous);
    row["c1"] = yes(p.c1), row["hyp_1_2"] = yes(p.hyp_1_2), row["hyp_1_3"] = yes(p.hyp_1_3);
    row["imoto_hyp2_k"] = fmt(p.imoto_hyp2_k), row["inv_r2_integral"] = fmt(p.inv_r2_integral);
    row["admissible"] = yes(p.admissible);
    t.add_row(row);
  }
  print(t);
  return 0;
}

int cmd_particles(int argc, char** argv) {
  Args a("gpm particles", "A jittered-grid particle distribution in Omega_H (TSV: x y in_omega i j).");
  a.opt("dx", "2^-5", "grid spacing");
  a.opt("seed", "1", "random seed of the jitter");
  a.opt("jitter", "0.25", "jitter amplitude as a fraction of dx (0 = plain grid)");
  a.parse(argc, argv, 2);
  const double dx = a.positive("dx");
  const uint64_t seed = a.seed();
  const double jitter = a.num("jitter");
  require_grid_fits_memory(dx, kParticlesBytes, "--dx");
  const auto p = jittered_grid(dx, seed, jitter);
  TsvTable t = header_from(a, "particles");
  const Domain dom;
  t.set("dx_value", dx);
  t.set("H", dom.H);
  t.set("omega_H", "(" + fmt(dom.lo()) + ", " + fmt(dom.hi()) + ")^2, the square (Omega = (0, 1)^2)");
  t.set("area_H", dom.area_H());
  t.set("volume_mismatch", "|Omega_H|/(N dx^2) - 1 = " + fmt(volume_mismatch(p, dx, dom)));
  t.set("N", fmt(p.size()));
  t.set("N_in_omega", fmt(p.count_in_omega()));
  t.columns = {"x", "y", "in_omega", "i", "j"};
  for (std::size_t k = 0; k < p.size(); ++k) {
    TsvRow row = t.named_row();
    row["x"] = fmt(p.x[k]), row["y"] = fmt(p.y[k]), row["in_omega"] = fmt(p.in_omega[k]);
    row["i"] = fmt(p.gi[k]), row["j"] = fmt(p.gj[k]);
    t.add_row(row);
  }
  print(t);
  return 0;
}

int cmd_voronoi(int argc, char** argv) {
  Args a("gpm voronoi",
         "Voronoi cells of Omega_H: per particle area and covering distance (TSV);\n"
         "the header gives N, the area sum and the covering radius r_c.");
  a.opt("dx", "2^-5", "grid spacing");
  a.opt("seed", "1", "random seed of the jitter");
  a.opt("jitter", "0.25", "jitter amplitude as a fraction of dx");
  a.flag("polygons", "print the clipped cell polygons instead (columns: particle, x, y)");
  a.parse(argc, argv, 2);
  const double dx = a.positive("dx");
  const uint64_t seed = a.seed();
  const double jitter = a.num("jitter");
  require_grid_fits_memory(dx, a.has("polygons") ? kPolygonsBytes : kVoronoiBytes, "--dx");
  const auto p = jittered_grid(dx, seed, jitter);
  const auto v = voronoi_cells(p, Domain{}, a.has("polygons"));
  TsvTable t = header_from(a, "voronoi");
  t.set("N", fmt(p.size()));
  t.set("area_sum", v.area_sum);
  t.set("covering_radius", v.covering_radius);
  t.set("worst_particle", fmt(v.worst));
  if (a.has("polygons")) {
    t.columns = {"particle", "x", "y"};
    for (std::size_t i = 0; i < p.size(); ++i)
      for (auto k = v.offset[i]; k < v.offset[i + 1]; ++k) {
        TsvRow row = t.named_row();
        row["particle"] = fmt(i), row["x"] = fmt(v.px[k]), row["y"] = fmt(v.py[k]);
        t.add_row(row);
      }
  } else {
    t.columns = {"x", "y", "area", "cover"};
    for (std::size_t i = 0; i < p.size(); ++i) {
      TsvRow row = t.named_row();
      row["x"] = fmt(p.x[i]), row["y"] = fmt(p.y[i]);
      row["area"] = fmt(v.area[i]), row["cover"] = fmt(v.cover[i]);
      t.add_row(row);
    }
  }
  print(t);
  return 0;
}

int cmd_trunc(int argc, char** argv) {
  Args a("gpm trunc",
         "Relative l-infinity truncation error of one operator over the particles in Omega:\n"
         "  interp: |v - Pi_h v| / |v|,  grad: |grad v - grad_h v| / |grad v|,\n"
         "  lap: |lap v - lap_h v| / |lap v|  (maxima over particles in Omega).\n"
         "Give the influence radius either as --h or as a regular order --m, which uses\n"
         "imoto's h = 2.6 * 2^(5/m - 5) * dx^(1/m).");
  a.opt("operator", "interp", "interp | grad | lap");
  a.opt("weight", "quadratic_spike", "a registry name (gpm weights lists them)");
  a.opt("volumes", "uniform", "uniform (|Omega_H|/N) | voronoi (cell areas)");
  a.opt("function", "sin2pi", "test function: sin2pi | quartic | linear");
  a.opt("dx", "2^-7", "grid spacing");
  a.opt("h", "", "influence radius");
  a.opt("m", "", "regular order m (alternative to --h)");
  a.opt("seed", "1", "random seed of the jitter");
  a.opt("jitter", "0.25", "jitter amplitude in units of dx (0: the plain grid)");
  a.parse(argc, argv, 2);
  TruncationSetting s;
  s.op = parse_operator(a.str("operator"));
  s.weight = weight(a.str("weight")).name;  // validates the name first
  s.volumes = parse_volumes(a.str("volumes"));
  s.function = a.str("function");
  s.dx = a.positive("dx");
  s.seed = a.seed();
  s.jitter = a.num("jitter");
  if (a.str("h").empty() == a.str("m").empty())
    throw InputError("give exactly one of --h or --m");
  const std::string h_opt = a.str("h").empty() ? "m" : "h";
  s.h = a.str("h").empty() ? imoto_h(a.positive("m"), s.dx) : a.positive("h");
  require_local_h(s.h, a, h_opt);
  require_grid_fits_memory(s.dx, truncation_bytes_per_particle(s.volumes), "--dx");
  const TruncationResult r = naming_small_h(a, h_opt, [&] { return truncation_error(s); });
  TsvTable t = header_from(a, "trunc");
  t.set("h_used", s.h);
  t.set("largest_spacing", r.largest_spacing);
  t.set("isolated_targets", fmt(r.isolated_targets));
  if (r.isolated_targets > 0) {
    char msg[320];
    std::snprintf(msg, sizeof msg,
                  "h = %g is below the largest particle spacing %.4g: %zu of %zu targets in "
                  "Omega have no neighbour but themselves, so rel_error is no approximation "
                  "error", s.h, r.largest_spacing, r.isolated_targets, r.n_in_omega);
    t.set("warning", msg);
    std::fprintf(stderr, "gpm trunc: warning: %s\n", msg);
  }
  // Where the maximum sits: the particle, its distance to the boundary of Ω = (0,1)², in
  // units of h (below 1: its stencil reaches outside Ω).
  const double to_boundary = std::min({r.worst_x, 1 - r.worst_x, r.worst_y, 1 - r.worst_y});
  t.set("where", "worst_x, worst_y: the particle of Omega with the largest error; "
                 "worst_to_boundary_over_h: its distance to the boundary of Omega / h");
  t.columns = {"dx", "h", "N", "N_in_omega", "pairs", "rel_error", "worst_x", "worst_y",
               "worst_to_boundary_over_h", "time_s"};
  TsvRow row = t.named_row();
  row["dx"] = fmt(s.dx), row["h"] = fmt(s.h), row["N"] = fmt(r.n), row["N_in_omega"] = fmt(r.n_in_omega);
  row["pairs"] = fmt(r.pairs), row["rel_error"] = fmt(r.rel_error);
  row["worst_x"] = fmt(r.worst_x), row["worst_y"] = fmt(r.worst_y);
  row["worst_to_boundary_over_h"] = fmt(to_boundary / s.h), row["time_s"] = fmt(r.seconds);
  t.add_row(row);
  if (r.h_exceeds_H)
    std::fprintf(stderr, "gpm trunc: warning: h = %g >= H = 0.1: stencils near the boundary are "
                         "cut by the edge of Omega_H (outside the theory)\n", s.h);
  print(t);
  return 0;
}

// One discrete Poisson problem of thesis §4.2 (u = sin 2π(x+y), uniform volumes), with the
// error, where it sits, and the solver's counts: the ad hoc run behind Table 4.4.
// What gpm poisson and gpm heat share: the options of one particle set, its volumes, the
// weight, h and the Laplacian's storage.
Args& add_pde_options(Args& a) {
  return a.opt("dx", "2^-6", "grid spacing")
      .opt("weight", "quartic_polynomial", "registry weight (gpm weights lists them)")
      .opt("h", "", "influence radius (or --h-rule)")
      .opt("h-rule", "h10", "h10 = (2.6^4 2^-10 dx)^(1/4) as printed, h15 = (2.6^4 2^-15 dx)^(1/4)")
      .opt("seed", "1", "jitter seed")
      .opt("jitter", "0.25", "jitter amplitude in units of dx (0: the plain grid)")
      .opt("volumes", "lattice", "lattice: |Omega_H|/N (thesis (A.10)); cell: dx^2 (a diagnostic)")
      .opt("storage", "auto", "Laplacian storage: auto, assembled, matrix_free");
}

struct PdeOptions {
  PdeVolumes volumes = PdeVolumes::lattice;
  double dx = 0, h = 0;
  std::string h_opt;  // the option h came from, for the messages
  const WeightFunction* w = nullptr;
  LaplacianStorage storage = LaplacianStorage::automatic;
};

// Reads and checks the options of add_pde_options (InputError naming the bad one).
PdeOptions read_pde_options(const Args& a) {
  PdeOptions s;
  s.volumes = parse_pde_volumes(a.str("volumes"));
  s.dx = a.positive("dx");
  s.h_opt = a.str("h").empty() ? "h-rule" : "h";
  s.h = a.str("h").empty() ? pde_h(parse_h_rule(a.str("h-rule")), s.dx) : a.positive("h");
  require_local_h(s.h, a, s.h_opt);
  const double jitter = a.num("jitter");
  if (jitter < 0 || jitter >= 0.5) throw InputError("--jitter: " + a.str("jitter") + " is not in [0, 0.5)");
  a.seed();
  s.w = &weight(a.str("weight"));
  s.storage = parse_laplacian_storage(a.str("storage"));
  return s;
}

// The particles and their volumes, once the machine's memory is known to hold them and the
// Laplacian the caller builds.  Matrix-free: peak RSS / N was 264 bytes at dx = 2^-8; an
// assembled one adds kAssembledBytesPerNonzero per non-zero of the Omega x all matrix, about
// pi (h/dx)^2 per unknown, |Omega|/|Omega_H| of the particles; `auto` assembles only within the
// 8 GB budget of DiscreteLaplacian.
struct PdeProblem {
  Particles p;
  std::vector<double> V;
};
PdeProblem make_pde_problem(const Args& a, const PdeOptions& s) {
  require_grid_fits_memory(s.dx, pde_bytes_per_particle(s.h, s.dx, s.storage, 8e9), "--dx");
  PdeProblem pr;
  pr.p = jittered_grid(s.dx, a.seed(), a.num("jitter"));
  pr.V = pde_volumes(s.volumes, pr.p, s.dx);
  return pr;
}

int cmd_poisson(int argc, char** argv) {
  Args a("gpm poisson", "One discrete Poisson problem (thesis (2.2), u = sin 2pi(x+y), V_i = |Omega_H|/N):\n"
                        "relative l-inf error over Omega, where the maximum sits, CG counts.");
  add_pde_options(a).opt("tol", "1e-10", "CG relative residual");
  a.parse(argc, argv, 2);
  const PdeOptions su = read_pde_options(a);
  const double dx = su.dx, h = su.h;
  const double tol = a.tolerance("tol");
  const auto [p, V] = make_pde_problem(a, su);
  const auto d = poisson_data(p, test_function("sin2pi"));
  const DiscreteLaplacian L =
      naming_small_h(a, su.h_opt, [&] { return DiscreteLaplacian(p, V, *su.w, h, su.storage); });
  const PoissonResult r = solve_poisson(p, L, d.f, d.g, tol);
  const ErrorLocation e = locate_error(p, d.g, r.U, h);
  TsvTable t = header_from(a, "poisson");
  t.set("h_used", h);
  t.set("rel_error_inner", "over the particles at least h from the boundary of Omega");
  t.set("volumes", pde_volumes_description(su.volumes));
  t.set("volume_mismatch", "V_i/dx^2 - 1");
  t.columns = {"dx", "h", "h_over_H", "N", "N_omega", "volume_mismatch", "nnz", "rel_error", "max_x", "max_y",
               "max_distance_over_h", "rel_error_inner", "cg_iterations", "rel_residual", "solve_s"};
  TsvRow row = t.named_row();
  row["dx"] = fmt(dx), row["h"] = fmt(h), row["h_over_H"] = fmt(h / Domain{}.H), row["N"] = fmt(p.size());
  row["N_omega"] = fmt(L.n_unknowns()), row["volume_mismatch"] = fmt(V.front() / (dx * dx) - 1);
  row["nnz"] = fmt(static_cast<long long>(L.nnz())), row["rel_error"] = fmt(e.rel_error);
  row["max_x"] = fmt(e.x), row["max_y"] = fmt(e.y);
  row["max_distance_over_h"] = fmt(e.distance_to_boundary / h);
  row["rel_error_inner"] = fmt(e.rel_error_inner), row["cg_iterations"] = fmt(r.cg.iterations);
  row["rel_residual"] = fmt(r.cg.rel_residual), row["solve_s"] = fmt(r.solve_seconds);
  t.add_row(row);
  print(t);
  return 0;
}

// One heat problem (thesis (3.2), §4.3's example) with a chosen weight, dx, h, θ and time
// step: the ad hoc run behind one row of Tables 4.5–4.7, without writing C++.
int cmd_heat(int argc, char** argv) {
  Args a("gpm heat", "One discrete heat problem (thesis (3.2), u = exp(-2 kappa pi^2 t) sin(pi x) sin(pi y),\n"
                     "kappa = 0.5, T = 0.1) with the theta-method: the relative error (4.2), steps, CG counts.");
  add_pde_options(a)
      .opt("theta", "1", "theta in [0, 1] (0 explicit, 1/2 Crank-Nicolson, 1 implicit)")
      .opt("dt", "", "time step dt0 (or --dt-c/--dt-p)")
      .opt("dt-c", "0.5", "dt0 = dt-c * h^dt-p when --dt is not given (Table 4.5: 0.0025, 2; 4.6: 0.5, 2; 4.7: 0.5, 1)")
      .opt("dt-p", "1", "power of h in dt0")
      .opt("steps", "fit", "fit: K = ceil(T/dt0), dt = T/K; exact: dt = dt0, K = ceil(T/dt0)")
      .opt("tol", "1e-10", "CG relative residual per implicit step");
  a.parse(argc, argv, 2);
  const PdeOptions su = read_pde_options(a);
  const double dx = su.dx, h = su.h;
  HeatSetting hs;
  hs.theta = a.num("theta");
  if (!(hs.theta >= 0 && hs.theta <= 1)) throw InputError("--theta: " + a.str("theta") + " is not in [0, 1]");
  hs.dt_nominal = a.str("dt").empty() ? a.positive("dt-c") * std::pow(h, a.num("dt-p")) : a.positive("dt");
  if (!(hs.dt_nominal > 0 && std::isfinite(hs.dt_nominal)))
    throw InputError("--dt-c/--dt-p give dt0 = " + fmt(hs.dt_nominal) + ": not a positive number");
  hs.fit_T = parse_dt_rule(a.str("steps"), "--steps") == DtRule::fit;
  hs.tol = a.tolerance("tol");
  if (hs.T / hs.dt_nominal > 1e7)
    throw InputError("dt0 = " + fmt(hs.dt_nominal) + " needs more than 1e7 steps to reach T = " + fmt(hs.T));
  const auto [p, V] = make_pde_problem(a, su);
  require_h_connectivity(p, h);
  const DiscreteLaplacian L =
      naming_small_h(a, su.h_opt, [&] { return DiscreteLaplacian(p, V, *su.w, h, su.storage); });
  const HeatResult r = solve_heat(p, L, hs);
  TsvTable t = header_from(a, "heat");
  t.set("h_used", h);
  t.set("kappa", hs.kappa);
  t.set("T", hs.T);
  t.set("volumes", pde_volumes_description(su.volumes));
  t.set("error", "(4.2): max_k ||u-U||_l2(Omega_H) / max_k ||u||_l2(Omega_H)");
  t.columns = {"dx", "h", "N", "N_omega", "volume_mismatch", "theta", "dt", "K", "steps_done",
               "blew_up", "rel_error", "rel_error_max", "growth_max", "cg_mean_iterations", "seconds"};
  TsvRow row = t.named_row();
  row["dx"] = fmt(dx), row["h"] = fmt(h), row["N"] = fmt(p.size()), row["N_omega"] = fmt(L.n_unknowns());
  row["volume_mismatch"] = fmt(V.front() / (dx * dx) - 1), row["theta"] = fmt(hs.theta), row["dt"] = fmt(r.dt);
  row["K"] = fmt(static_cast<long long>(r.K)), row["steps_done"] = fmt(static_cast<long long>(r.steps_done));
  row["blew_up"] = r.blew_up ? "yes" : "no";
  row["rel_error"] = r.blew_up ? "NA" : fmt(r.rel_error);
  row["rel_error_max"] = r.blew_up ? "NA" : fmt(r.rel_error_max);
  row["growth_max"] = fmt(r.growth_max), row["cg_mean_iterations"] = fmt(r.mean_cg_iterations);
  row["seconds"] = fmt(r.seconds);
  t.add_row(row);
  print(t);
  return 0;
}

// The smoothing part of the discrete Laplacian (or gradient) for one Fourier mode
// (smoothing.hpp): no particles, so it separates the operator's own error from the
// particles' in a measurement.
int cmd_smoothing(int argc, char** argv) {
  Args a("gpm smoothing", "The smoothing error of the Laplacian, eps(kh) = 1 - (8 pi/(kh)^2) int_0^1\n"
                          "(1 - J0(kh s)) w(s)/s ds, or of the gradient, 1 - (4 pi/(kh)) int_0^1\n"
                          "J1(kh s) w(s) ds, for a weight and radii (no particles); or of the\n"
                          "interpolant for the thesis' Case 1 (X^4 + Y^4): max over Omega of\n"
                          "|3 m2 h^2 (X^2+Y^2) + (3/4) m4 h^4| / (1/8), m_q = 2 pi int s^(q+1) w.");
  a.opt("weight", "quartic_polynomial", "registry weight (gpm weights lists them)")
      .opt("h", "", "comma-separated influence radii (required)")
      .opt("k", fmt(kSin2piWaveNumber), "wave number |k| (default 2 pi sqrt 2, for sin 2pi(x+y))")
      .opt("operator", "lap", "lap, grad or interp-case1 (--k unused)");
  a.parse(argc, argv, 2);
  if (a.str("h").empty()) throw InputError("--h is required (see --help)");
  const std::string op = a.str("operator");
  if (op != "lap" && op != "grad" && op != "interp-case1")
    throw InputError("--operator: '" + op + "' is not lap, grad or interp-case1");
  const double k = a.positive("k");
  const WeightFunction& w = weight(a.str("weight"));
  TsvTable t = header_from(a, "smoothing");
  t.set("eps", op == "lap" ? "1 - (8 pi/(kh)^2) int_0^1 (1 - J0(kh s)) w(s)/s ds: relative error "
                             "of the continuous Laplacian on the mode"
               : op == "grad" ? "1 - (4 pi/(kh)) int_0^1 J1(kh s) w(s) ds: relative error of the "
                                "continuous gradient on the mode"
                              : "max_Omega |3 m2 h^2 (X^2+Y^2) + (3/4) m4 h^4| / max_Omega |v|, "
                                "v = X^4 + Y^4: relative error of the continuous interpolant");
  t.columns = {"h", "kh", "eps"};
  for (double h : a.nums("h")) {
    require_positive(h, "--h");
    const double e = op == "lap"    ? laplacian_smoothing_error(w, k * h)
                     : op == "grad" ? gradient_smoothing_error(w, k * h)
                                    : interpolant_smoothing_error_case1(w, h);
    TsvRow row = t.named_row();
    row["h"] = fmt(h), row["kh"] = fmt(k * h), row["eps"] = fmt(e);
    t.add_row(row);
  }
  print(t);
  return 0;
}

// The fingerprint of the code that decides each named program's numbers, as the result
// store's rows carry it (provenance.hpp): a stored row is current when they agree.
int cmd_fingerprint(int argc, char** argv) {
  if (argc >= 3 && (std::string(argv[2]) == "--help" || std::string(argv[2]) == "-h")) {
    std::cout << "usage: gpm fingerprint PROGRAM...\n"
                 "The code fingerprint of each program: the `code` column of a result-store row\n"
                 "it computed with the code of this build (results/paper/README.md).\n";
    return 0;
  }
  if (argc < 3) throw InputError("gpm fingerprint: name at least one program (see --help)");
  const auto known = fingerprinted_programs();
  for (int i = 2; i < argc; ++i)
    if (std::find(known.begin(), known.end(), argv[i]) == known.end())
      throw InputError("gpm fingerprint: '" + std::string(argv[i]) + "' is not a program of this build; valid: " +
                       join(known, ", "));
  TsvTable t;
  t.set("git_revision", git_revision());
  t.columns = {"program", "code"};  // two columns written on the next line: kept by position
  for (int i = 2; i < argc; ++i) t.add_row({argv[i], code_fingerprint(argv[i])});
  print(t);
  return 0;
}

// gpm store-seal: the one-time step that gave the result store's rows their seal
// (store.hpp).  A file written before seals (provenance columns code, made_on, checked) gets
// the seal column; each row's `checked` chain of re-checks is cut to its last record with the
// count of earlier ones, the chain itself going to rechecks.log beside the file.  Sealing
// vouches for nothing but the rows as they are now: their history is git's.
int cmd_store_seal(int argc, char** argv) {
  if (argc >= 3 && (std::string(argv[2]) == "--help" || std::string(argv[2]) == "-h")) {
    std::cout << "usage: gpm store-seal FILE...\n"
                 "Adds the seal column to result-store files written before seals (once; a sealed\n"
                 "file is refused) and shortens each row's re-check chain to its last record.\n";
    return 0;
  }
  if (argc < 3) throw InputError("gpm store-seal: name at least one file (see --help)");
  for (int i = 2; i < argc; ++i) {
    const std::string path = argv[i];
    TsvTable t = TsvTable::load(path);
    const std::vector<std::string> before = {"code", "made_on", "checked"};
    if (t.columns.size() < 3 || !std::equal(before.begin(), before.end(), t.columns.end() - 3))
      throw InputError(path + ": not a store file written before seals (its last columns are not "
                       "code, made_on, checked)");
    t.columns.push_back("seal");
    const int cchecked = t.require_column("checked");
    std::map<std::string, std::size_t> chains;  // each distinct chain once, with its row count
    for (std::size_t r = 0; r < t.rows.size(); ++r) {
      auto& row = t.rows[r];
      if (row.size() + 1 != t.columns.size())
        throw InputError(path + " line " + std::to_string(t.row_lines[r]) + ": " +
                         std::to_string(row.size()) + " cells for " + std::to_string(t.columns.size() - 1) +
                         " columns; mend or recompute it before sealing");
      std::string& chain = row[cchecked];
      const auto last = chain.rfind("; ");
      if (last != std::string::npos) {
        ++chains[chain];
        chain = checked_cell(chain.substr(last + 2), recheck_count(chain) - 1);
      }
      row.push_back("");
      row.back() = row_seal(row);
    }
    std::ofstream log(std::filesystem::path(path).parent_path() / "rechecks.log", std::ios::app);
    for (auto& [chain, n] : chains)
      log << std::filesystem::path(path).filename().string() << "\t" << n << " rows\t" << chain << "\n";
    t.save(path);
    std::cout << "sealed " << path << " (" << t.rows.size() << " rows)\n";
  }
  return 0;
}

// The folders a store subcommand reads (--store, --published, --data): each must exist.
void require_directories(const std::vector<std::pair<std::string, std::string>>& options) {
  for (auto& [option, path] : options)
    if (!std::filesystem::is_directory(path)) throw InputError("--" + option + " " + path + " is not a directory");
}

// The git revision and date as every output of the store's verdicts carries them.
void set_revision_and_date(TsvTable& header, const std::string& store) {
  for (auto& [k, v] : store_provenance(store))
    if (k == "git_revision" || k == "written_utc") header.set(k, v);
}

// gpm store-rates: the documents' rates judged against the committed result store (verdicts.hpp),
// the report's paper-scale tables.  Every input is read and every output path checked before
// anything is written; each output is written to a temporary file and renamed (TsvTable::save).
int cmd_store_rates(int argc, char** argv) {
  Args a("gpm store-rates",
         "The documents' rates from the committed result store, with their verdicts and the two\n"
         "scoreboards (src/gpm/studies/verdicts.hpp defines every verdict); no study is run.");
  a.opt("store", "results/paper", "the result store")
      .opt("published", "tables/published", "the published values (imoto_table1.tsv, thesis_table4_N_long.tsv)")
      .opt("checked", "", "checked reasons for differing rates (gpm checked-reasons --out); default: none")
      .output("out", "", "the rates with their verdicts and boards (required)")
      .output("summary", "", "where the stored rows come from, file by file")
      .output("score", "", "the verdict counts per table and slice, and each board's totals")
      .output("ident", "", "setup_identification's table: the fingerprint evidence of Chapter 4's reading");
  a.parse(argc, argv, 2);
  const std::string out = a.required("out"), store = a.str("store"), pub = a.str("published");
  require_directories({{"store", store}, {"published", pub}});
  const CheckedReasons checked =
      a.str("checked").empty() ? CheckedReasons{} : passed_reasons(TsvTable::load(a.str("checked")));

  // The reading of Chapter 4 that Table 4.6's theta = 0 rates identify (paper/04-setup-rule.md).
  const RegisteredStudy& fp = fingerprint_study(study_registry());
  SetupIdentification ident = identify_setup(store, fp, TsvTable::load(published_file(pub, fp.published->table)));
  const std::vector<JudgedRate> judged = judge_rates(store_rates(store, pub, kRateTolerance),
                                                     store_unstable_series(store, pub), checked,
                                                     kRateTolerance, ident.identified);
  // Header lines first, then the table's own (a TsvTable writes its meta in order).
  auto with_header = [&](TsvTable t, const std::string& program,
                         const std::vector<std::pair<std::string, std::string>>& lines) {
    TsvTable h;
    h.set("program", program);
    for (auto& [k, v] : store_provenance(store)) h.set(k, v);
    for (auto& [k, v] : lines) h.set(k, v);
    t.meta.insert(t.meta.begin(), h.meta.begin(), h.meta.end());
    return t;
  };
  // Every table is made before the first is written: a store file that cannot be read leaves
  // no output half done.
  std::vector<std::pair<std::string, TsvTable>> outputs;
  outputs.emplace_back(
      out, with_header(rates_table(judged), "gpm store-rates",
                       {{"store", store},
                        {"checked_reasons", a.str("checked").empty() ? "none (no reason accepted)" : a.str("checked")},
                        {"note", "rates at the documents' levels from the committed paper-profile rows; status from "
                                 "rate_table (tolerance " + fmt(kRateTolerance) + "); verdict as listed in "
                                 "src/gpm/studies/verdicts.hpp"}}));
  if (!a.str("summary").empty())
    outputs.emplace_back(
        a.str("summary"),
        with_header(store_summary(store), "gpm store-rates (summary)",
                    {{"store", store},
                     {"current", "rows whose code column is the fingerprint of this build's program (gpm fingerprint)"}}));
  if (!a.str("score").empty())
    outputs.emplace_back(
        a.str("score"),
        with_header(score_table(judged, pub), "gpm store-rates (score)",
                    {{"boards", "printed: every set-up detail as the text prints it; identified: the readings of "
                                "paper/04-setup-rule.md (fingerprint: a published rate that identified the reading)"}}));
  if (!a.str("ident").empty()) {
    ident.table.set("program", "gpm store-rates (setup_identification)");
    add_provenance(ident.table);
    outputs.emplace_back(a.str("ident"), ident.table);
  }
  for (auto& [path, table] : outputs) table.save(path);
  return 0;
}

// gpm checked-reasons: the reasons for differing paper-scale rates, each with the diagnostic
// that checks it against the committed store (checked_reasons.hpp); gpm store-rates --checked
// reads the first file.  Both tables are made before either is written (temporary file and
// rename each): a store file that cannot be read leaves no output half done.
int cmd_checked_reasons(int argc, char** argv) {
  Args a("gpm checked-reasons",
         "Reasons for paper-scale rates that differ from the published ones, each with the\n"
         "diagnostic that checks it against the committed result store (pass or fail, and whether\n"
         "a run restores the published rate); src/gpm/studies/checked_reasons.hpp states each rule.");
  a.opt("store", "results/paper", "the result store")
      .opt("published", "tables/published", "the published values (thesis_table4_N_long.tsv)")
      .output("out", "", "one row per checked rate: table, slice, key, reason, evidence, check, restores (required)")
      .output("by-mechanism", "", "the same reasons, one row per mechanism with the rows it covers");
  a.parse(argc, argv, 2);
  const std::string out = a.required("out"), store = a.str("store"), pub = a.str("published");
  require_directories({{"store", store}, {"published", pub}});
  TsvTable checked = checked_reasons(store, pub, kRateTolerance);
  // The header: what the report prints under the table (git revision and date as every output
  // of the store's verdicts carries them).
  auto header = [&](TsvTable& t, const std::vector<std::pair<std::string, std::string>>& lines) {
    TsvTable h;
    for (auto& [k, v] : lines) h.set(k, v);
    set_revision_and_date(h, store);
    h.set("note", "rules and thresholds in src/gpm/studies/checked_reasons.hpp; published values from " + pub);
    t.meta.insert(t.meta.begin(), h.meta.begin(), h.meta.end());
  };
  std::vector<std::pair<std::string, TsvTable>> outputs;
  if (!a.str("by-mechanism").empty()) {
    TsvTable by = reasons_by_mechanism(checked);
    header(by, {{"program", "gpm checked-reasons (by mechanism)"}, {"sources", out}});
    outputs.emplace_back(a.str("by-mechanism"), by);
  }
  header(checked, {{"program", "gpm checked-reasons"}, {"store", store}, {"tolerance", fmt(kRateTolerance) + " (rates)"}});
  outputs.emplace(outputs.begin(), out, checked);
  for (auto& [path, table] : outputs) table.save(path);
  return 0;
}

// gpm verdicts: page one of the report, a verdict per item of the documents with the number
// that decides it (page_verdicts.hpp).  Every input is read before the output is written
// (temporary file and rename).
int cmd_verdicts(int argc, char** argv) {
  Args a("gpm verdicts",
         "Page one of the report: one verdict per figure and table of the documents (the items\n"
         "file), each with the number that decides it, from the store's score and this run's data\n"
         "files; src/gpm/studies/page_verdicts.hpp states each rule and how rows are merged.");
  a.opt("items", "tables/items.tsv", "the documents' items and the rule of each (document, item, shows, rule, section)")
      .opt("score", "", "the store's verdict counts (gpm store-rates --score; required)")
      .opt("data", "", "the folder of this run's data files (koba_sato_cor71.tsv, core_voronoi.tsv, ...; required)")
      .output("out", "", "page one's table: document, item, shows, verdict, evidence, section (required)");
  a.parse(argc, argv, 2);
  const std::string out = a.required("out"), score = a.required("score"), data = a.required("data"),
                    items = a.str("items");
  require_directories({{"data", data}});
  TsvTable page = page_verdicts(TsvTable::load(items), TsvTable::load(score), page_data_dir(data));
  TsvTable h;
  h.set("program", "gpm verdicts");
  h.set("items", items);
  h.set("score", score + " (paper scale, the result store)");
  h.set("data", data);
  set_revision_and_date(h, "");
  page.meta = h.meta;
  page.save(out);
  return 0;
}

// gpm decisions: the documents' open set-up questions, each with the evidence the committed
// store gives (decisions.hpp).  The table is made before it is written (temporary file and
// rename): a store file that cannot be read leaves no output.
int cmd_decisions(int argc, char** argv) {
  Args a("gpm decisions",
         "The documents' open set-up questions (time step, volumes, smoothing, Omega_H, ...), each\n"
         "with the evidence the committed result store gives; src/gpm/studies/decisions.hpp lists them.");
  a.opt("store", "results/paper", "the result store")
      .opt("published", "tables/published", "the published values (thesis_table4_N_long.tsv, imoto_table1.tsv)")
      .opt("score", "", "the store's verdict counts (gpm store-rates --score): adds which reading each table ran")
      .output("out", "", "one row per question: question, evidence, decision (required)");
  a.parse(argc, argv, 2);
  const std::string out = a.required("out"), store = a.str("store"), pub = a.str("published");
  require_directories({{"store", store}, {"published", pub}});
  std::optional<TsvTable> score;
  if (!a.str("score").empty()) score = TsvTable::load(a.str("score"));
  TsvTable table = decisions(store, pub, score);
  TsvTable h;
  h.set("program", "gpm decisions");
  h.set("store", store);
  set_revision_and_date(h, store);
  table.meta = h.meta;
  table.save(out);
  return 0;
}

// gpm study: the study registry (registry.hpp) on the command line.  `--list` prints every
// study with its document item and levels; `--make FILE` writes the studies' make rules
// (make build does, to build/studies.mk); `gpm study NAME [options]` runs the study's program
// (from the directory of this gpm) with the study's fixed arguments and the options given,
// so it takes the program's --profile, --levels, --out, --help as they are.
int cmd_study(int argc, char** argv) {
  const std::string first = argc >= 3 ? argv[2] : "";
  if (first == "--help" || first == "-h") {
    std::cout << "usage: gpm study --list | --readings | --store-files | --reading-file STUDY READING |\n"
                 "                 --make FILE | NAME [options]\n"
                 "  --list      every registered study: document item, program, levels per profile\n"
                 "  --make FILE the studies' make rules and lists (make build writes build/studies.mk)\n"
                 "  --store-files  every study's files in the result store: program and arguments, the\n"
                 "              units each must hold (census) and the ones the store check recomputes\n"
                 "  --readings  the heat tables' set-up readings: name, h rule, volumes, time step,\n"
                 "              store file suffix (thesis_heat's {reading})\n"
                 "  --reading-file STUDY READING  the store file (stem) holding that set-up reading's\n"
                 "              rows (the per-reading figures find their data with it)\n"
                 "  NAME        runs the study's program with its fixed arguments, then the\n"
                 "              options given (e.g. --profile quick --out FILE); see\n"
                 "              gpm study NAME --help for them\n";
    return 0;
  }
  if (first.empty() || first == "--list") {
    TsvTable t;
    t.set("program", "gpm study");
    add_provenance(t);
    t.columns = {"study", "item", "program", "quick_levels", "paper_levels", "header"};
    auto levels = [](const std::vector<int>& k) {
      std::vector<std::string> s;
      for (int v : k) s.push_back(fmt(v));
      return join(s, ",");
    };
    for (auto& e : study_registry()) {
      std::vector<std::string> command = {e.program};
      command.insert(command.end(), e.fixed_args.begin(), e.fixed_args.end());
      TsvRow row = t.named_row();
      row["study"] = e.name, row["item"] = e.item, row["program"] = join(command, " ");
      row["quick_levels"] = levels(e.levels.quick), row["paper_levels"] = levels(e.levels.paper);
      row["header"] = join(e.header(), ",");
      t.add_row(row);
    }
    print(t);
    return first.empty() ? 2 : 0;
  }
  if (first == "--readings") {
    TsvTable t;
    t.set("program", "gpm study --readings");
    add_provenance(t);
    t.columns = {"reading", "h_rule", "volumes", "dt_rule", "file_suffix"};
    for (const PdeSetup& r : pde_setups()) {
      TsvRow row = t.named_row();
      row["reading"] = r.name(), row["h_rule"] = h_rule_name(r.h_rule), row["volumes"] = pde_volumes_name(r.volumes);
      row["dt_rule"] = dt_rule_name(r.dt_rule), row["file_suffix"] = r.file_suffix();
      t.add_row(row);
    }
    print(t);
    return 0;
  }
  if (first == "--reading-file") {
    if (argc != 5) throw InputError("gpm study --reading-file: give a study and a reading (e.g. thesis_table4_6 h15_cell_exact)");
    std::cout << study_registry().study(argv[3]).store_file_of(argv[4]).name << "\n";
    return 0;
  }
  if (first == "--store-files") {
    TsvTable t = store_file_table(study_registry());
    t.set("program", "gpm study --store-files");
    add_provenance(t);
    print(t);
    return 0;
  }
  if (first == "--make") {
    if (argc != 4) throw InputError("gpm study --make: give one output file (e.g. build/studies.mk)");
    save_text(argv[3], make_rules(study_registry()));
    return 0;
  }
  const RegisteredStudy& e = study_registry().study(first);
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe");
  const std::string program = (self.parent_path() / e.program).string();
  if (access(program.c_str(), X_OK) != 0)
    throw InputError("gpm study " + first + ": its program " + program +
                     " is not built (make build)");
  std::vector<std::string> args = {program};
  args.insert(args.end(), e.fixed_args.begin(), e.fixed_args.end());
  for (int i = 3; i < argc; ++i) {
    // An option the study fixes (its --table, …) cannot be given again: it names the study.
    const std::string name = std::string(argv[i]).substr(0, std::string(argv[i]).find('='));
    for (std::size_t f = 0; f < e.fixed_args.size(); ++f)
      if (e.fixed_args[f] == name)
        throw InputError("gpm study " + first + ": " + name + " is fixed by the study (" + name + " " +
                         (f + 1 < e.fixed_args.size() ? e.fixed_args[f + 1] : "") + "); run another study for another value");
    args.push_back(argv[i]);
  }
  std::vector<char*> cargs;
  for (auto& a : args) cargs.push_back(a.data());
  cargs.push_back(nullptr);
  std::cout.flush();
  execv(program.c_str(), cargs.data());
  throw std::runtime_error("gpm study: cannot run " + program + ": " + std::strerror(errno));
}

int dispatch(int argc, char** argv) {
  const std::string usage =
      "usage: gpm SUBCOMMAND [options]   (gpm SUBCOMMAND --help for its options)\n"
      "  weights     weight functions and their computed properties\n"
      "  particles   a jittered-grid distribution\n"
      "  voronoi     Voronoi cell areas, covering distances and r_c\n"
      "  trunc       relative l-infinity error of an operator\n"
      "  poisson     one discrete Poisson problem: error, where it sits, CG counts\n"
      "  heat        one discrete heat problem (theta-method): error (4.2), steps, CG counts\n"
      "  smoothing   the Laplacian's smoothing error for a Fourier mode (no particles)\n"
      "  fingerprint the code fingerprint of programs (result-store rows)\n"
      "  store-seal  seal result-store files written before seals (once)\n"
      "  store-rates the documents' rates judged against the result store: verdicts, boards\n"
      "  checked-reasons  the reasons for differing rates, each checked against the result store\n"
      "  verdicts    page one of the report: a verdict per figure and table of the documents\n"
      "  decisions   the documents' open set-up questions with the result store's evidence\n"
      "  study       the study catalog: --list, or run one study by name\n";
  if (argc < 2 || std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h") {
    std::cout << usage;
    return argc < 2 ? 2 : 0;
  }
  const std::string sub = argv[1];
  if (sub == "weights") return cmd_weights(argc, argv);
  if (sub == "particles") return cmd_particles(argc, argv);
  if (sub == "voronoi") return cmd_voronoi(argc, argv);
  if (sub == "trunc") return cmd_trunc(argc, argv);
  if (sub == "poisson") return cmd_poisson(argc, argv);
  if (sub == "heat") return cmd_heat(argc, argv);
  if (sub == "smoothing") return cmd_smoothing(argc, argv);
  if (sub == "fingerprint") return cmd_fingerprint(argc, argv);
  if (sub == "study") return cmd_study(argc, argv);
  if (sub == "store-seal") return cmd_store_seal(argc, argv);
  if (sub == "store-rates") return cmd_store_rates(argc, argv);
  if (sub == "checked-reasons") return cmd_checked_reasons(argc, argv);
  if (sub == "verdicts") return cmd_verdicts(argc, argv);
  if (sub == "decisions") return cmd_decisions(argc, argv);
  throw InputError("unknown subcommand '" + sub + "'; valid: weights, particles, voronoi, trunc, poisson, "
                   "heat, smoothing, fingerprint, study, store-seal, store-rates, checked-reasons, verdicts, decisions");
}

}  // namespace

int main(int argc, char** argv) { return run_main("gpm", dispatch, argc, argv); }
