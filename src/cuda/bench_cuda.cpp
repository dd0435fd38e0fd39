// bench_cuda: the CUDA path's pair interactions per second beside the CPU kernel's
// (issue 7, item 5).  Built only with -DGPM_CUDA=ON; run by bench/run_cuda_check.sh.
//
// Setting as bench_kernel's fused1 variant: jittered grid Δx = 2^-9, h = 0.03, the cubic
// B-spline (Π2) weight, Π + ∇ + Δ of sin(2πx)sin(2πy) at the particles of Ω.  The pairs are
// counted on the host (accepted pairs r < h, self included: the same count as
// bench_kernel), so the rates of the two programs are directly comparable.  Each cell size
// in --cells-per-h is timed: kernel alone (cudaEvent, best of --repeats after a warm-up)
// and end to end (host wall clock of apply(): gather, upload, kernel, download).
//
// Then the Poisson/heat operator y = M_ΩΩ x, matrix-free, in bench_laplacian's setting
// (quartic polynomial weight, h = (2.6⁴·2^-10·Δx)^{1/4}) at --lap-dx.
//
// Every GPU result is compared with the CPU (gpm::FusedKernel, DiscreteLaplacian
// matrix-free): max |GPU − CPU| / max |CPU| per column.  Above --tolerance the program
// still writes its table (the numbers are the finding) and then exits non-zero.
// Without a CUDA device it prints one line and exits 0, writing nothing.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <span>
#include <string>
#include <vector>

#include "cuda/kernel_cuda.hpp"
#include "cuda/kernel_cuda_body.hpp"
#include "gpm/error.hpp"
#include "gpm/geometry/domain.hpp"
#include "gpm/geometry/influence_radius.hpp"
#include "gpm/io/args.hpp"
#include "gpm/io/tsv.hpp"
#include "gpm/kernel/kernel.hpp"
#include "gpm/operators/fused_errors.hpp"
#include "gpm/operators/testfunctions.hpp"
#include "gpm/studies/define/catalog.hpp"
#include "gpm/studies/define/thesis_tables.hpp"
#include "gpm/solvers/laplacian_matrix.hpp"
#include "gpm/weights/weights.hpp"

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point a) {
  return std::chrono::duration<double>(Clock::now() - a).count();
}

double max_rel_diff(const std::vector<double>& gpu, std::span<const double> cpu) {
  double d = 0, s = 0;
  for (std::size_t i = 0; i < gpu.size(); ++i) {
    d = std::max(d, std::abs(gpu[i] - cpu[i]));
    s = std::max(s, std::abs(cpu[i]));
  }
  if (!std::isfinite(d)) return INFINITY;
  return s > 0 ? d / s : d;
}

int body(int argc, char** argv) {
  gpm::Args args("bench_cuda",
                 "Pairs per second of the CUDA truncation-error kernel and matrix-free Laplacian, "
                 "checked against the CPU kernel.  Exits 0 with one line when there is no CUDA "
                 "device.");
  args.opt("dx", "2^-9", "particle spacing of the jittered grid (truncation kernel)")
      .opt("h", "0.03", "influence radius (truncation kernel)")
      .opt("weight", "Pi2", "weight of the truncation kernel (Pi+grad+Lap)")
      .opt("seed", "1", "jitter seed")
      .opt("cells-per-h", "1,4", "comma-separated cell sizes h/k to time")
      .opt("repeats", "10", "timed kernel calls per measurement (best and median reported)")
      .opt("lap-dx", "2^-8", "particle spacing of the Laplacian (0: skip it)")
      .opt("lap-weight", "quartic_polynomial", "weight of the Laplacian")
      .opt("cpu-threads", "2", "threads of the CPU reference (timed once, for the record)")
      .opt("tolerance", "1e-10", "largest max relative GPU-CPU difference accepted")
      .opt("out", "data/bench/cuda.tsv", "TSV output");
  args.parse(argc, argv);
  const double dx = args.positive("dx"), h = args.positive("h");
  const long long repeats = args.integer("repeats");
  if (repeats < 1) throw gpm::InputError("--repeats must be >= 1");
  std::vector<int> cells;
  for (double k : args.nums("cells-per-h")) {
    if (k < 1 || k != std::floor(k) || k > 64)
      throw gpm::InputError("--cells-per-h: integers from 1 to 64");
    cells.push_back(static_cast<int>(k));
  }
  const double lap_dx = args.num("lap-dx");
  if (lap_dx < 0) throw gpm::InputError("--lap-dx must be >= 0");
  const long long cpu_threads = args.integer("cpu-threads");
  if (cpu_threads < 1) throw gpm::InputError("--cpu-threads must be >= 1");
  const double tol = args.positive("tolerance");
  const gpm::WeightFunction& w1 = gpm::weight(args.str("weight"));
  const gpm::WeightFunction& wl = gpm::weight(args.str("lap-weight"));

  // No device: one line, exit 0, nothing written.
  const gpm::cuda::DeviceInfo dev = gpm::cuda::device_info();
  if (dev.count == 0) {
    std::printf("bench_cuda: no CUDA device: skipped (%s)\n", dev.error.c_str());
    return 0;
  }
  const auto wall_start = Clock::now();
  std::printf("bench_cuda: %s (compute capability %d.%d, %.1f GiB), runtime %d, driver %d\n",
              dev.name.c_str(), dev.cc_major, dev.cc_minor, dev.memory_gib, dev.runtime_version,
              dev.driver_version);

  // The truncation-kernel setting (bench_kernel's fused1).
  const gpm::Particles p = gpm::jittered_grid(dx, static_cast<uint64_t>(args.integer("seed")));
  const std::vector<double> V(p.size(), gpm::Domain{}.area_H() / static_cast<double>(p.size()));
  const auto& f = gpm::test_function("sin2pi");
  std::vector<double> v(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) v[i] = f.v(p.x[i], p.y[i]);
  const std::vector<int32_t> targets = gpm::omega_targets(p);

  gpm::KernelOptions copt;
  copt.threads = static_cast<int>(cpu_threads);
  const gpm::FusedKernel cpu(p, V, h, {{w1, gpm::kAllOps}}, copt);
  const gpm::PairCount pc = cpu.count_pairs(targets);
  const double pairs = static_cast<double>(pc.accepted);
  auto t0 = Clock::now();
  const gpm::KernelResult ref = cpu.apply(targets, std::vector<std::vector<double>>{v});
  const double cpu_s = seconds_since(t0);
  std::printf("  N = %zu, %zu targets, dx = %g, h = %g, weight %s: %.0f pairs; CPU (%lld "
              "threads, one call) %.3f s = %.4g pairs/s\n",
              p.size(), targets.size(), dx, h, w1.name.c_str(), pairs, cpu_threads, cpu_s,
              pairs / cpu_s);

  gpm::TsvTable t;
  t.set("program", "bench_cuda");
  for (auto& [k, val] : args.values()) t.set("arg_" + k, val);
  t.set("device", dev.name);
  t.set("compute_capability", std::to_string(dev.cc_major) + "." + std::to_string(dev.cc_minor));
  t.set("device_memory_gib", dev.memory_gib);
  t.set("cuda_runtime", static_cast<long long>(dev.runtime_version));
  t.set("cuda_driver", static_cast<long long>(dev.driver_version));
  t.set("note", "pairs = accepted pairs (r<h, self included), counted on the host as in "
                "bench_kernel; kernel_s: cudaEvent time of the kernel alone; end_to_end_s: "
                "host wall time of one apply (gather, upload, kernel, download); cpu rows: "
                "the CPU kernel on this machine's host CPU, one call (bench_kernel is the "
                "CPU benchmark)");
  gpm::add_provenance(t);
  t.columns = {"operator", "processor", "cells_per_h", "n_particles", "n_targets", "pairs",
               "candidates", "kernel_s_best", "kernel_s_median", "end_to_end_s_best",
               "pairs_per_s", "pairs_per_s_end_to_end", "max_rel_diff_vs_cpu", "flops_per_pair",
               "fraction_of_fp64_peak"};
  t.add_row({"fused1 P+G+L " + w1.name, "cpu " + std::to_string(cpu_threads) + " threads",
             gpm::fmt(cpu.options().cells_per_h), gpm::fmt(p.size()), gpm::fmt(targets.size()),
             gpm::fmt(static_cast<long long>(pc.accepted)),
             gpm::fmt(static_cast<long long>(pc.candidates)), gpm::fmt(cpu_s), gpm::fmt(cpu_s),
             gpm::fmt(cpu_s), gpm::fmt(pairs / cpu_s), gpm::fmt(pairs / cpu_s), "0", "", ""});

  double worst = 0;
  std::printf("  %-22s %5s %12s %10s %10s %11s %11s %9s\n", "operator", "cells", "candidates",
              "kernel_s", "e2e_s", "pairs/s", "e2e pairs/s", "max_rel");
  for (const int k : cells) {
    gpm::KernelOptions ko;
    ko.cells_per_h = k;
    const int64_t cand =
        gpm::FusedKernel(p, V, h, {{w1, gpm::kAllOps}}, ko).count_pairs(targets).candidates;
    const gpm::cuda::CudaKernel gk(p, V, w1, h, gpm::kAllOps, k);
    gpm::cuda::CudaResult r = gk.apply(targets, v);  // warm-up (module load, caches)
    std::vector<double> ks, es;
    for (long long i = 0; i < repeats; ++i) {
      t0 = Clock::now();
      r = gk.apply(targets, v);
      es.push_back(seconds_since(t0));
      ks.push_back(1e-3 * r.kernel_ms);
    }
    std::sort(ks.begin(), ks.end());
    std::sort(es.begin(), es.end());
    const double diff = std::max({max_rel_diff(r.interp, ref.interpolant(0, 0)),
                                  max_rel_diff(r.grad_x, ref.grad_x(0, 0)),
                                  max_rel_diff(r.grad_y, ref.grad_y(0, 0)),
                                  max_rel_diff(r.lap, ref.laplacian(0, 0))});
    worst = std::max(worst, diff);
    std::printf("  %-22s %5d %12lld %10.5f %10.5f %11.4g %11.4g %9.2e\n", "fused1 P+G+L", k,
                static_cast<long long>(cand), ks.front(), es.front(), pairs / ks.front(),
                pairs / es.front(), diff);
    std::fflush(stdout);
    t.add_row({"fused1 P+G+L " + w1.name, "gpu", gpm::fmt(k), gpm::fmt(p.size()),
               gpm::fmt(targets.size()), gpm::fmt(static_cast<long long>(pc.accepted)),
               gpm::fmt(static_cast<long long>(cand)), gpm::fmt(ks.front()),
               gpm::fmt(ks[ks.size() / 2]), gpm::fmt(es.front()), gpm::fmt(pairs / ks.front()),
               gpm::fmt(pairs / es.front()), gpm::fmt(diff), "", ""});
  }

  // The matrix-free Laplacian y = M_ΩΩ x (bench_laplacian's setting).
  if (lap_dx > 0) {
    const gpm::Particles q = gpm::jittered_grid(lap_dx, static_cast<uint64_t>(args.integer("seed")));
    const std::vector<double> Vq(q.size(), gpm::Domain{}.area_H() / static_cast<double>(q.size()));
    const double hl = gpm::pde_h(gpm::HRule::h10, lap_dx);  // the thesis' printed h, one function
    const gpm::DiscreteLaplacian L(q, Vq, wl, hl, gpm::LaplacianStorage::matrix_free);
    Eigen::VectorXd x(static_cast<Eigen::Index>(L.n_unknowns())), y;
    for (Eigen::Index u = 0; u < x.size(); ++u) x[u] = std::cos(0.37 * static_cast<double>(u));
    const gpm::PairCount lpc =
        gpm::FusedKernel(q, Vq, hl, {{wl, gpm::kLap}}, copt).count_pairs(L.omega());
    const double lpairs = static_cast<double>(lpc.accepted);
    t0 = Clock::now();
    L.apply(x, y);
    const double lcpu_s = seconds_since(t0);
    std::printf("  Laplacian: N = %zu, %zu unknowns, dx = %g, h = %.6g, weight %s: %.0f pairs; "
                "CPU (one product) %.3f s = %.4g pairs/s\n",
                q.size(), L.n_unknowns(), lap_dx, hl, wl.name.c_str(), lpairs, lcpu_s,
                lpairs / lcpu_s);
    t.set("lap_h", hl);
    t.set("lap_h_rule", "(2.6^4 * 2^-10 * lap_dx)^(1/4)");
    t.add_row({"laplacian M_OO x " + wl.name, "cpu " + std::to_string(cpu_threads) + " threads",
               "4", gpm::fmt(q.size()), gpm::fmt(L.n_unknowns()),
               gpm::fmt(static_cast<long long>(lpc.accepted)),
               gpm::fmt(static_cast<long long>(lpc.candidates)), gpm::fmt(lcpu_s),
               gpm::fmt(lcpu_s), gpm::fmt(lcpu_s), gpm::fmt(lpairs / lcpu_s),
               gpm::fmt(lpairs / lcpu_s), "0", "", ""});
    const std::vector<double> xs(x.data(), x.data() + x.size());
    for (const int k : cells) {
      const gpm::cuda::CudaLaplacian gl(q, Vq, wl, hl, k);
      std::vector<double> gy;
      gl.apply(xs, gy);  // warm-up
      std::vector<double> ks, es;
      for (long long i = 0; i < repeats; ++i) {
        t0 = Clock::now();
        gl.apply(xs, gy);
        es.push_back(seconds_since(t0));
        ks.push_back(1e-3 * gl.last_kernel_ms());
      }
      std::sort(ks.begin(), ks.end());
      std::sort(es.begin(), es.end());
      const double diff =
          max_rel_diff(gy, std::span<const double>(y.data(), static_cast<std::size_t>(y.size())));
      worst = std::max(worst, diff);
      std::printf("  %-22s %5d %12s %10.5f %10.5f %11.4g %11.4g %9.2e\n", "laplacian M_OO x", k,
                  "", ks.front(), es.front(), lpairs / ks.front(), lpairs / es.front(), diff);
      std::fflush(stdout);
      t.add_row({"laplacian M_OO x " + wl.name, "gpu", gpm::fmt(k), gpm::fmt(q.size()),
                 gpm::fmt(L.n_unknowns()), gpm::fmt(static_cast<long long>(lpc.accepted)), "",
                 gpm::fmt(ks.front()), gpm::fmt(ks[ks.size() / 2]), gpm::fmt(es.front()),
                 gpm::fmt(lpairs / ks.front()), gpm::fmt(lpairs / es.front()), gpm::fmt(diff),
                 "", ""});
    }
  }

  // The studies' own passes (every weight and test function of a study at once, as the
  // --device cuda runs do) against the CPU's, and their floating-point rate (the body's
  // operations per pair) as a fraction of the device's measured fp64 peak.
  const double peak = gpm::cuda::fp64_peak_flops();
  t.set("fp64_peak_flops", peak);
  t.set("fp64_peak_note", "DFMA microkernel, 2 FLOP per FMA, this device; flops_per_pair: "
                          "operations of fused_target_sums per pair (body_flops_per_pair)");
  std::printf("  fp64 peak (DFMA microkernel): %.4g FLOP/s\n", peak);
  struct Mix {
    std::string name;
    std::vector<gpm::ErrorRequest> req;
    std::vector<std::string> fns;
  };
  std::vector<Mix> mixes = {{"imoto9", gpm::imoto_study().requests(), {gpm::imoto_study().function}}};
  std::vector<std::string> cases;
  for (auto& c : gpm::thesis_cases()) cases.push_back(c.function);
  for (auto& spec : gpm::thesis_table_specs()) mixes.push_back({spec.mix(), spec.requests, cases});
  for (const Mix& m : mixes) {
    const std::vector<gpm::KernelWeight> kw = gpm::kernel_weights(m.req);
    std::vector<std::vector<double>> fields;
    for (auto& fn : m.fns) {
      const auto& tf = gpm::test_function(fn);
      std::vector<double> fv(p.size());
      for (std::size_t i = 0; i < p.size(); ++i) fv[i] = tf.v(p.x[i], p.y[i]);
      fields.push_back(std::move(fv));
    }
    const gpm::FusedKernel mc(p, V, h, kw, copt);
    t0 = Clock::now();
    const gpm::KernelResult mref = mc.apply(targets, fields);
    const double mcpu_s = seconds_since(t0);
    std::vector<std::pair<gpm::WeightFunction, unsigned>> wp;
    std::vector<gpm::cuda::WeightEntry> entries;
    for (auto& k : kw) wp.emplace_back(k.weight, k.ops), entries.push_back(gpm::cuda::weight_entry(k.weight, k.ops));
    const gpm::cuda::CudaFusedPass gp(p, V, h, wp);
    gpm::cuda::CudaPassResult r = gp.apply(targets, fields);  // warm-up
    std::vector<double> ks;
    for (long long i = 0; i < repeats; ++i) ks.push_back(1e-3 * (r = gp.apply(targets, fields)).kernel_ms);
    std::sort(ks.begin(), ks.end());
    double diff = 0;
    const int nf = static_cast<int>(fields.size());
    for (int w = 0; w < static_cast<int>(kw.size()); ++w)
      for (int f2 = 0; f2 < nf; ++f2) {
        auto cmp = [&](int c, std::span<const double> cpu_col) {
          const std::vector<double> g(r.column(w, f2, c), r.column(w, f2, c) + r.nt);
          diff = std::max(diff, max_rel_diff(g, cpu_col));
        };
        if (kw[w].ops & gpm::kInterp) cmp(0, mref.interpolant(w, f2));
        if (kw[w].ops & gpm::kGrad) cmp(1, mref.grad_x(w, f2)), cmp(2, mref.grad_y(w, f2));
        if (kw[w].ops & gpm::kLap) cmp(3, mref.laplacian(w, f2));
      }
    worst = std::max(worst, diff);
    const double fpp = gpm::cuda::body_flops_per_pair(entries, nf);
    const double rate = pairs / ks.front();
    std::printf("  %-22s %5d %12s %10.5f %10s %11.4g %11s %9.2e  %.0f flop/pair, %.3f of fp64 peak"
                " (CPU %.3f s)\n", ("pass " + m.name).c_str(), 4, "", ks.front(), "", rate, "",
                diff, fpp, rate * fpp / peak, mcpu_s);
    t.add_row({"pass " + m.name, "gpu", "4", gpm::fmt(p.size()), gpm::fmt(targets.size()),
               gpm::fmt(static_cast<long long>(pc.accepted)), "", gpm::fmt(ks.front()),
               gpm::fmt(ks[ks.size() / 2]), "", gpm::fmt(rate), "", gpm::fmt(diff), gpm::fmt(fpp),
               gpm::fmt(rate * fpp / peak)});
  }

  t.set("max_rel_diff_vs_cpu", worst);
  t.set("check", worst <= tol ? "passed" : "FAILED");
  t.set("wall_time_s", seconds_since(wall_start));
  const std::string out = args.str("out");
  t.save(out);
  std::printf("  GPU vs CPU: max relative difference %.2e (tolerance %g); wrote %s\n", worst, tol,
              out.c_str());
  if (!(worst <= tol))
    throw gpm::NumericalError("GPU results differ from the CPU kernel: max relative difference " +
                              gpm::fmt(worst) + " > tolerance " + gpm::fmt(tol) + " (see " + out +
                              ")");
  return 0;
}

}  // namespace

int main(int argc, char** argv) { return gpm::run_main("bench_cuda", body, argc, argv); }
