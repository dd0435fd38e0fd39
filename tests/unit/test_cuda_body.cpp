// The CUDA kernels' per-target arithmetic (src/cuda/kernel_cuda_body.hpp), run on the CPU
// and compared with gpm::FusedKernel and the matrix-free DiscreteLaplacian.  The body is the
// code the GPU runs (one thread per target), so this checks the neighbour ranges, the piece
// tables, the G modes and the scaling without a GPU; only the CUDA plumbing (uploads,
// launches, device rounding) stays unchecked here.  Built in the default build: it needs no
// CUDA toolchain.
//
// Tolerance.  Both sides sum the same pairs in double; they differ only in the order of the
// sums (the CPU kernel adds in 8-lane vectors and uses pre-divided coefficients), a few
// ulps per pair.  Measured max |difference| / max |column| over seeds 1–5, Δx = 2^-6 and
// 2^-7, h = 0.05 and 0.1, the weights Pi2, quintic_bspline, quartic_polynomial, mps, Lap3,
// Grad1 and cell sizes h and h/4: at most 9.4e-15.  Dropping one row of cells from the
// search (a deliberately broken body) gives at least 7e-5.  So 1e-11 is safe both ways.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "cuda/kernel_cuda_body.hpp"
#include "gpm/error.hpp"
#include "gpm/geometry/cells.hpp"
#include "gpm/geometry/domain.hpp"
#include "gpm/kernel/kernel.hpp"
#include "gpm/operators/fused_errors.hpp"
#include "gpm/operators/testfunctions.hpp"
#include "gpm/studies/define/catalog.hpp"
#include "gpm/studies/define/thesis_tables.hpp"
#include "gpm/solvers/laplacian_matrix.hpp"
#include "gpm/weights/weights.hpp"

using namespace gpm;

namespace {

double max_rel_diff(const std::vector<double>& a, std::span<const double> b) {
  double d = 0, s = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    d = std::max(d, std::abs(a[i] - b[i]));
    s = std::max(s, std::abs(b[i]));
  }
  return s > 0 ? d / s : d;
}

// All four columns of the emulated device kernel at the targets (original indices).
std::vector<std::vector<double>> emulate(const Particles& p, const std::vector<double>& V,
                                         const std::vector<double>& v, const WeightFunction& w,
                                         double h, unsigned ops, int cells_per_h,
                                         const std::vector<int32_t>& targets) {
  const CellList cl(p.x, p.y, h / cells_per_h);
  const std::vector<double> Vs = cl.gather(V), vs = cl.gather(v);
  const cuda::GridView g = cuda::grid_view(cl, Vs.data(), h);
  const cuda::PieceTable wt = cuda::piece_table(w, 0), gt = cuda::piece_table(w, 2);
  const int gm = cuda::g_mode(gt, ops);
  std::vector<std::vector<double>> cols(4, std::vector<double>(targets.size()));
  for (std::size_t i = 0; i < targets.size(); ++i) {
    double o[4];
    cuda::target_sums_any(ops, g, wt, gt, gm, vs.data(), cl.slot()[targets[i]], o);
    for (int c = 0; c < 4; ++c) cols[c][i] = o[c];
  }
  return cols;
}

}  // namespace

TEST_CASE("CUDA body on the CPU equals the fused kernel (Pi, grad, Lap)", "[cuda]") {
  for (uint64_t seed : {1u, 2u, 3u}) {
    const Particles p = jittered_grid(std::pow(2.0, -6), seed);
    const std::vector<double> V(p.size(), Domain{}.area_H() / static_cast<double>(p.size()));
    const auto& f = test_function("sin2pi");
    std::vector<double> v(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) v[i] = f.v(p.x[i], p.y[i]);
    const std::vector<int32_t> targets = omega_targets(p);
    const double h = 0.1;
    // Pi2: Π with G = W·h²/r²; quintic_bspline: 3 pieces; quartic_polynomial: w/q² without
    // a divide; mps (Δ only): a weight singular at 0, G with divides.
    for (const std::string name : {"Pi2", "quintic_bspline", "quartic_polynomial", "mps"}) {
      const unsigned ops = name == "mps" ? cuda::kOpLap : cuda::kOpAll;
      const FusedKernel fk(p, V, h, {{weight(name), ops}});
      const KernelResult ref = fk.apply(targets, std::vector<std::vector<double>>{v});
      for (int k : {1, 4}) {
        INFO("seed " << seed << ", weight " << name << ", cells h/" << k);
        const auto cols = emulate(p, V, v, weight(name), h, ops, k, targets);
        if (ops & cuda::kOpInterp) CHECK(max_rel_diff(cols[0], ref.interpolant(0, 0)) < 1e-11);
        if (ops & cuda::kOpGrad) {
          CHECK(max_rel_diff(cols[1], ref.grad_x(0, 0)) < 1e-11);
          CHECK(max_rel_diff(cols[2], ref.grad_y(0, 0)) < 1e-11);
        }
        CHECK(max_rel_diff(cols[3], ref.laplacian(0, 0)) < 1e-11);
      }
    }
  }
}

TEST_CASE("CUDA body on the CPU: Laplacian with v = 0 outside Omega equals M_OO x", "[cuda]") {
  const Particles p = jittered_grid(std::pow(2.0, -6), 1);
  const std::vector<double> V(p.size(), Domain{}.area_H() / static_cast<double>(p.size()));
  const double h = 0.12;
  const DiscreteLaplacian L(p, V, weight("quartic_polynomial"), h,
                            LaplacianStorage::matrix_free);
  Eigen::VectorXd x(static_cast<Eigen::Index>(L.n_unknowns())), y;
  for (Eigen::Index u = 0; u < x.size(); ++u) x[u] = std::cos(0.37 * static_cast<double>(u));
  L.apply(x, y);
  std::vector<double> full(p.size(), 0.0);
  for (std::size_t u = 0; u < L.n_unknowns(); ++u) full[L.omega()[u]] = x[static_cast<Eigen::Index>(u)];
  const auto cols = emulate(p, V, full, weight("quartic_polynomial"), h, cuda::kOpLap, 1, L.omega());
  CHECK(max_rel_diff(cols[3], std::span<const double>(y.data(), static_cast<std::size_t>(y.size()))) <
        1e-11);
}

TEST_CASE("CUDA piece tables: the divide only where w/q^2 needs it", "[cuda]") {
  CHECK_FALSE(cuda::piece_table(weight("quartic_polynomial"), 2).negative_power);
  CHECK(cuda::piece_table(weight("Pi2"), 2).negative_power);
  CHECK(cuda::piece_table(weight("mps"), 0).negative_power);
  // Every table covers [0, 1) from 0, ascending.
  for (const auto& w : weight_registry()) {
    const cuda::PieceTable t = cuda::piece_table(w, 0);
    REQUIRE(t.np >= 1);
    CHECK(t.begin[0] == 0);
    for (int i = 1; i < t.np; ++i) CHECK(t.begin[i] > t.begin[i - 1]);
    // Values agree with the weight itself away from the pieces' ends.
    for (double q : {0.05, 0.3, 0.55, 0.8, 0.95})
      CHECK(cuda::eval_pieces(t, q) == Approx(w.value(q)).epsilon(1e-12).margin(1e-12));
  }
}

// The studies' own fused passes (issue 15: every paper-profile truncation pass): imoto's nine
// weights on one field and the thesis tables' mixes on their test functions, with uneven
// volumes (the Voronoi volumes of Tables 4.2/4.3 enter the same way), at once through
// fused_target_sums, against gpm::FusedKernel for every requested weight, operator and field.
TEST_CASE("CUDA body on the CPU: the studies' multi-weight passes equal the fused kernel", "[cuda]") {
  struct Mix {
    std::string name;
    std::vector<ErrorRequest> requests;
    std::vector<std::string> functions;
  };
  std::vector<Mix> mixes = {{"imoto9", imoto_study().requests(), {imoto_study().function}}};
  std::vector<std::string> cases;
  for (auto& c : thesis_cases()) cases.push_back(c.function);
  for (auto& t : thesis_table_specs()) mixes.push_back({t.mix(), t.requests, cases});

  const Particles p = jittered_grid(std::pow(2.0, -6), 2);
  std::vector<double> V(p.size());
  for (std::size_t i = 0; i < p.size(); ++i)
    V[i] = std::pow(2.0, -12) * (0.8 + 0.4 * std::fabs(std::sin(7.0 * static_cast<double>(i))));
  const std::vector<int32_t> targets = omega_targets(p);
  const double h = 0.1;
  const CellList cl(p.x, p.y, h / 4);
  const std::vector<double> Vs = cl.gather(V);
  const cuda::GridView g = cuda::grid_view(cl, Vs.data(), h);
  for (const Mix& m : mixes) {
    INFO("mix " << m.name);
    const std::vector<KernelWeight> kw = kernel_weights(m.requests);
    REQUIRE(kw.size() <= static_cast<std::size_t>(cuda::kMaxWeights));
    REQUIRE(m.functions.size() <= static_cast<std::size_t>(cuda::kMaxFieldsDevice));
    std::vector<cuda::WeightEntry> we;
    for (auto& k : kw) we.push_back(cuda::weight_entry(k.weight, k.ops));
    std::vector<std::vector<double>> fields, sorted;
    for (auto& f : m.functions) {
      const TestFunction& tf = test_function(f);
      std::vector<double> v(p.size());
      for (std::size_t i = 0; i < p.size(); ++i) v[i] = tf.v(p.x[i], p.y[i]);
      sorted.push_back(cl.gather(v));
      fields.push_back(std::move(v));
    }
    std::vector<const double*> vp;
    for (auto& s : sorted) vp.push_back(s.data());
    const int nw = static_cast<int>(we.size()), nf = static_cast<int>(vp.size());
    // The emulated device pass: column (w, f, c) at every target.
    std::vector<std::vector<double>> cols(static_cast<std::size_t>(nw * nf * 4),
                                          std::vector<double>(targets.size()));
    std::vector<double> o(static_cast<std::size_t>(nw * nf * 4));
    for (std::size_t t = 0; t < targets.size(); ++t) {
      cuda::fused_target_sums(g, we.data(), nw, vp.data(), nf, cl.slot()[targets[t]], o.data());
      for (std::size_t c = 0; c < o.size(); ++c) cols[c][t] = o[c];
    }
    const FusedKernel fk(p, V, h, kw);
    const KernelResult ref = fk.apply(targets, fields);
    int compared = 0;
    for (int w = 0; w < nw; ++w)
      for (int f = 0; f < nf; ++f) {
        auto col = [&](int c) { return cols[static_cast<std::size_t>((w * nf + f) * 4 + c)]; };
        if (kw[w].ops & kInterp) {
          CHECK(max_rel_diff(col(0), ref.interpolant(w, f)) < 1e-11);
          ++compared;
        }
        if (kw[w].ops & kGrad) {
          CHECK(max_rel_diff(col(1), ref.grad_x(w, f)) < 1e-11);
          CHECK(max_rel_diff(col(2), ref.grad_y(w, f)) < 1e-11);
          ++compared;
        }
        if (kw[w].ops & kLap) {
          CHECK(max_rel_diff(col(3), ref.laplacian(w, f)) < 1e-11);
          ++compared;
        }
      }
    CHECK(compared >= nw * nf);
  }
}

TEST_CASE("CUDA body: operations per pair, counted from the code", "[cuda]") {
  // quartic_polynomial, all operators, one field: distance 7; W = q²·(3 coefficients) by
  // Horner and two multiplies 8; G = w/q² from its own table (3 coefficients, no divide) 6;
  // per field Π 3, t 3, ∇ 4, Δ 1.  A second field adds the per-field 11.
  const auto q = cuda::weight_entry(weight("quartic_polynomial"), cuda::kOpAll);
  REQUIRE(q.gmode == cuda::kGOwnTable);
  CHECK(cuda::body_flops_per_pair({q}, 1) == 32);
  CHECK(cuda::body_flops_per_pair({q}, 2) == 43);
  const auto lap = cuda::weight_entry(weight("quartic_polynomial"), cuda::kOpLap);
  CHECK(cuda::body_flops_per_pair({q, lap}, 1) > cuda::body_flops_per_pair({q}, 1));
}
