// The fused kernel's driver (FusedKernel, KernelResult; definitions and design in
// kernel.hpp): building the weights' plans, ordering the targets by cell, the parallel loop
// over targets with its fixed-order reduction, and the pair count.  The loops it runs are in
// the private headers: kernel_pass.hpp (the block path and the kernel's state),
// kernel_fused1.hpp (one weight, one field), kernel_compact.hpp (compact mode),
// kernel_blocks.hpp (the per-weight loops over a block), kernel_dispatch.hpp (which
// instantiation serves a weight or a pass) and kernel_poly.hpp (the weights as plain
// coefficients).
#include "gpm/kernel/kernel.hpp"

#include <omp.h>

#include <algorithm>
#include <sstream>
#include <utility>

#include "gpm/error.hpp"
#include "gpm/kernel/kernel_compact.hpp"
#include "gpm/kernel/kernel_dispatch.hpp"
#include "gpm/kernel/kernel_fused1.hpp"
#include "gpm/kernel/kernel_pass.hpp"
#include "gpm/kernel/simd.hpp"

namespace gpm {

// The built kernel: its state and loops are KernelPass (kernel_pass.hpp), which lives in the
// private headers' anonymous namespace (see there why).
struct FusedKernel::Impl : KernelPass {};

// ---------------------------------------------------------------------------------

FusedKernel::FusedKernel(const std::vector<double>& x, const std::vector<double>& y,
                         const std::vector<double>& V, double h,
                         std::vector<KernelWeight> weights, KernelOptions opt)
    : impl_(new Impl) {
  try {
    require_positive(h, "influence radius h");
    if (V.size() != x.size()) throw InputError("fused kernel: V and x differ in length");
    if (opt.cells_per_h < 1) throw InputError("fused kernel: cells_per_h must be >= 1");
    if (opt.chunk < 1) opt.chunk = 1;
    impl_->h = h;
    impl_->h2 = h * h;
    impl_->invh = 1.0 / h;
    impl_->opt = opt;
    impl_->cl = CellList(x, y, h / opt.cells_per_h);
    impl_->Vs = impl_->cl.gather(V, 0.0);
    for (const auto& kw : weights) {
      WPlan p;
      p.ops = kw.ops & kAllOps;
      if (p.ops & kInterp) {
        p.pi = build_eval(kw.weight, 0, "interpolant");
        if (p.pi.m > 0)
          throw InputError("weight '" + kw.weight.name +
                           "' is unbounded at r = 0: no interpolant with it");
      }
      if (p.ops & (kGrad | kLap)) {
        p.g = build_eval(kw.weight, 2, "w/r^2");
        if (p.g.m > 3)
          throw InputError("weight '" + kw.weight.name + "': w/r^2 more singular than r^-3");
        p.g1 = pick(false, p.g, p.ops, 1);
        p.g2 = pick(false, p.g, p.ops, 2);
      }
      if (p.ops & kInterp) {
        p.pi1 = pick(true, p.pi, p.ops, 1);
        p.pi2 = pick(true, p.pi, p.ops, 2);
      }
      // Π and ∇/Δ of the same weight with a divide anyway: G = W·(h/r)².  (The
      // breakpoints of w and w/q² are the same pieces.)
      if ((p.ops & kInterp) && (p.ops & (kGrad | kLap)) && p.g.m > 0 && p.pi.np == p.g.np) {
        p.pg1 = pick_pg(p.pi, p.ops, 1);
        p.pg2 = pick_pg(p.pi, p.ops, 2);
      }
      // The powers of h/r the shared stage must provide.
      if (p.pg1) impl_->need_pow[2] = true;
      else if ((p.ops & (kGrad | kLap)) && p.g.m > 0) impl_->need_pow[p.g.m] = true;
      impl_->need_iq = impl_->need_iq || p.pg1 || ((p.ops & (kGrad | kLap)) && p.g.m > 0);
      impl_->plans.push_back(p);
    }
  } catch (...) {
    delete impl_;
    throw;
  }
}

FusedKernel::FusedKernel(const Particles& p, const std::vector<double>& V, double h,
                         std::vector<KernelWeight> weights, KernelOptions opt)
    : FusedKernel(p.x, p.y, V, h, std::move(weights), opt) {}

FusedKernel::~FusedKernel() { delete impl_; }
FusedKernel::FusedKernel(FusedKernel&& o) noexcept : impl_(o.impl_) { o.impl_ = nullptr; }
FusedKernel& FusedKernel::operator=(FusedKernel&& o) noexcept {
  std::swap(impl_, o.impl_);
  return *this;
}

double FusedKernel::h() const { return impl_->h; }
const CellList& FusedKernel::cells() const { return impl_->cl; }
std::size_t FusedKernel::n_weights() const { return impl_->plans.size(); }
const KernelOptions& FusedKernel::options() const { return impl_->opt; }
bool FusedKernel::needs_divide() const { return impl_->need_iq; }

KernelResult FusedKernel::apply(const std::vector<int32_t>& targets,
                                const std::vector<std::vector<double>>& fields) const {
  std::vector<const std::vector<double>*> ptr;
  for (const auto& f : fields) ptr.push_back(&f);
  return apply(targets, ptr);
}

namespace {
// Target positions ordered by their slot in the cell list (cell order: locality).
// Counting sort: O(N + targets), stable for repeated targets.
std::vector<int32_t> order_by_slot(const CellList& cl, const std::vector<int32_t>& targets) {
  const std::size_t n = cl.size();
  for (auto t : targets)
    if (t < 0 || static_cast<std::size_t>(t) >= n) {
      std::ostringstream s;
      s << "fused kernel: target index " << t << " is not a particle (N = " << n << ")";
      throw InputError(s.str());
    }
  std::vector<int32_t> first(n + 1, 0);
  for (auto t : targets) ++first[cl.slot()[t] + 1];
  for (std::size_t k = 1; k <= n; ++k) first[k] += first[k - 1];
  std::vector<int32_t> order(targets.size());
  for (std::size_t i = 0; i < targets.size(); ++i)
    order[first[cl.slot()[targets[i]]]++] = static_cast<int32_t>(i);
  return order;
}

int thread_count(int requested) { return requested > 0 ? requested : omp_get_max_threads(); }
}  // namespace

KernelResult FusedKernel::apply(const std::vector<int32_t>& targets,
                                const std::vector<const std::vector<double>*>& fields) const {
  KernelResult res;
  apply(targets, fields, res);
  return res;
}

void FusedKernel::apply(const std::vector<int32_t>& targets,
                        const std::vector<const std::vector<double>*>& fields,
                        KernelResult& res) const {
  const Impl& I = *impl_;
  const int nf = static_cast<int>(fields.size());
  if (nf > kMaxFields) throw InputError("fused kernel: more than 8 fields in one pass");
  const std::size_t n = I.cl.size(), stride = n + CellList::kPad;
  for (const auto* f : fields)
    if (f == nullptr || f->size() != n)
      throw InputError("fused kernel: a field's size differs from the number of particles");

  // Reuse the result's storage when called again with the same targets (time loops).
  const int nw = static_cast<int>(I.plans.size());
  if (res.targets_ != targets || res.order_.size() != targets.size()) {
    res.order_ = order_by_slot(I.cl, targets);
    res.targets_ = targets;
  }
  res.nw_ = nw;
  res.nf_ = nf;
  res.column_.assign(static_cast<std::size_t>(nw) * nf * 4, -1);
  int ncol = 0;
  for (int w = 0; w < nw; ++w)
    for (int f = 0; f < nf; ++f)
      for (int c = 0; c < 4; ++c) {
        const unsigned op = c == 0 ? kInterp : c == 3 ? kLap : kGrad;
        if (I.plans[w].ops & op) res.column_[(w * nf + f) * 4 + c] = ncol++;
      }
  const std::size_t nt = targets.size();
  res.data_.resize(static_cast<std::size_t>(ncol) * nt);  // every entry is written below
  if (nt == 0 || nf == 0 || nw == 0) return;
  // The fields in sorted order (padded with 0), gathered inside the parallel region.
  if (res.work_.size() != nf * stride) res.work_.assign(nf * stride, 0.0);
  const double* fs[kMaxFields] = {};
  for (int f = 0; f < nf; ++f) fs[f] = res.work_.data() + f * stride;

  const int32_t* order = res.order_.data();
  const double h4 = I.h2 * I.h2;
  const double scale[4] = {1.0 / I.h2, kD / h4, kD / h4, 2.0 * kD / h4};
  const std::size_t nacc = static_cast<std::size_t>(nw) * nf * 4;
  double* out = res.data_.data();
  double* work = res.work_.data();
  const int32_t* colmap = res.column_.data();
  const int32_t* index = I.cl.index().data();
  const Impl::RangeFn fused1 = I.opt.compact ? nullptr : pick_fused1(I, nf);
  const Impl::RangeFn range = fused1 ? fused1 : pick_range(I, nf);

#pragma omp parallel num_threads(thread_count(I.opt.threads))
  {
    for (int f = 0; f < nf; ++f) {
      const double* src = fields[f]->data();
      double* dst = work + f * stride;
#pragma omp for schedule(static)
      for (std::size_t k = 0; k < n; ++k) dst[k] = src[index[k]];
    }
    Impl::Thread th(nacc, nf);
    vd vt[kMaxFields];
#pragma omp for schedule(dynamic, I.opt.chunk)
    for (std::size_t it = 0; it < nt; ++it) {
      const int32_t pos = order[it];
      const int32_t slot = I.cl.slot()[targets[pos]];
      const double px = I.cl.xs()[slot], py = I.cl.ys()[slot];
      for (int f = 0; f < nf; ++f) vt[f] = vbc(fs[f][slot]);
      std::fill(th.acc.begin(), th.acc.end(), vbc(0.0));
      th.nvec = 0;
      th.scnt = 0;
      if (I.opt.compact) {
        I.cl.for_each_range(px, py, I.h, [&](int32_t b, int32_t e) {
          I.compact_range(th, b, e, px, py, fs, vt);
        });
        I.drain(th, vt, true);
      } else {
        I.cl.for_each_range(px, py, I.h, [&](int32_t b, int32_t e) {
          (I.*range)(th, b, e, px, py, fs, vt);
        });
      }
      I.run_block(th);
      // Fixed-order lane reduction: bitwise the same for any thread count.
      for (std::size_t a = 0; a < nacc; ++a) {
        const int32_t col = colmap[a];
        if (col < 0) continue;
        double s = 0;
        for (int l = 0; l < kW; ++l) s += th.acc[a][l];
        out[static_cast<std::size_t>(col) * nt + pos] = s * scale[a % 4];
      }
    }
  }
}

PairCount FusedKernel::count_pairs(const std::vector<int32_t>& targets) const {
  const Impl& I = *impl_;
  const std::vector<int32_t> order = order_by_slot(I.cl, targets);
  int64_t cand = 0, acc = 0;
  const double* xs = I.cl.xs();
  const double* ys = I.cl.ys();
  const std::size_t nt = targets.size();
#pragma omp parallel for schedule(dynamic, 64) reduction(+ : cand, acc) \
    num_threads(thread_count(I.opt.threads))
  for (std::size_t it = 0; it < nt; ++it) {
    const int32_t slot = I.cl.slot()[targets[order[it]]];
    const double px = xs[slot], py = ys[slot];
    I.cl.for_each_range(px, py, I.h, [&](int32_t b, int32_t e) {
      cand += e - b;
      for (int32_t k = b; k < e; ++k) acc += dist2(xs[k] - px, ys[k] - py) < I.h2;
    });
  }
  return {cand, acc};
}

// ---------------------------------------------------------------------------------

bool KernelResult::has(int w, KernelOp op) const {
  if (w < 0 || w >= nw_ || nf_ == 0) return false;
  const int c = op == kInterp ? 0 : op == kGrad ? 1 : op == kLap ? 3 : -1;
  return c >= 0 && column_[(w * nf_) * 4 + c] >= 0;
}

std::span<const double> KernelResult::col(int w, int f, int comp) const {
  if (w < 0 || w >= nw_ || f < 0 || f >= nf_) {
    std::ostringstream s;
    s << "kernel result: no weight " << w << " / field " << f;
    throw InputError(s.str());
  }
  const int32_t c = column_[(w * nf_ + f) * 4 + comp];
  if (c < 0) {
    static const char* names[4] = {"interpolant", "gradient", "gradient", "Laplacian"};
    std::ostringstream s;
    s << "kernel result: the " << names[comp] << " was not requested for weight " << w;
    throw InputError(s.str());
  }
  return {data_.data() + static_cast<std::size_t>(c) * targets_.size(), targets_.size()};
}

std::vector<int32_t> omega_targets(const Particles& p) {
  std::vector<int32_t> t;
  t.reserve(p.count_in_omega());
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.in_omega[i]) t.push_back(static_cast<int32_t>(i));
  return t;
}

}  // namespace gpm
