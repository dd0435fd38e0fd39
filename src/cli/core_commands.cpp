// gpm weights, particles, voronoi, trunc, poisson, heat, smoothing: the common core on the
// command line, one problem at a time, for ad hoc studies.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <string>

#include "cli/commands.hpp"
#include "gpm/error.hpp"
#include "gpm/geometry/domain.hpp"
#include "gpm/geometry/influence_radius.hpp"
#include "gpm/geometry/volumes.hpp"
#include "gpm/geometry/voronoi.hpp"
#include "gpm/io/provenance.hpp"
#include "gpm/operators/testfunctions.hpp"
#include "gpm/operators/truncation.hpp"
#include "gpm/solvers/heat.hpp"
#include "gpm/solvers/heat_krylov.hpp"
#include "gpm/solvers/laplacian_matrix.hpp"
#include "gpm/solvers/poisson.hpp"
#include "gpm/solvers/poisson_probes.hpp"
#include "gpm/studies/define/heat_tables.hpp"
#include "gpm/studies/define/profile.hpp"
#include "gpm/theory/smoothing.hpp"
#include "gpm/weights/weights.hpp"

namespace gpm::cli {

namespace {

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

}  // namespace

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
      .opt("tol", "1e-10", "CG relative residual per implicit step")
      .opt("propagator", "auto", "stepped: the theta-method step by step (the reference); krylov: the\n"
                                 "  recurrence propagated in a Krylov subspace (heat_krylov.hpp); auto: the\n"
                                 "  one with fewer predicted Laplacian products");
  a.parse(argc, argv, 2);
  const PdeOptions su = read_pde_options(a);
  const double dx = su.dx, h = su.h;
  const HeatPropagator how = parse_heat_propagator(a.str("propagator"));
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
  const HeatResult r = run_heat(p, L, {hs}, {how}, dx).front();
  TsvTable t = header_from(a, "heat");
  t.set("h_used", h);
  t.set("kappa", hs.kappa);
  t.set("T", hs.T);
  t.set("volumes", pde_volumes_description(su.volumes));
  t.set("error", "(4.2): max_k ||u-U||_l2(Omega_H) / max_k ||u||_l2(Omega_H)");
  t.columns = {"dx", "h", "N", "N_omega", "volume_mismatch", "theta", "dt", "K", "steps_done",
               "blew_up", "rel_error", "rel_error_max", "growth_max", "propagator", "subspace", "products",
               "cg_mean_iterations", "seconds"};
  TsvRow row = t.named_row();
  row["dx"] = fmt(dx), row["h"] = fmt(h), row["N"] = fmt(p.size()), row["N_omega"] = fmt(L.n_unknowns());
  row["volume_mismatch"] = fmt(V.front() / (dx * dx) - 1), row["theta"] = fmt(hs.theta), row["dt"] = fmt(r.dt);
  row["K"] = fmt(static_cast<long long>(r.K)), row["steps_done"] = fmt(static_cast<long long>(r.steps_done));
  row["blew_up"] = r.blew_up ? "yes" : "no";
  row["rel_error"] = r.blew_up ? "NA" : fmt(r.rel_error);
  row["rel_error_max"] = r.blew_up ? "NA" : fmt(r.rel_error_max);
  row["growth_max"] = fmt(r.growth_max), row["cg_mean_iterations"] = fmt(r.mean_cg_iterations);
  row["propagator"] = r.subspace > 0 ? "krylov" : "stepped", row["subspace"] = fmt(r.subspace);
  row["products"] = fmt(r.products);
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

}  // namespace gpm::cli
