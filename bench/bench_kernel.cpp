// bench_kernel: throughput of the neighbour-sum kernel (pairs with r < h per second).
//
// Setting (the report's performance appendix, paper/60-performance.md): jittered grid Δx = 2^-9 (seed 1), h = 0.03, uniform
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
//   study:<mix>      a study's own pass (imoto9, thesis4_1 … thesis4_3: its weights, its
//                    number of fields), against bench_limit's kernel_l1:<mix> — the kernel
//                    on the same mix with every candidate in L1 (--variants studies: these
//                    only; all: every variant)
// The machine is shared (others compile on it): compare variants within one run.
//
// Against the measured limit (bench_limit → --limit file): each one-weight variant's
// candidate pairs per second (the lanes its loop actually computes: accepted pairs × the
// candidates per pair of its cell layout) over the rate of the kernel's arithmetic mix for
// the same weight with data in L1 — the fraction of what the arithmetic alone allows.
// Both are also given from CPU time (process CPU seconds / threads), which a shared
// machine disturbs much less than wall time.  fused3/fused9 have no limit of their own (blank);
// the study passes have theirs (kernel_l1).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <functional>
#include <map>
#include <numbers>
#include <tuple>
#include <string>
#include <vector>

#include "gpm/io/args.hpp"
#include "limit_table.hpp"
#include "study_mixes.hpp"
#include "gpm/error.hpp"
#include "gpm/geometry/domain.hpp"
#include "gpm/io/tsv.hpp"
#include "gpm/kernel/kernel.hpp"
#include "gpm/kernel/plain_baseline.hpp"
#include "gpm/operators/testfunctions.hpp"
#include "gpm/weights/weights.hpp"

namespace {

using Clock = std::chrono::steady_clock;

struct Timing {
  double best = 0, median = 0;
  double cpu_best = 0;  // process CPU seconds of the call (all threads), least over repeats
};

double process_cpu_seconds() {
  timespec ts;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

Timing time_it(int repeats, const std::function<void()>& f) {
  f();  // warm-up (page faults, caches, thread pool)
  std::vector<double> t;
  double cpu = 1e300;
  for (int r = 0; r < repeats; ++r) {
    const double c0 = process_cpu_seconds();
    const auto a = Clock::now();
    f();
    t.push_back(std::chrono::duration<double>(Clock::now() - a).count());
    cpu = std::min(cpu, process_cpu_seconds() - c0);
  }
  std::sort(t.begin(), t.end());
  return {t.front(), t[t.size() / 2], cpu};
}

std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
  return "unknown";
}

// What each variant changes, and the variant it is a step from (for the report's table of
// steps and what each gained; "vs_previous" = its rate over the previous one's).
struct Step {
  const char* previous;
  const char* description;
};
const std::map<std::string, Step>& steps() {
  static const std::map<std::string, Step> s = {
      {"plain", {"", "per target 3x3 cells of size h, array of structs, if (r < h)"}},
      {"fused1_cells1",
       {"plain", "sorted by cell, structure of arrays, branch-free 8-lane loop over the chord "
                 "of each row of h-cells"}},
      {"fused1", {"fused1_cells1", "cells of h/4: fewer candidates per pair (chord)"}},
      {"fused1_nodiv", {"fused1", "a weight whose w/q^2 is a polynomial: no divide"}},
      {"fused1_block",
       {"fused1", "the multi-weight block path for one weight (block in L1, per-weight loop)"}},
      {"fused1_compact", {"fused1_block", "block path, accepted pairs compressed before the sqrt"}},
      {"fused1_rsqrt", {"fused1_block", "block path, rsqrt14 + 2 Newton steps for 1/r"}},
      {"separate3", {"", "3 weights as 3 single-weight passes"}},
      {"fused3", {"separate3", "3 weights in one pass (shared sqrt/divide, block path)"}},
      {"separate9", {"", "imoto's 9 weight/operator sets as 9 passes"}},
      {"fused9", {"separate9", "the 9 sets in one pass"}}};
  return s;
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
      .opt("limit", "data/bench/limit.tsv",
           "bench_limit's output, for the fraction of the limit (absent file: no fractions)")
      .opt("profile", "bench", "label recorded as the file's profile (the report's rules pass theirs)")
      .output("out", "data/bench/kernel.tsv", "TSV output");
  args.parse(argc, argv);
  const double dx = args.positive("dx"), h = args.positive("h");
  const long long repeats = args.integer("repeats", 1, 1000000);
  const uint64_t seed = args.seed();
  const int cells_per_h = static_cast<int>(args.integer("cells-per-h", 1, 64));
  std::vector<int> threads;
  for (double t : args.nums("threads")) {
    if (t < 1 || t != std::floor(t)) throw gpm::InputError("--threads: positive integers");
    threads.push_back(static_cast<int>(t));
  }
  std::vector<std::string> variants = args.list("variants");
  // In the order of the steps (a variant runs after the one it is compared with).
  const std::vector<std::string> all = {
      "plain",          "fused1_cells1", "fused1",    "fused1_nodiv", "fused1_block",
      "fused1_compact", "fused1_rsqrt",  "separate3", "fused3",       "separate9",
      "fused9"};
  // The studies' own passes (bench/study_mixes.hpp), each against its mix's limit.
  std::vector<std::string> known = all;
  for (const auto& sm : bench::study_mixes()) known.push_back("study:" + sm.name);
  if (variants.size() == 1 && variants[0] == "all") variants = known;
  if (variants.size() == 1 && variants[0] == "studies") variants.assign(known.begin() + all.size(), known.end());
  for (auto& v : variants)
    if (std::find(known.begin(), known.end(), v) == known.end())
      throw gpm::InputError("unknown variant '" + v + "'");
  const std::string w1 = args.str("weight");
  gpm::weight(w1);  // validates the name

  const gpm::Particles p = gpm::jittered_grid(dx, seed);
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

  const bench::LimitTable limits(args.str("limit"));
  if (!limits.loaded())
    std::printf("  (no limit file '%s': run bench_limit first for the fractions)\n\n",
                args.str("limit").c_str());
  const auto wall_start = Clock::now();

  gpm::TsvTable t;
  t.set("program", "bench_kernel");
  t.set("profile", args.str("profile"));
  for (auto& [k, val] : args.values()) t.set("arg_" + k, val);
  t.set("n_particles", gpm::fmt(p.size()));
  t.set("n_targets", gpm::fmt(targets.size()));
  t.set("pairs", gpm::fmt(static_cast<long long>(pc.accepted)));
  t.set("candidates_h4", gpm::fmt(static_cast<long long>(pc.candidates)));
  t.set("candidates_h1_chord", gpm::fmt(static_cast<long long>(pc1.candidates)));
  t.set("cpu", cpu_model());
  t.set("cpu_family_model", bench::cpu_family_model());
  t.set("loadavg_1min_start", bench::loadavg());
  t.set("note", "rates = accepted pairs (r<h, self included) / wall seconds of one call; "
                "machine shared with concurrent builds, compare variants within one run");
  gpm::add_provenance(t);
  t.columns = {"variant", "threads", "weights", "ops", "mode", "cells_per_h", "pairs",
               "seconds_best", "seconds_median", "pairs_per_s", "pair_weights_per_s",
               "ns_per_pair_weight_thread", "speedup_vs_plain", "candidates_per_pair",
               "candidates_per_s", "limit_test", "limit_pairs_per_s", "fraction_of_limit",
               "pairs_per_s_cpu", "candidates_per_s_cpu", "limit_pairs_per_s_cpu",
               "fraction_of_limit_cpu", "previous", "vs_previous", "description"};

  std::printf("%-15s %3s %3s %-6s %8s %8s %10s %8s %10s %7s %7s\n", "variant", "thr", "nw",
              "ops", "best_s", "median_s", "pairs/s", "vs plain", "cand/s", "f_lim", "f_cpu");
  std::vector<double> plain_rate(threads.size(), 0);
  std::map<std::string, double> best;  // "variant/threads" → best seconds
  std::map<std::string, double> rate_of;  // "variant/threads" → pairs per second

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
      opt.cells_per_h = cells_per_h;
      opt.fast_rsqrt = args.has("fast-rsqrt");
      opt.fuse_single = !args.has("no-fuse-single");
      std::vector<std::vector<gpm::KernelWeight>> passes;  // one kernel call each
      std::string mode = "compact";
      std::string ops = "P+G+L";
      int nw = 1, nfields = 1;
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
        else if (var.rfind("study:", 0) == 0) {
          for (const auto& sm : bench::study_mixes())
            if ("study:" + sm.name == var) {
              passes = {sm.weights};
              nfields = sm.fields;
            }
          ops = "study mix";
        }
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
        std::vector<const std::vector<double>*> fptr;
        for (int j = 0; j < nfields; ++j) fptr.push_back(&fields[0]);  // the same values: rate only
        tm = time_it(static_cast<int>(repeats), [&] {
          for (std::size_t k = 0; k < kernels.size(); ++k) kernels[k].apply(targets, fptr, res[k]);
        });
        if (ti == 0 && passes.size() == 1 && passes[0][0].weight.name == w1) check(res[0].laplacian(0, 0));
      }
      const double rate = pairs / tm.best;
      const bool study = var.rfind("study:", 0) == 0;
      if (var == "plain") plain_rate[ti] = rate;
      rate_of[var + "/" + std::to_string(nt)] = rate;
      const Step step = study ? Step{"", "a study's own pass: its weights and fields (catalog)"}
                              : steps().at(var);
      const auto prev = rate_of.find(std::string(step.previous) + "/" + std::to_string(nt));
      const double vs_prev = prev != rate_of.end() ? rate / prev->second : NAN;
      best[var + "/" + std::to_string(nt)] = tm.best;
      const double ns = 1e9 * tm.best * nt / (pairs * nw);
      const double speed = plain_rate[ti] > 0 ? rate / plain_rate[ti] : NAN;
      // Candidates per accepted pair of this variant's cell layout (plain: 3×3 cells of h,
      // 9/π on average); separate passes each visit the candidates once.
      double cpp = var == "plain"           ? 9.0 / std::numbers::pi
                   : var == "fused1_cells1" ? static_cast<double>(pc1.candidates) / pairs
                                            : static_cast<double>(pc.candidates) / pairs;
      // The limit: the arithmetic mix of the same single weight (Π+∇+Δ).
      std::string limit_test;
      if (nw == 1 && passes.size() <= 1)
        limit_test = "mix:" + std::string(var == "fused1_nodiv" ? "quartic_polynomial" : w1) +
                     ":PGL";
      // A study pass against the kernel on its own mix held in L1 (bench_limit
      // --study-mixes): pairs against pairs, so the fraction includes the candidates the
      // cell layout adds, the memory traffic and the per-target work.
      if (study) limit_test = "kernel_l1:" + var.substr(6);
      const bench::Limit lim = limit_test.empty() ? bench::Limit{} : limits.get(limit_test, nt);
      if (!lim.found()) limit_test.clear();
      const double cand_rate = rate * cpp;
      const double frac = !lim.found() ? NAN : study ? rate / lim.rate : cand_rate / lim.rate;
      const double rate_cpu = pairs / (tm.cpu_best / nt);
      const double frac_cpu = !lim.found() ? NAN
                              : study      ? rate_cpu / lim.rate_cpu
                                           : rate_cpu * cpp / lim.rate_cpu;
      auto opt_fmt = [](double x) { return std::isfinite(x) ? gpm::fmt(x) : std::string(); };
      std::printf("%-15s %3d %3d %-6s %8.4f %8.4f %10.4g %8.2f %10.4g %7.3f %7.3f\n",
                  var.c_str(), nt, nw, ops.c_str(), tm.best, tm.median, rate, speed,
                  cand_rate, frac, frac_cpu);
      std::fflush(stdout);
      t.add_row({var, gpm::fmt(nt), gpm::fmt(nw), ops, mode,
                 gpm::fmt(var == "plain" ? 0 : opt.cells_per_h),
                 gpm::fmt(static_cast<long long>(pc.accepted)), gpm::fmt(tm.best),
                 gpm::fmt(tm.median), gpm::fmt(rate), gpm::fmt(rate * nw), gpm::fmt(ns),
                 opt_fmt(speed), gpm::fmt(cpp), gpm::fmt(cand_rate), limit_test,
                 opt_fmt(lim.rate), opt_fmt(frac), gpm::fmt(rate_cpu), gpm::fmt(rate_cpu * cpp),
                 opt_fmt(lim.rate_cpu), opt_fmt(frac_cpu), step.previous, opt_fmt(vs_prev),
                 step.description});
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
  t.set("limit_file", args.str("limit"));
  t.set("loadavg_1min_end", bench::loadavg());
  t.set("wall_time_s", std::chrono::duration<double>(Clock::now() - wall_start).count());
  const std::string out = args.str("out");
  t.save(out);
  std::printf("  wrote %s\n", out.c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) { return gpm::run_main("bench_kernel", body, argc, argv); }
