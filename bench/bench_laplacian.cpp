// bench_laplacian: one application of the discrete Laplacian of the Poisson and heat
// solvers (DiscreteLaplacian::apply, y = M_ΩΩ x), assembled against matrix-free, each
// against the bound that applies to it (issue 7, item 2).
//
//  * assembled: the symmetric half of the matrix (laplacian_matrix.hpp), 12 bytes per stored
//    entry (value + column index) streamed once per product, so its bound is the storage's
//    bytes / (read bandwidth); the vectors are reused from cache and not counted.
//  * full: the whole Ω × all matrix in CSR (the storage before the half), the same bound
//    with its own bytes (about twice the half's).
//  * matrix-free: the fused kernel with Δ only, so its bound is the candidate pairs the
//    kernel visits / (rate of the kernel's arithmetic mix for this weight, Δ only).
// Both bounds come from bench_limit's file (--limit), with the same thread count.
// --block s1,s2,…: the assembled forms also apply M to blocks of s vectors at once
// (DiscreteLaplacian::apply_block, one pass over the storage for all s); per_vector_s is the
// product's time / s.  Matrix-free has no shared pass (column by column): block 1 only.
// Setting as in the thesis' Poisson/heat studies: jittered grid, uniform volumes, the
// printed h = (2.6⁴·2^-10·Δx)^{1/4} and the quartic polynomial weight.
// Times: best of --repeats after a warm-up; the machine is shared (see also the
// CPU-time columns: process CPU seconds / threads).
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <functional>
#include <string>
#include <vector>

#include "gpm/error.hpp"
#include "gpm/geometry/domain.hpp"
#include "gpm/geometry/influence_radius.hpp"
#include "gpm/io/args.hpp"
#include "gpm/io/tsv.hpp"
#include "gpm/kernel/kernel.hpp"
#include "gpm/solvers/laplacian_matrix.hpp"
#include "gpm/studies/define/profile.hpp"
#include "gpm/weights/weights.hpp"
#include "limit_table.hpp"

namespace {

using Clock = std::chrono::steady_clock;

double process_cpu_seconds() {
  timespec ts;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}
double since(Clock::time_point a) {
  return std::chrono::duration<double>(Clock::now() - a).count();
}

struct Timing {
  double best = 0, cpu_best = 0;
};
Timing time_it(int repeats, const std::function<void()>& f) {
  f();  // warm-up
  Timing t{1e300, 1e300};
  for (int r = 0; r < repeats; ++r) {
    const double c0 = process_cpu_seconds();
    const auto a = Clock::now();
    f();
    t.best = std::min(t.best, since(a));
    t.cpu_best = std::min(t.cpu_best, process_cpu_seconds() - c0);
  }
  return t;
}

int body(int argc, char** argv) {
  gpm::Args args("bench_laplacian",
                 "Time of one Poisson/heat operator application y = M x, assembled (SpMV) "
                 "against matrix-free (fused kernel), each against its measured bound.");
  args.opt("dx", "2^-6,2^-7,2^-8", "particle spacings")
      .opt("weight", "quartic_polynomial", "weight (w/q^2 must be a polynomial: no divide)")
      .opt("seed", "1", "jitter seed")
      .opt("threads", "1,2", "comma-separated thread counts")
      .opt("block", "1", "comma-separated block widths s (vectors per product, assembled forms)")
      .opt("repeats", "5", "timed products per measurement (best reported)")
      .opt("max-gb", "6", "largest assembled matrix to build (GB); larger: matrix-free only")
      .opt("limit", "data/bench/limit.tsv", "bench_limit's output (the bounds)")
      .opt("profile", "bench", "label recorded as the file's profile (the report's rules pass theirs)")
      .output("out", "data/bench/laplacian.tsv", "TSV output");
  args.parse(argc, argv);
  const auto t_start = Clock::now();
  const std::vector<double> dxs = args.nums("dx");
  for (double dx : dxs)
    if (!(dx > 0) || dx > 0.25) throw gpm::InputError("--dx: values in (0, 1/4], got " + gpm::fmt(dx));
  const long long repeats = args.integer("repeats", 1, 1000000);
  const uint64_t seed = args.seed();
  std::vector<int> threads;
  for (double t : args.nums("threads")) {
    if (t < 1 || t != std::floor(t)) throw gpm::InputError("--threads: positive integers");
    threads.push_back(static_cast<int>(t));
  }
  std::vector<int> blocks;
  for (double s : args.nums("block")) {
    if (s < 1 || s > 64 || s != std::floor(s))
      throw gpm::InputError("--block: integers in [1, 64]");
    blocks.push_back(static_cast<int>(s));
  }
  const gpm::WeightFunction& w = gpm::weight(args.str("weight"));
  const double max_bytes = 1e9 * args.positive("max-gb");
  const bench::LimitTable limits(args.str("limit"));
  if (!limits.loaded())
    std::printf("  (no limit file '%s': run bench_limit first for the bounds)\n",
                args.str("limit").c_str());
  const std::string mix = "mix:" + w.name + ":L";

  gpm::TsvTable t;
  t.set("program", "bench_laplacian");
  t.set("profile", args.str("profile"));
  for (auto& [k, val] : args.values()) t.set("arg_" + k, val);
  t.set("h_rule", "(2.6^4 * 2^-10 * dx)^(1/4)");
  t.set("bound_assembled", "bytes of the assembled storage / read bandwidth (bench_limit 'read', same threads)");
  t.set("bound_matrix_free", "candidate pairs / rate of bench_limit '" + mix + "' (same threads)");
  t.set("cpu_family_model", bench::cpu_family_model());
  t.set("loadavg_1min_start", bench::loadavg());
  gpm::add_provenance(t);
  t.columns = {"dx", "h", "n_particles", "n_unknowns", "nnz", "matrix_gb", "candidates",
               "storage", "threads", "block", "setup_s", "seconds", "per_vector_s",
               "seconds_cpu", "bound_s", "fraction_of_bound", "bound_s_cpu", "fraction_of_bound_cpu", "winner", "winner_cpu", "check_max_rel_diff"};
  std::printf("%-7s %7s %9s %-11s %3s %5s %8s %9s %10s %9s %6s %6s %s\n", "dx", "h", "nnz",
              "storage", "thr", "block", "setup_s", "product_s", "per_vector", "bound_s", "frac",
              "f_cpu", "winner");

  // One loop over the resolutions: build both forms, time products per thread count.
  for (double dx : dxs) {
    const double h = gpm::pde_h(gpm::HRule::h10, dx);
    const gpm::Particles p = gpm::jittered_grid(dx, seed);
    const std::vector<double> V(p.size(), gpm::Domain{}.area_H() / static_cast<double>(p.size()));

    // The matrix-free form first (cheap), and its candidate count (the kernel's lanes).
    auto a0 = Clock::now();
    const gpm::DiscreteLaplacian free(p, V, w, h, gpm::LaplacianStorage::matrix_free);
    const double setup_free = since(a0);
    const gpm::FusedKernel counter(p, V, h, {gpm::KernelWeight{w, gpm::kLap}});
    const gpm::PairCount pc = counter.count_pairs(free.omega());
    const double nnz_est = free.nnz_estimate();

    // The assembled forms where they fit the budget: the symmetric half (the solvers'
    // storage) and the full Ω × all matrix (the storage before it).
    struct Assembled {
      std::string name;
      std::unique_ptr<gpm::DiscreteLaplacian> L;
      double setup = 0;
    };
    std::vector<Assembled> forms;
    for (auto [name, storage, per_nnz] :
         {std::tuple{"assembled", gpm::LaplacianStorage::assembled, gpm::kAssembledBytesPerNonzero},
          std::tuple{"full", gpm::LaplacianStorage::full, 12.0}}) {
      if (per_nnz * nnz_est > max_bytes) continue;
      a0 = Clock::now();
      auto L = std::make_unique<gpm::DiscreteLaplacian>(p, V, w, h, storage, max_bytes);
      forms.push_back({name, std::move(L), since(a0)});
    }
    const double nnz = forms.empty() ? nnz_est : static_cast<double>(forms[0].L->nnz());

    Eigen::VectorXd x(static_cast<Eigen::Index>(free.n_unknowns())), y;
    for (Eigen::Index k = 0; k < x.size(); ++k) x[k] = std::sin(0.001 * static_cast<double>(k));
    // The block: s shifted copies of x (distinct columns, the same pattern of values).
    auto block_of = [&](int s) {
      gpm::DiscreteLaplacian::RowBlock X(x.size(), s);
      for (int c = 0; c < s; ++c) X.col(c) = x.array() + 0.1 * c;
      return X;
    };
    // Every form must compute the same product (up to the summation order).
    double check = NAN;
    {
      Eigen::VectorXd yf, ya;
      free.apply(x, yf);
      for (auto& f : forms) {
        f.L->apply(x, ya);
        const double d = (ya - yf).lpNorm<Eigen::Infinity>() / yf.lpNorm<Eigen::Infinity>();
        check = std::isfinite(check) ? std::max(check, d) : d;
        if (!(d < 1e-10))
          throw gpm::NumericalError(f.name + " and matrix-free products differ at dx = " +
                                    gpm::fmt(dx) + ": max relative difference " + gpm::fmt(d));
        // The widest block's columns must be the single products, bit for bit.
        const int widest = *std::max_element(blocks.begin(), blocks.end());
        const gpm::DiscreteLaplacian::RowBlock X = block_of(widest);
        gpm::DiscreteLaplacian::RowBlock Y;
        f.L->apply_block(X, Y);
        for (Eigen::Index c = 0; c < X.cols(); ++c) {
          f.L->apply(X.col(c), ya);
          if (!(Y.col(c).array() == ya.array()).all())
            throw gpm::NumericalError(f.name + ": block product column " + std::to_string(c) +
                                      " differs from the single product at dx = " + gpm::fmt(dx));
        }
      }
    }

    for (int nt : threads) {
      omp_set_num_threads(nt);
      struct Row {
        std::string storage;
        int block;
        double setup, sec, cpu, bound, bound_cpu, bytes;
        double per_vector() const { return sec / block; }
        double per_vector_cpu() const { return cpu / block; }
      };
      std::vector<Row> rows;
      {
        const Timing tm = time_it(static_cast<int>(repeats), [&] { free.apply(x, y); });
        const bench::Limit lim = limits.get(mix, nt);
        rows.push_back({"matrix_free", 1, setup_free, tm.best, tm.cpu_best / nt,
                        static_cast<double>(pc.candidates) / lim.rate,
                        static_cast<double>(pc.candidates) / lim.rate_cpu, 0.0});
      }
      // The storage is streamed once per product, whatever the block: the same bound.
      for (auto& f : forms)
        for (int s : blocks) {
          const gpm::DiscreteLaplacian::RowBlock X = block_of(s);
          gpm::DiscreteLaplacian::RowBlock Y;
          const Timing tm =
              time_it(static_cast<int>(repeats), [&] {
                if (s == 1) f.L->apply(x, y);
                else f.L->apply_block(X, Y);
              });
          const bench::Limit lim = limits.get("read", nt);
          const double bytes = f.L->bytes();
          rows.push_back({f.name, s, f.setup, tm.best, tm.cpu_best / nt, bytes / lim.rate,
                          bytes / lim.rate_cpu, bytes});
        }
      auto fastest = [&](auto key) {
        return std::min_element(rows.begin(), rows.end(),
                                [&](const Row& a, const Row& b) { return key(a) < key(b); })
            ->storage;
      };
      const std::string winner = fastest([](const Row& r) { return r.per_vector(); });
      const std::string winner_cpu = fastest([](const Row& r) { return r.per_vector_cpu(); });
      for (const auto& r : rows) {
        auto opt_fmt = [](double v) { return std::isfinite(v) ? gpm::fmt(v) : std::string(); };
        std::printf("%-7.4g %7.4f %9.3g %-11s %3d %5d %8.2f %9.4f %10.5f %9.4f %6.3f %6.3f %s\n",
                    dx, h, nnz, r.storage.c_str(), nt, r.block, r.setup, r.sec, r.per_vector(),
                    r.bound, r.bound / r.sec, r.bound_cpu / r.cpu,
                    r.storage == winner ? "<- faster" : "");
        std::fflush(stdout);
        t.add_row({gpm::fmt(dx), gpm::fmt(h), gpm::fmt(p.size()), gpm::fmt(free.n_unknowns()),
                   gpm::fmt(nnz), gpm::fmt(r.bytes / 1e9),
                   gpm::fmt(static_cast<long long>(pc.candidates)), r.storage, gpm::fmt(nt),
                   gpm::fmt(r.block), gpm::fmt(r.setup), gpm::fmt(r.sec), gpm::fmt(r.per_vector()),
                   gpm::fmt(r.cpu), opt_fmt(r.bound),
                   opt_fmt(r.bound / r.sec), opt_fmt(r.bound_cpu),
                   opt_fmt(r.bound_cpu / r.cpu), winner, winner_cpu, opt_fmt(check)});
      }
    }
    t.set("peak_rss_mib", gpm::peak_rss_mib());
    t.set("loadavg_1min_end", bench::loadavg());
    t.set("wall_time_s", since(t_start));
    t.save(args.str("out"));  // after each level: a partial run leaves what it measured
  }
  std::printf("  wrote %s\n", args.str("out").c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) { return gpm::run_main("bench_laplacian", body, argc, argv); }
