// bench_kernel: throughput of the neighbour-sum kernel (pairs with r < h per second).
//
// Setting (notes/kernel-throughput.md): jittered grid Δx = 2^-9 (seed 1), h = 0.03, uniform
// volumes, targets = the particles in Ω (262,144), one field (sin 2π(x+y)).  The pairs
// (target, i) with |x_i − x_j| < h, the target itself included, are counted once, untimed;
// every rate is that count divided by the wall time of one kernel call (best of the
// repeats; the median is reported too).
//
// Variants (each with every thread count of --threads):
//   plain            per-target loop over 3×3 cells of size h, array of structs, if (r < h)
//   fused1           fused kernel, one weight (--weight, default Π2 = cubic B-spline),
//                    Π+∇+Δ, cells of h/4, the fully fused single-weight loop
//   fused1_block     same through the multi-weight block path (shared block + per-weight loop)
//   fused1_compact   block path, accepted pairs compacted (AVX-512 compress) before the sqrt
//   fused1_cells1    fused loop, cells of size h (chord over ≤ 3 cells per row)
//   fused1_rsqrt     block path, 1/√r² by rsqrt14 + 2 Newton steps (AVX-512 only)
//   fused1_nodiv     one weight whose w/q² is a polynomial (quartic_polynomial): no divide
//   fused3           three weights, Π+∇+Δ each (cubic spike, cubic and quintic B-spline)
//   fused9           imoto's nine: Π1–Π3 (Π), ∇1–∇3 (∇), Δ1–Δ3 (Δ)
//   separate3/9      the same weights as single-weight passes, times summed
// The machine is shared (others compile on it): compare variants within one run.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <map>
#include <numbers>
#include <tuple>
#include <string>
#include <vector>

#include "gpm/args.hpp"
#include "gpm/domain.hpp"
#include "gpm/error.hpp"
#include "gpm/kernel.hpp"
#include "gpm/testfunctions.hpp"
#include "gpm/tsv.hpp"
#include "gpm/weights.hpp"

namespace {

using Clock = std::chrono::steady_clock;

struct Timing {
  double best = 0, median = 0;
};

Timing time_it(int repeats, const std::function<void()>& f) {
  f();  // warm-up (page faults, caches, thread pool)
  std::vector<double> t;
  for (int r = 0; r < repeats; ++r) {
    const auto a = Clock::now();
    f();
    t.push_back(std::chrono::duration<double>(Clock::now() - a).count());
  }
  std::sort(t.begin(), t.end());
  return {t.front(), t[t.size() / 2]};
}

std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
  return "unknown";
}

std::vector<gpm::KernelWeight> with_ops(const std::vector<std::string>& names, unsigned ops) {
  std::vector<gpm::KernelWeight> w;
  for (auto& n : names) w.push_back({gpm::weight(n), ops});
  return w;
}

int body(int argc, char** argv) {
  gpm::Args args("bench_kernel",
                 "Pairs (r < h) per second of the fused neighbour-sum kernel against a plain "
                 "loop, 1 and 2 threads.");
  args.opt("dx", "2^-9", "particle spacing of the jittered grid")
      .opt("h", "0.03", "influence radius")
      .opt("seed", "1", "jitter seed")
      .opt("threads", "1,2", "comma-separated thread counts")
      .opt("repeats", "5", "timed repetitions per measurement (best and median reported)")
      .opt("weight", "Pi2", "weight of the one-weight variants (Π+∇+Δ)")
      .opt("variants", "all",
           "comma-separated subset of: plain, fused1, fused1_block, fused1_compact, "
           "fused1_cells1, fused1_rsqrt, fused1_nodiv, fused3, separate3, fused9, separate9")
      .opt("cells-per-h", "4", "cell size h/k of the fused variants (fused1_cells1: k = 1)")
      .flag("fast-rsqrt", "all fused variants: 1/sqrt(r^2) by rsqrt14 + Newton (AVX-512)")
      .flag("no-fuse-single", "one-weight variants through the block path too")
      .opt("out", "data/bench/kernel.tsv", "TSV output");
  args.parse(argc, argv);
  const double dx = args.positive("dx"), h = args.positive("h");
  const long long repeats = args.integer("repeats");
  if (repeats < 1) throw gpm::InputError("--repeats must be >= 1");
  std::vector<int> threads;
  for (double t : args.nums("threads")) {
    if (t < 1 || t != std::floor(t)) throw gpm::InputError("--threads: positive integers");
    threads.push_back(static_cast<int>(t));
  }
  std::vector<std::string> variants = args.list("variants");
  const std::vector<std::string> all = {
      "plain",        "fused1",       "fused1_block", "fused1_compact", "fused1_cells1",
      "fused1_rsqrt", "fused1_nodiv", "fused3",       "separate3",      "fused9",
      "separate9"};
  if (variants.size() == 1 && variants[0] == "all") variants = all;
  for (auto& v : variants)
    if (std::find(all.begin(), all.end(), v) == all.end())
      throw gpm::InputError("unknown variant '" + v + "'");
  const std::string w1 = args.str("weight");
  gpm::weight(w1);  // validates the name

  const gpm::Particles p = gpm::jittered_grid(dx, static_cast<uint64_t>(args.integer("seed")));
  const std::vector<double> V(p.size(), gpm::Domain{}.area_H() / static_cast<double>(p.size()));
  const auto& f = gpm::test_function("sin2pi");
  std::vector<double> v(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) v[i] = f.v(p.x[i], p.y[i]);
  const std::vector<int32_t> targets = gpm::omega_targets(p);
  const std::vector<std::vector<double>> fields{v};

  // Pair counts, once, untimed.
  const gpm::FusedKernel counter(p, V, h, with_ops({w1}, gpm::kAllOps));
  const gpm::PairCount pc = counter.count_pairs(targets);
  gpm::KernelOptions o1;
  o1.cells_per_h = 1;
  const gpm::PairCount pc1 = gpm::FusedKernel(p, V, h, with_ops({w1}, gpm::kAllOps), o1)
                                 .count_pairs(targets);
  const double pairs = static_cast<double>(pc.accepted);
  std::printf("bench_kernel: N = %zu particles, %zu targets in Omega, dx = %g, h = %g\n",
              p.size(), targets.size(), dx, h);
  std::printf("  %.0f pairs (r < h, self included) = %.1f per target; candidates per pair: "
              "%.3f (cells h/4, chord), %.3f (cells h, chord), %.3f (3x3 cells of h)\n",
              pairs, pairs / targets.size(), pc.candidates / pairs, pc1.candidates / pairs,
              9.0 / std::numbers::pi);
  std::printf("  CPU: %s; timings are the best of %lld runs (machine shared: compare within "
              "one run)\n\n",
              cpu_model().c_str(), repeats);

  gpm::TsvTable t;
  t.set("program", "bench_kernel");
  for (auto& [k, val] : args.values()) t.set("arg_" + k, val);
  t.set("n_particles", gpm::fmt(p.size()));
  t.set("n_targets", gpm::fmt(targets.size()));
  t.set("pairs", gpm::fmt(static_cast<long long>(pc.accepted)));
  t.set("candidates_h4", gpm::fmt(static_cast<long long>(pc.candidates)));
  t.set("candidates_h1_chord", gpm::fmt(static_cast<long long>(pc1.candidates)));
  t.set("cpu", cpu_model());
  t.set("note", "rates = accepted pairs (r<h, self included) / wall seconds of one call; "
                "machine shared with concurrent builds, compare variants within one run");
  gpm::add_provenance(t);
  t.columns = {"variant", "threads", "weights", "ops", "mode", "cells_per_h", "pairs",
               "seconds_best", "seconds_median", "pairs_per_s", "pair_weights_per_s",
               "ns_per_pair_weight_thread", "speedup_vs_plain"};

  std::printf("%-15s %3s %3s %-8s %9s %9s %14s %12s %9s\n", "variant", "thr", "nw", "ops",
              "best_s", "median_s", "pairs/s", "ns/pair·w·thr", "vs plain");
  std::vector<double> plain_rate(threads.size(), 0);
  std::map<std::string, double> best;  // "variant/threads" → best seconds

  // A check that the variants compute the same numbers (max relative difference).
  std::vector<double> ref_lap;
  double worst_check = 0;
  auto check = [&](std::span<const double> lap) {
    if (ref_lap.empty()) {
      ref_lap.assign(lap.begin(), lap.end());
      return;
    }
    double d = 0, s = 0;
    for (std::size_t i = 0; i < lap.size(); ++i) {
      d = std::max(d, std::abs(lap[i] - ref_lap[i]));
      s = std::max(s, std::abs(ref_lap[i]));
    }
    worst_check = std::max(worst_check, d / s);
  };

  for (const auto& var : variants) {
    for (std::size_t ti = 0; ti < threads.size(); ++ti) {
      const int nt = threads[ti];
      gpm::KernelOptions opt;
      opt.threads = nt;
      opt.cells_per_h = static_cast<int>(args.integer("cells-per-h"));
      opt.fast_rsqrt = args.has("fast-rsqrt");
      opt.fuse_single = !args.has("no-fuse-single");
      std::vector<std::vector<gpm::KernelWeight>> passes;  // one kernel call each
      std::string mode = "compact";
      std::string ops = "P+G+L";
      int nw = 1;
      Timing tm;
      if (var == "plain") {
        mode = "plain";
        gpm::BaselineResult br;
        tm = time_it(static_cast<int>(repeats), [&] {
          br = gpm::plain_baseline(p.x, p.y, V, v, gpm::weight(w1), h, targets, nt);
        });
        if (ti == 0) check(br.lap);
      } else {
        if (var == "fused1" || var == "fused1_block" || var == "fused1_compact" ||
            var == "fused1_cells1" || var == "fused1_rsqrt")
          passes = {with_ops({w1}, gpm::kAllOps)};
        else if (var == "fused1_nodiv")
          passes = {with_ops({"quartic_polynomial"}, gpm::kAllOps)};
        else if (var == "fused3")
          passes = {with_ops({"cubic_spike", "cubic_bspline", "quintic_bspline"}, gpm::kAllOps)};
        else if (var == "separate3")
          for (auto n : {"cubic_spike", "cubic_bspline", "quintic_bspline"})
            passes.push_back(with_ops({n}, gpm::kAllOps));
        else {
          std::vector<gpm::KernelWeight> nine = with_ops({"Pi1", "Pi2", "Pi3"}, gpm::kInterp);
          for (auto& w : with_ops({"Grad1", "Grad2", "Grad3"}, gpm::kGrad)) nine.push_back(w);
          for (auto& w : with_ops({"Lap1", "Lap2", "Lap3"}, gpm::kLap)) nine.push_back(w);
          if (var == "fused9") {
            passes = {nine};
          } else {
            for (auto& w : nine) passes.push_back({w});
          }
          ops = "9 sets";
        }
        mode = passes.size() == 1 && passes[0].size() == 1 && opt.fuse_single ? "fused loop"
                                                                               : "block";
        if (var == "fused1_block") opt.fuse_single = false, mode = "block";
        if (var == "fused1_compact") opt.compact = true, mode = "block, compact";
        if (var == "fused1_cells1") opt.cells_per_h = 1;
        if (var == "fused1_rsqrt") opt.fast_rsqrt = true, mode = "block, rsqrt";
        if (var.rfind("separate", 0) == 0) mode = "separate passes (fused loop)";
        std::vector<gpm::FusedKernel> kernels;
        nw = 0;
        for (auto& ws : passes) {
          nw += static_cast<int>(ws.size());
          kernels.emplace_back(p, V, h, ws, opt);
        }
        // Steady state, as in a time loop: results written into reused storage.
        std::vector<gpm::KernelResult> res(kernels.size());
        const std::vector<const std::vector<double>*> fptr{&fields[0]};
        tm = time_it(static_cast<int>(repeats), [&] {
          for (std::size_t k = 0; k < kernels.size(); ++k) kernels[k].apply(targets, fptr, res[k]);
        });
        if (ti == 0 && passes.size() == 1 && passes[0][0].weight.name == w1) check(res[0].laplacian(0, 0));
      }
      const double rate = pairs / tm.best;
      if (var == "plain") plain_rate[ti] = rate;
      best[var + "/" + std::to_string(nt)] = tm.best;
      const double ns = 1e9 * tm.best * nt / (pairs * nw);
      const double speed = plain_rate[ti] > 0 ? rate / plain_rate[ti] : NAN;
      std::printf("%-15s %3d %3d %-8s %9.4f %9.4f %14.4g %12.3f %9.2f\n", var.c_str(), nt, nw,
                  ops.c_str(), tm.best, tm.median, rate, ns, speed);
      std::fflush(stdout);
      t.add_row({var, gpm::fmt(nt), gpm::fmt(nw), ops, mode,
                 gpm::fmt(var == "plain" ? 0 : opt.cells_per_h),
                 gpm::fmt(static_cast<long long>(pc.accepted)), gpm::fmt(tm.best),
                 gpm::fmt(tm.median), gpm::fmt(rate), gpm::fmt(rate * nw), gpm::fmt(ns),
                 std::isnan(speed) ? std::string() : gpm::fmt(speed)});
    }
  }
  // Per (pair × weight): one multi-weight pass against the same weights one by one.
  std::printf("\n");
  for (const int nt : threads)
    for (const auto& [multi, sep, nw] : {std::tuple<std::string, std::string, int>{"fused3", "separate3", 3},
                                         {"fused9", "separate9", 9}}) {
      const auto a = best.find(multi + "/" + std::to_string(nt));
      const auto b = best.find(sep + "/" + std::to_string(nt));
      if (a == best.end() || b == best.end()) continue;
      std::printf("  %d thread(s), %d weights: %.3f ns (wall) per pair x weight in one pass, "
                  "%.3f ns in %d single-weight passes (%.2fx)\n",
                  nt, nw, 1e9 * a->second / (pairs * nw), 1e9 * b->second / (pairs * nw), nw,
                  b->second / a->second);
      t.set("per_pair_weight_ns_" + multi + "_" + std::to_string(nt) + "thr",
            1e9 * a->second / (pairs * nw));
      t.set("per_pair_weight_ns_" + sep + "_" + std::to_string(nt) + "thr",
            1e9 * b->second / (pairs * nw));
    }
  if (ref_lap.empty() || worst_check == 0)
    std::printf("\n  (no two one-weight variants with weight %s ran: no cross-check)\n", w1.c_str());
  else
    std::printf("\n  Laplacian of the one-weight variants vs the first: max relative difference "
                "%.2e\n",
                worst_check);
  t.set("check_max_rel_diff", worst_check);
  const std::string out = args.str("out");
  t.save(out);
  std::printf("  wrote %s\n", out.c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) { return gpm::run_main("bench_kernel", body, argc, argv); }
