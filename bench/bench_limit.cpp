// bench_limit: what this machine can do, measured — the yardstick of bench_kernel and
// bench_laplacian (issue 7, item 1).
//
// Two kinds of limit:
//  (a) arithmetic.  The neighbour-sum kernel spends, per candidate pair (one vector lane),
//      one square root, at most one divide, a few Horner FMAs and some accumulations.  The
//      "mix" tests run exactly the operations of the kernel's fused one-weight loop
//      (kernel_fused1.hpp, fused1_range: same masks, same Horner per piece, same accumulators)
//      over 512 candidates kept in L1 and reused, so nothing waits on memory and nothing
//      else (cell ranges, tails, per-target reductions) is done: the rate the kernel would
//      reach if a candidate cost only its arithmetic.  The pure tests (sqrt, divide,
//      sqrt + divide, FMA) show which unit binds.
//  (b) memory.  STREAM-like triad a = b + s·c and a read-only sum over arrays far larger
//      than the last-level cache; bytes counted as STREAM does (triad 24 B per element,
//      the write-allocate read not counted; sum 8 B).
// Each test runs with every thread count of --threads; with t threads every thread does
// the same work on its own data, the rate is the total.  Best of --repeats timed runs
// after one warm-up.  The machine is shared: compare within one run.
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "gpm/error.hpp"
#include "gpm/io/args.hpp"
#include "gpm/io/tsv.hpp"
#include "gpm/kernel/simd.hpp"
#include "gpm/weights/weights.hpp"
#include "gpm/kernel/kernel.hpp"
#include "limit_table.hpp"
#include "study_mixes.hpp"

namespace {

// Vectors exactly as in the kernel (gpm/kernel/simd.hpp): the same helpers, the same instructions.
using namespace gpm::simd;

using Clock = std::chrono::steady_clock;
volatile double g_sink = 0;  // results go here so no loop is optimized away

// ---------------------------------------------------------------------------------
// The candidates: 512 pairs (L1: 4 arrays × 4 KB) scattered uniformly over the square
// [−h, h]², so that as in the kernel about π/4 of them lie in the disc r < h.
constexpr int kL = 512;
struct Candidates {
  alignas(64) double x[kL], y[kL], V[kL], v[kL];
  explicit Candidates(uint64_t seed) {
    uint64_t s = seed * 0x9E3779B97F4A7C15ull + 1;
    auto u = [&] {  // uniform in [0, 1)
      s = s * 6364136223846793005ull + 1442695040888963407ull;
      return static_cast<double>(s >> 11) * 0x1.0p-53;
    };
    for (int k = 0; k < kL; ++k) {
      x[k] = 2 * u() - 1;  // h = 1 below: the mix is scale-free
      y[k] = 2 * u() - 1;
      V[k] = 0.5 + u();
      v[k] = u();
    }
  }
};

// The weight as the kernel sees it: NP pieces, NC coefficients (padded like the kernel's
// instantiations), and whether w/q² needs the divide.
struct MixPlan {
  int np = 1, nc = 2, m = 0;
  double begin[3] = {};
  double cpi[3][8] = {}, cg[3][8] = {};
};

int pad_nc(int nc) { return nc <= 2 ? 2 : nc <= 6 ? nc : 8; }

MixPlan plan_for(const gpm::WeightFunction& w) {
  MixPlan mp;
  std::vector<const gpm::PolyPiece*> ps;
  for (const auto& p : w.shape)
    if (p.r_begin < 1) ps.push_back(&p);
  if (ps.empty() || ps.size() > 3)
    throw gpm::InputError("weight '" + w.name + "': the mix handles 1 to 3 pieces");
  mp.np = static_cast<int>(ps.size());
  int nc = 1, low = 99;
  for (auto* p : ps)
    for (std::size_t j = 0; j < p->c.size(); ++j)
      if (p->c[j] != 0) {
        nc = std::max(nc, p->p_min + static_cast<int>(j) + 1);
        low = std::min(low, p->p_min + static_cast<int>(j));
      }
  mp.m = std::max(0, 2 - low);  // power of 1/q left in w/q²
  if (nc > 8) throw gpm::InputError("weight '" + w.name + "': degree above 7");
  mp.nc = pad_nc(nc);
  for (int i = 0; i < mp.np; ++i) {
    mp.begin[i] = ps[i]->r_begin;
    for (std::size_t j = 0; j < ps[i]->c.size(); ++j) {
      const int e = ps[i]->p_min + static_cast<int>(j);
      if (e >= 0) mp.cpi[i][e] = w.constant * ps[i]->c[j];
      if (e - 2 + mp.m >= 0) mp.cg[i][e - 2 + mp.m] = w.constant * ps[i]->c[j];
    }
  }
  return mp;
}

// The kernel's fused one-weight step (kernel_fused1.hpp, fused1_range) over the candidates,
// `sweeps` times.  PI: Π wanted; GM = 5: G = W·h²/r² (one divide), GM = 1: own Horner
// of w/q² (no divide).  Returns the sum of the accumulators.
template <int NP, int NC, bool PI, int GM>
double mix_loop(const Candidates& c, const MixPlan& w, long long sweeps) {
  const vd PX = vbc(0.01), PY = vbc(-0.02), H2 = vbc(1.0), H = vbc(1.0), Z = vbc(0.0),
           INVH = vbc(1.0), VT = vbc(0.3);
  vd api = Z, agx = Z, agy = Z, alap = Z;
  for (long long s = 0; s < sweeps; ++s) {
    for (int k = 0; k < kL; k += kW) {
      const vd dx = vload(c.x + k) - PX, dy = vload(c.y + k) - PY;
      const vd r2 = dx * dx + dy * dy;
      const vm in = r2 < H2;
      const vm nz = in & (r2 > Z);
      const vd V = in ? vload(c.V + k) : Z;
      const vd v = vload(c.v + k);
      const vd q = vsqrt(r2) * INVH;
      vd W = Z, Gq;
      if constexpr (PI || GM == 5) {
        W = horner<NC>(w.cpi[0], q);
        for (int p = 1; p < NP; ++p) W = (q >= vbc(w.begin[p])) ? horner<NC>(w.cpi[p], q) : W;
      }
      if constexpr (PI) api += (V * v) * W;
      if constexpr (GM == 5) {
        Gq = nz ? W * (H2 / r2) : Z;
      } else {
        Gq = horner<NC>(w.cg[0], q);
        for (int p = 1; p < NP; ++p) Gq = (q >= vbc(w.begin[p])) ? horner<NC>(w.cg[p], q) : Gq;
        Gq = nz ? Gq : Z;
      }
      const vd t = Gq * (V * (v - VT));
      agx += t * dx;
      agy += t * dy;
      alap += t;
    }
    asm volatile("" ::: "memory");  // one sweep is not folded into the next
  }
  (void)H;
  return hsum(api + agx + agy + alap);
}

using MixFn = double (*)(const Candidates&, const MixPlan&, long long);
template <int NP, bool PI, int GM>
MixFn pick_nc(int nc) {
  switch (nc) {
    case 2: return &mix_loop<NP, 2, PI, GM>;
    case 3: return &mix_loop<NP, 3, PI, GM>;
    case 4: return &mix_loop<NP, 4, PI, GM>;
    case 5: return &mix_loop<NP, 5, PI, GM>;
    case 6: return &mix_loop<NP, 6, PI, GM>;
    default: return &mix_loop<NP, 8, PI, GM>;
  }
}
template <bool PI, int GM>
MixFn pick_np(int np, int nc) {
  return np == 1 ? pick_nc<1, PI, GM>(nc) : np == 2 ? pick_nc<2, PI, GM>(nc)
                                                    : pick_nc<3, PI, GM>(nc);
}
// As the kernel picks (pick_fused1): with Π and a divide needed, G from the Π value.
MixFn pick_mix(const MixPlan& w, bool pi) {
  if (pi) return w.m > 0 ? pick_np<true, 5>(w.np, w.nc) : pick_np<true, 1>(w.np, w.nc);
  if (w.m > 0) throw gpm::InputError("the Laplacian-only mix needs a weight with w/q^2 polynomial");
  return pick_np<false, 1>(w.np, w.nc);
}

// ---------------------------------------------------------------------------------
// Pure throughput: 8 independent chains so latency is hidden; inputs from L1.
enum class Pure { sqrt, div, sqrt_div, fma };
double pure_loop(const Candidates& c, Pure what, long long sweeps) {
  constexpr int kChains = 8;
  vd acc[kChains];
  for (auto& a : acc) a = vbc(0.0);
  if (what == Pure::fma) {
    // acc = acc·a + b on registers: 8 chains × 4-cycle latency cover 2 FMA pipes.
    vd a = vbc(0.999999), b = vbc(1e-7);
    for (int i = 0; i < kChains; ++i) acc[i] = vbc(1.0 + i);
    for (long long s = 0; s < sweeps; ++s) {
      for (int k = 0; k < kL; k += kW * kChains)
        for (int i = 0; i < kChains; ++i) acc[i] = acc[i] * a + b;
      asm volatile("" : "+v"(a));
    }
  } else {
    const vd one = vbc(1.0);
    for (long long s = 0; s < sweeps; ++s) {
      for (int k = 0; k < kL; k += kW * kChains)
        for (int i = 0; i < kChains; ++i) {
          const vd x = vload(c.V + k + i * kW);
          if (what == Pure::sqrt) acc[i] += vsqrt(x);
          if (what == Pure::div) acc[i] += one / x;
          if (what == Pure::sqrt_div) acc[i] += vsqrt(x) + one / vload(c.v + k + i * kW);
        }
      asm volatile("" ::: "memory");
    }
  }
  vd t = acc[0];
  for (int i = 1; i < kChains; ++i) t += acc[i];
  return hsum(t);
}

// ---------------------------------------------------------------------------------
// Wall time of one run (all threads), and the CPU time of its slowest thread: on a
// machine shared with other jobs the wall time includes the slices others took, the
// thread CPU time does not (it is what the cores would give if they were ours).
struct Result {
  double best = 0, median = 0, cpu_best = 0;
};
double thread_cpu_seconds() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}
Result time_threads(int nt, int repeats, const std::function<double(int)>& run) {
  auto once = [&](double& cpu) {
    double sum = 0, cpu_max = 0;
    const auto a = Clock::now();
#pragma omp parallel num_threads(nt) reduction(+ : sum) reduction(max : cpu_max)
    {
      const double c0 = thread_cpu_seconds();
      sum += run(omp_get_thread_num());
      cpu_max = thread_cpu_seconds() - c0;
    }
    const double t = std::chrono::duration<double>(Clock::now() - a).count();
    g_sink = g_sink + sum;
    cpu = cpu_max;
    return t;
  };
  double cpu = 0;
  once(cpu);  // warm-up: thread start, page faults, clock ramp
  std::vector<double> t;
  Result res;
  res.cpu_best = 1e300;
  for (int r = 0; r < repeats; ++r) {
    t.push_back(once(cpu));
    res.cpu_best = std::min(res.cpu_best, cpu);
  }
  std::sort(t.begin(), t.end());
  res.best = t.front();
  res.median = t[t.size() / 2];
  return res;
}

std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
  return "unknown";
}

int body(int argc, char** argv) {
  gpm::Args args("bench_limit",
                 "Measured limits of this machine for the pair kernel: the kernel's "
                 "arithmetic mix with data in L1, pure sqrt/divide/FMA throughput, memory "
                 "bandwidth (triad, read-only sum).");
  args.opt("threads", "1,2", "comma-separated thread counts")
      .opt("repeats", "5", "timed repetitions per test (best and median reported)")
      .opt("lanes", "4e8", "candidate pairs (vector lanes) per thread per arithmetic run")
      .opt("mib", "512", "memory tests: MiB per thread for the read-only sum (triad: 3 arrays "
                         "of a third of that each)")
      .opt("mixes", "Pi2:PGL,quartic_polynomial:PGL,quartic_polynomial:L",
           "kernel mixes weight:ops (ops PGL = Π+∇+Δ, L = ∇/Δ only)")
      .opt("profile", "bench", "label recorded as the file's profile (the report's rules pass theirs)")
      .output("out", "data/bench/limit.tsv", "TSV output");
  args.parse(argc, argv);
  const auto t_start = Clock::now();
  const long long repeats = args.integer("repeats", 1, 1000000);
  const double lanes = args.positive("lanes");
  const double mib = args.positive("mib");
  std::vector<int> threads;
  for (double t : args.nums("threads")) {
    if (t < 1 || t != std::floor(t)) throw gpm::InputError("--threads: positive integers");
    threads.push_back(static_cast<int>(t));
  }
  const int max_threads = *std::max_element(threads.begin(), threads.end());
  struct Mix {
    std::string name;
    MixPlan plan;
    MixFn fn;
  };
  std::vector<Mix> mixes;
  for (const auto& spec : args.list("mixes")) {
    const auto colon = spec.find(':');
    if (colon == std::string::npos) throw gpm::InputError("--mixes: '" + spec + "' is not weight:ops");
    const std::string wname = spec.substr(0, colon), ops = spec.substr(colon + 1);
    if (ops != "PGL" && ops != "L") throw gpm::InputError("--mixes: ops '" + ops + "' (PGL or L)");
    const MixPlan mp = plan_for(gpm::weight(wname));
    mixes.push_back({"mix:" + spec, mp, pick_mix(mp, ops == "PGL")});
  }

  const long long sweeps = std::max(1LL, static_cast<long long>(lanes / kL));
  std::vector<Candidates> cand;
  for (int t = 0; t < max_threads; ++t) cand.emplace_back(static_cast<uint64_t>(t + 1));

  gpm::TsvTable tab;
  tab.set("program", "bench_limit");
  tab.set("profile", args.str("profile"));
  for (auto& [k, val] : args.values()) tab.set("arg_" + k, val);
  tab.set("cpu", cpu_model());
  tab.set("cpu_family_model", bench::cpu_family_model());
  tab.set("loadavg_1min_start", bench::loadavg());
  tab.set("vector_lanes", static_cast<double>(kW));
  tab.set("note", "arithmetic rates: vector lanes (candidate pairs, or operations) per second, "
                  "all threads; memory: bytes per second counted as STREAM does (triad 24 B/"
                  "element); shared machine, compare within one run");
  gpm::add_provenance(tab);
  tab.columns = {"test", "threads", "rate", "unit", "seconds_best", "seconds_median",
                 "ns_per_lane_thread", "rate_cpu", "description"};
  std::printf("bench_limit: %s, %d double lanes per vector, best of %lld\n", cpu_model().c_str(),
              kW, repeats);
  std::printf("%-28s %3s %11s %-8s %9s %11s %11s\n", "test", "thr", "rate", "unit", "best_s",
              "ns/lane/thr", "rate(cpu)");
  auto report = [&](const std::string& test, int nt, double per_thread_units, const Result& r,
                    const std::string& unit, const std::string& what) {
    const double rate = nt * per_thread_units / r.best;
    const double ns = unit == "B/s" ? NAN : 1e9 * r.best / per_thread_units;
    const double rate_cpu = nt * per_thread_units / r.cpu_best;
    std::printf("%-28s %3d %11.4g %-8s %9.4f %11.4f %11.4g\n", test.c_str(), nt, rate,
                unit.c_str(), r.best, ns, rate_cpu);
    std::fflush(stdout);
    tab.add_row({test, gpm::fmt(nt), gpm::fmt(rate), unit, gpm::fmt(r.best), gpm::fmt(r.median),
                 std::isnan(ns) ? std::string() : gpm::fmt(ns), gpm::fmt(rate_cpu), what});
  };

  // (a) Arithmetic.
  const double lanes_run = static_cast<double>(sweeps) * kL;
  for (const auto& mx : mixes)
    for (int nt : threads) {
      const Result r = time_threads(nt, static_cast<int>(repeats), [&](int tid) {
        return mx.fn(cand[tid], mx.plan, sweeps);
      });
      report(mx.name, nt, lanes_run, r, "pairs/s",
             "kernel's fused one-weight loop, data in L1 (" + std::to_string(mx.plan.np) +
                 " pieces, " + std::to_string(mx.plan.nc) + " coefficients, " +
                 (mx.plan.m > 0 && mx.name.find(":PGL") != std::string::npos ? "sqrt + divide"
                                                                              : "sqrt, no divide") +
                 ")");
    }
  // The studies' multi-weight mixes: the kernel itself on a neighbourhood held in L1 —
  // 512 particles in a disc of radius 0.45h, every one a target and every pair within h —
  // so that what remains is the mix's arithmetic and the kernel's per-target work spread
  // over 512 candidates.  Each thread runs its own one-thread kernel on its own particles.
  for (const auto& sm : bench::study_mixes()) {
      const int n = kL;
      std::vector<std::vector<double>> xs(max_threads), ys(max_threads), f(max_threads * sm.fields);
      std::vector<gpm::FusedKernel> kernels;
      std::vector<gpm::KernelResult> res(max_threads);
      gpm::KernelOptions opt;
      opt.threads = 1;
      for (int t = 0; t < max_threads; ++t) {
        const Candidates c(static_cast<uint64_t>(t + 101));
        for (int k = 0; k < n; ++k) {  // the unit square's points mapped into the disc
          const double r = 0.45 * std::sqrt(0.5 * (c.x[k] + 1)), a = M_PI * (c.y[k] + 1);
          xs[t].push_back(r * std::cos(a));
          ys[t].push_back(r * std::sin(a));
        }
        for (int j = 0; j < sm.fields; ++j) f[t * sm.fields + j].assign(c.v, c.v + n);
        kernels.emplace_back(xs[t], ys[t], std::vector<double>(n, 1.0 / n), 1.0, sm.weights, opt);
      }
      std::vector<int32_t> targets(n);
      for (int k = 0; k < n; ++k) targets[k] = k;
      const double pairs = static_cast<double>(kernels[0].count_pairs(targets).accepted);
      const long long calls = std::max(1LL, static_cast<long long>(lanes / (pairs * sm.weights.size())));
      for (int nt : threads) {
        const Result r = time_threads(nt, static_cast<int>(repeats), [&](int tid) {
          std::vector<const std::vector<double>*> fp;
          for (int j = 0; j < sm.fields; ++j) fp.push_back(&f[tid * sm.fields + j]);
          for (long long c = 0; c < calls; ++c) kernels[tid].apply(targets, fp, res[tid]);
          return 0.0;
        });
        report("kernel_l1:" + sm.name, nt, pairs * static_cast<double>(calls), r, "pairs/s",
               "the fused kernel on 512 particles held in L1 (all pairs within h): " +
                   std::to_string(sm.weights.size()) + " weights, " +
                   std::to_string(sm.fields) + " field(s)");
      }
    }
  const struct {
    const char* name;
    Pure what;
    const char* desc;
  } pures[] = {{"sqrt", Pure::sqrt, "vsqrtpd only, 8 independent chains"},
               {"div", Pure::div, "vdivpd only, 8 independent chains"},
               {"sqrt+div", Pure::sqrt_div, "one vsqrtpd and one vdivpd per lane"},
               {"fma", Pure::fma, "vfmadd only, 8 independent chains in registers"}};
  for (const auto& pu : pures)
    for (int nt : threads) {
      const long long sw = pu.what == Pure::fma ? sweeps * 8 : sweeps;
      const Result r = time_threads(nt, static_cast<int>(repeats), [&](int tid) {
        return pure_loop(cand[tid], pu.what, sw);
      });
      report(pu.name, nt, static_cast<double>(sw) * kL, r, "lanes/s", pu.desc);
    }

  // (b) Memory: per thread its own arrays, first touched by that thread.
  const std::size_t n_sum = static_cast<std::size_t>(mib * 1048576.0 / 8);
  const std::size_t n_tri = n_sum / 3;
  std::vector<std::vector<double>> A(max_threads), B(max_threads), C(max_threads);
#pragma omp parallel num_threads(max_threads)
  {
    const int t = omp_get_thread_num();
    A[t].assign(n_sum, 1.0);
    B[t].assign(n_tri, 2.0);
    C[t].assign(n_tri, 0.5);
  }
  for (int nt : threads) {
    const Result r = time_threads(nt, static_cast<int>(repeats), [&](int tid) {
      double* __restrict a = A[tid].data();
      const double* __restrict b = B[tid].data();
      const double* __restrict c = C[tid].data();
      for (std::size_t i = 0; i < n_tri; ++i) a[i] = b[i] + 0.5 * c[i];
      return a[n_tri / 2];
    });
    report("triad", nt, 24.0 * static_cast<double>(n_tri), r, "B/s",
           "a = b + s*c, 3 arrays of " + gpm::fmt(std::round(8.0 * n_tri / 1048576.0)) +
               " MiB per thread, 24 B per element");
  }
  for (int nt : threads) {
    const Result r = time_threads(nt, static_cast<int>(repeats), [&](int tid) {
      // Four vector accumulators: the adds never limit the stream.
      const double* __restrict a = A[tid].data();
      vd s0 = vbc(0), s1 = s0, s2 = s0, s3 = s0;
      std::size_t i = 0;
      for (; i + 4 * kW <= n_sum; i += 4 * kW) {
        s0 += vload(a + i);
        s1 += vload(a + i + kW);
        s2 += vload(a + i + 2 * kW);
        s3 += vload(a + i + 3 * kW);
      }
      double s = hsum(s0 + s1 + s2 + s3);
      for (; i < n_sum; ++i) s += a[i];
      return s;
    });
    report("read", nt, 8.0 * static_cast<double>(n_sum), r, "B/s",
           "sum of one array of " + gpm::fmt(std::round(8.0 * n_sum / 1048576.0)) + " MiB per thread");
  }
  tab.set("loadavg_1min_end", bench::loadavg());
  tab.set("wall_time_s", std::chrono::duration<double>(Clock::now() - t_start).count());
  const std::string out = args.str("out");
  tab.save(out);
  std::printf("  wrote %s\n", out.c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) { return gpm::run_main("bench_limit", body, argc, argv); }
