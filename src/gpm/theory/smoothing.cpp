#include "gpm/theory/smoothing.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_sf_bessel.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>

#include "gpm/error.hpp"

namespace gpm {

namespace {
struct Params {
  const PolyPiece* piece;
  double kh;
};
// J₁(kh s) w(s): the gradient's kernel in polar form.
double integrand_grad(double s, void* vp) {
  const auto* p = static_cast<const Params*>(vp);
  return gsl_sf_bessel_J1(p->kh * s) * p->piece->value(s);
}
// (1 − J₀(kh s)) w(s)/s: bounded at s = 0, where 1 − J₀ ~ (kh s)²/4.
double integrand(double s, void* vp) {
  const auto* p = static_cast<const Params*>(vp);
  if (s <= 0) return 0.0;
  return (1 - gsl_sf_bessel_J0(p->kh * s)) * p->piece->value(s) / s;
}

// ∫₀¹ f(s; kh) ds over the weight's pieces (GSL, to about 1e-12).
double integrate_pieces(const WeightFunction& w, double kh, double (*f)(double, void*)) {
  constexpr std::size_t kLimit = 200;
  std::unique_ptr<gsl_integration_workspace, void (*)(gsl_integration_workspace*)> ws(
      gsl_integration_workspace_alloc(kLimit), gsl_integration_workspace_free);
  double sum = 0;
  gsl_error_handler_t* old = gsl_set_error_handler_off();
  for (const PolyPiece& pc : w.scaled_pieces()) {
    Params params{&pc, kh};
    gsl_function g{f, &params};
    double result = 0, abserr = 0;
    const int status = gsl_integration_qags(&g, pc.r_begin, pc.r_end, 1e-13, 1e-12, kLimit,
                                            ws.get(), &result, &abserr);
    if (status != GSL_SUCCESS && abserr > 1e-10 * std::max(1.0, std::fabs(result))) {
      gsl_set_error_handler(old);
      throw NumericalError("smoothing error of " + w.name + ": quadrature failed (" +
                           gsl_strerror(status) + ")");
    }
    sum += result;
  }
  gsl_set_error_handler(old);
  return sum;
}
}  // namespace

namespace {

// Below this kh the closed form 1 − (integral) loses digits to cancellation (ε ~ (kh)² is a
// small difference of two numbers near 1: at kh = 1e-4 not one digit is left), so ε is summed
// from the Bessel series instead.  The threshold keeps every kh of the stored studies
// (≥ 0.4) on the quadrature, and at 0.25 the two forms agree to ~1e-9 (test [smoothing]).
constexpr double kSeriesBelow = 0.25;

// The range of kh either form can deliver: below 1e-150, (kh)² underflows; above 1e3 the
// integrand oscillates faster than the quadrature resolves (no local operator has such h).
void require_kh(double kh) {
  require_positive(kh, "kh");
  if (kh < 1e-150 || kh > 1e3) {
    char v[32];
    std::snprintf(v, sizeof v, "%.3g", kh);
    throw InputError("kh = " + std::string(v) + " is outside [1e-150, 1e3], where the smoothing "
                     "error is representable and computed (check h and k)");
  }
}

// Σ_{n≥first} term(n), stopping once a term no longer changes the sum.
template <class Term>
double series(int first, Term term) {
  double sum = 0;
  for (int n = first; n < 60; ++n) {
    const double t = term(n);
    sum += t;
    if (std::fabs(t) <= 1e-18 * std::fabs(sum)) break;
  }
  return sum;
}

}  // namespace

// With 1 − J₀(z) = Σ_{n≥1} (−1)^{n+1} (z/2)^{2n}/(n!)² and m_q = 2π∫ s^{q+1} w:
//   ε(kh) = (1 − m₀) + Σ_{n≥2} (−1)^n (kh)^{2n−2} m_{2n−2} / (4^{n−1} (n!)²).
// The registry's weights are normalized (m₀ = 1; test [weights]); the rounding-level rest of
// 1 − m₀ (~1e-16) would swamp ε at small kh, so the series takes m₀ = 1.
double laplacian_smoothing_error(const WeightFunction& w, double kh) {
  require_kh(kh);
  if (kh >= kSeriesBelow)
    return 1 - 8 * std::numbers::pi / (kh * kh) * integrate_pieces(w, kh, &integrand);
  const double x = kh * kh / 4;
  return series(2, [&](int n) {
           return (n % 2 ? -1.0 : 1.0) * std::pow(x, n - 1) * radial_moment(w, 2 * n - 2) /
                  std::pow(std::tgamma(n + 1.0), 2);
         });
}

// With J₁(z) = Σ_{n≥0} (−1)^n (z/2)^{2n+1}/(n!(n+1)!):
//   ε_∇(kh) = (1 − m₀) − Σ_{n≥1} (−1)^n (kh)^{2n} m_{2n} / (4^n n! (n+1)!), with m₀ = 1 (above).
double gradient_smoothing_error(const WeightFunction& w, double kh) {
  require_kh(kh);
  if (kh >= kSeriesBelow) return 1 - 4 * std::numbers::pi / kh * integrate_pieces(w, kh, &integrand_grad);
  const double x = kh * kh / 4;
  return -series(1, [&](int n) {
           return (n % 2 ? -1.0 : 1.0) * std::pow(x, n) * radial_moment(w, 2 * n) /
                  (std::tgamma(n + 1.0) * std::tgamma(n + 2.0));
         });
}

double radial_moment(const WeightFunction& w, int q) {
  double m = 0;
  for (const PolyPiece& pc : w.scaled_pieces())
    for (std::size_t k = 0; k < pc.c.size(); ++k) {
      const int e = pc.p_min + static_cast<int>(k) + q + 2;  // ∫ s^(p+k+q+1) ds = s^e / e
      m += pc.c[k] * (std::pow(pc.r_end, e) - std::pow(pc.r_begin, e)) / e;
    }
  return 2 * M_PI * m;
}

double interpolant_smoothing_error_case1(const WeightFunction& w, double h) {
  const double a = 3 * radial_moment(w, 2) * h * h, b = 0.75 * radial_moment(w, 4) * std::pow(h, 4);
  // Over Ω, X² + Y² runs through [0, ½]: the extremes of a (X² + Y²) + b are at the ends.
  return std::max(std::fabs(b), std::fabs(0.5 * a + b)) / 0.125;
}

}  // namespace gpm
