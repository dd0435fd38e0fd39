#include "gpm/operators/fused_errors.hpp"

#include <chrono>
#include <cstdio>
#include <cmath>
#include <map>
#include <stdexcept>

#include "gpm/error.hpp"
#include "gpm/kernel/device_pass.hpp"
#include "gpm/kernel/kernel.hpp"
#include "gpm/operators/testfunctions.hpp"
#include "gpm/weights/weights.hpp"

namespace gpm {

namespace {
unsigned op_bit(Operator op) {
  return op == Operator::interp ? kInterp : op == Operator::grad ? kGrad : kLap;
}
}  // namespace

std::vector<KernelWeight> kernel_weights(const std::vector<ErrorRequest>& requests) {
  std::vector<KernelWeight> kw;
  std::map<std::string, int> slot;
  for (auto& r : requests) {
    auto it = slot.find(r.weight);
    if (it == slot.end()) {
      slot[r.weight] = static_cast<int>(kw.size());
      kw.push_back(KernelWeight{weight(r.weight), op_bit(r.op)});
    } else {
      kw[it->second].ops |= op_bit(r.op);
    }
  }
  return kw;
}

ErrorMaxima fused_error_maxima(const Particles& p, const std::vector<double>& V, double h,
                               const std::vector<ErrorRequest>& requests,
                               const std::vector<std::string>& functions, bool count_pairs,
                               TargetShare share) {
  if (share.parts < 1 || share.part < 0 || share.part >= share.parts)
    throw InputError("target share " + std::to_string(share.part) + " of " +
                     std::to_string(share.parts) + " does not exist");
  if (functions.empty() || functions.size() > FusedKernel::kMaxFields)
    throw InputError("between 1 and " + std::to_string(FusedKernel::kMaxFields) +
                     " test functions per pass, got " + std::to_string(functions.size()));
  const std::vector<KernelWeight> kw = kernel_weights(requests);
  std::map<std::string, int> slot;  // registry name → its kernel weight
  for (std::size_t i = 0; i < kw.size(); ++i) slot[kw[i].weight.name] = static_cast<int>(i);
  std::vector<const TestFunction*> tf;
  std::vector<std::vector<double>> fields;
  for (auto& name : functions) {
    tf.push_back(&test_function(name));
    std::vector<double> v(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) v[i] = tf.back()->v(p.x[i], p.y[i]);
    fields.push_back(std::move(v));
  }
  const auto all_targets = omega_targets(p);
  if (all_targets.empty()) throw InputError("no particle lies inside Omega");
  const std::size_t nt = all_targets.size();
  const auto cut = [&](int part) { return nt * static_cast<std::size_t>(part) / static_cast<std::size_t>(share.parts); };
  const std::vector<int32_t> targets(all_targets.begin() + static_cast<std::ptrdiff_t>(cut(share.part)),
                                     all_targets.begin() + static_cast<std::ptrdiff_t>(cut(share.part + 1)));

  FusedKernel kernel(p, V, h, kw);
  ErrorMaxima out;
  if (count_pairs && !targets.empty())
    out.pairs = static_cast<double>(kernel.count_pairs(targets).accepted);

  // Running maxima of |error| and |exact| per (request, function).
  const std::size_t nrf = requests.size() * tf.size();
  std::vector<double>& err = out.error;
  std::vector<double>& ref = out.exact;
  std::vector<int32_t>& worst = out.worst;
  err.assign(nrf, 0), ref.assign(nrf, 0), worst.assign(nrf, -1);
  if (targets.empty()) return out;
  // col(w, f, c): the operator c (0 Π, 1 ∂x ∇, 2 ∂y ∇, 3 Δ) of weight w, field f at the
  // chunk's targets, from the CPU kernel's result or the device's columns.
  auto accumulate = [&](const std::vector<int32_t>& tg, auto col) {
    for (std::size_t ri = 0; ri < requests.size(); ++ri) {
      const auto& r = requests[ri];
      const int w = slot.at(r.weight);
      for (std::size_t f = 0; f < tf.size(); ++f) {
        const int fi = static_cast<int>(f);
        const double* pi = col(w, fi, 0);
        const double* gx = col(w, fi, 1);
        const double* gy = col(w, fi, 2);
        const double* lap = col(w, fi, 3);
        double& em = err[ri * tf.size() + f];
        int32_t& where = worst[ri * tf.size() + f];
        double& qm = ref[ri * tf.size() + f];
        for (std::size_t k = 0; k < tg.size(); ++k) {
          const int32_t i = tg[k];
          const double x = p.x[i], y = p.y[i];
          double e = 0, q = 0;
          switch (r.op) {
            case Operator::interp:
              e = std::fabs(tf[f]->v(x, y) - pi[k]);
              q = std::fabs(tf[f]->v(x, y));
              break;
            case Operator::grad:
              // Euclidean length of the error vector (imoto §1: |x| is the Euclidean
              // norm on R^d; thesis (1.27) [C]^d and [ℓ∞(Ω)]² inherit it).
              e = std::hypot(tf[f]->vx(x, y) - gx[k], tf[f]->vy(x, y) - gy[k]);
              q = std::hypot(tf[f]->vx(x, y), tf[f]->vy(x, y));
              break;
            case Operator::lap:
              e = std::fabs(tf[f]->lap(x, y) - lap[k]);
              q = std::fabs(tf[f]->lap(x, y));
              break;
          }
          if (!std::isfinite(e))
            throw NumericalError("non-finite " + operator_name(r.op) + " with weight " +
                                 r.weight + " at particle " + std::to_string(i));
          if (e > em || where < 0) em = std::max(em, e), where = i;
          qm = std::max(qm, q);
        }
      }
    }
  };

  // One kernel call for the usual sizes.  Above kChunkTargets targets (Δx ≤ 2^-11) the pass
  // can run for most of an hour, so the targets go through the kernel in chunks with a
  // progress line at most every 30 s; the maxima are combined across chunks, so the
  // errors are exactly those of one call.
  constexpr std::size_t kChunkTargets = 2'000'000, kChunks = 64;
  const auto t0 = std::chrono::steady_clock::now();
  double kernel_s = 0;  // the kernel calls alone, not the error maxima
  auto since = [](std::chrono::steady_clock::time_point a) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - a).count();
  };
  // The operators of a chunk of targets: the CPU kernel, or the installed device
  // (device_pass.hpp) when this process uses one.
  std::unique_ptr<DevicePass> device;
  if (using_device()) device = make_device_pass(p, V, h, kw);
  KernelResult res;
  DeviceColumns dc;
  std::vector<const std::vector<double>*> fp;
  for (auto& v : fields) fp.push_back(&v);
  auto evaluate = [&](const std::vector<int32_t>& tg) {
    const auto tk = std::chrono::steady_clock::now();
    if (device) {
      dc = device->apply(tg, fields);
      kernel_s += since(tk);
      accumulate(tg, [&](int w, int f, int c) { return dc.column(w, f, c); });
      return;
    }
    kernel.apply(tg, fp, res);
    kernel_s += since(tk);
    accumulate(tg, [&](int w, int f, int c) -> const double* {
      static constexpr KernelOp kOpOf[4] = {kInterp, kGrad, kGrad, kLap};
      if (!res.has(w, kOpOf[c])) return nullptr;  // not requested: never read
      switch (c) {
        case 0: return res.interpolant(w, f).data();
        case 1: return res.grad_x(w, f).data();
        case 2: return res.grad_y(w, f).data();
        default: return res.laplacian(w, f).data();
      }
    });
  };
  if (targets.size() <= kChunkTargets) {
    evaluate(targets);
  } else {
    const std::size_t per = (targets.size() + kChunks - 1) / kChunks;
    auto last = t0;
    for (std::size_t b = 0; b < targets.size(); b += per) {
      const std::vector<int32_t> tg(targets.begin() + b,
                                    targets.begin() + std::min(targets.size(), b + per));
      evaluate(tg);
      const auto now = std::chrono::steady_clock::now();
      if (std::chrono::duration<double>(now - last).count() >= 30) {
        const double done = static_cast<double>(b + tg.size()) / static_cast<double>(targets.size());
        const double el = std::chrono::duration<double>(now - t0).count();
        std::fprintf(stderr, "[fused pass] %5.1f%% of %zu targets, h = %.4g, %.0f s, ETA %.0f s\n",
                     100 * done, targets.size(), h, el, el * (1 - done) / done);
        last = now;
      }
    }
  }
  out.kernel_seconds = kernel_s;
  return out;
}

void ErrorMaxima::merge_following(const ErrorMaxima& later) {
  if (later.error.size() != error.size())
    throw std::logic_error("ErrorMaxima::merge_following: passes of different requests");
  for (std::size_t i = 0; i < error.size(); ++i) {
    if (later.worst[i] >= 0 && (worst[i] < 0 || later.error[i] > error[i]))
      error[i] = later.error[i], worst[i] = later.worst[i];
    exact[i] = std::max(exact[i], later.exact[i]);
  }
  pairs += later.pairs;
}

FusedErrors relative_errors(const ErrorMaxima& m, const std::vector<ErrorRequest>& requests,
                            const std::vector<std::string>& functions) {
  FusedErrors out;
  out.pairs = m.pairs;
  out.kernel_seconds = m.kernel_seconds;
  const std::size_t nf = functions.size();
  for (std::size_t ri = 0; ri < requests.size(); ++ri) {
    const auto& r = requests[ri];
    for (std::size_t f = 0; f < nf; ++f) {
      const double q = m.exact[ri * nf + f];
      if (!(q > 0))
        throw InputError("the exact " + operator_name(r.op) + " of '" + functions[f] +
                         "' vanishes on Omega: relative error undefined");
      out.errors.push_back({r.weight, functions[f], r.op, m.error[ri * nf + f] / q,
                            m.worst[ri * nf + f]});
    }
  }
  return out;
}

FusedErrors fused_errors(const Particles& p, const std::vector<double>& V, double h,
                         const std::vector<ErrorRequest>& requests,
                         const std::vector<std::string>& functions, bool count_pairs) {
  return relative_errors(fused_error_maxima(p, V, h, requests, functions, count_pairs),
                         requests, functions);
}

}  // namespace gpm
