#include "gpm/theory/smoothing.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_sf_bessel.h>

#include <algorithm>
#include <cmath>
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

double laplacian_smoothing_error(const WeightFunction& w, double kh) {
  require_positive(kh, "kh");
  return 1 - 8 * std::numbers::pi / (kh * kh) * integrate_pieces(w, kh, &integrand);
}

double gradient_smoothing_error(const WeightFunction& w, double kh) {
  require_positive(kh, "kh");
  return 1 - 4 * std::numbers::pi / kh * integrate_pieces(w, kh, &integrand_grad);
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
