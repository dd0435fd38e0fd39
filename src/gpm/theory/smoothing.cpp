#include "gpm/theory/smoothing.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_sf_bessel.h>

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
// (1 − J₀(kh s)) w(s)/s: bounded at s = 0, where 1 − J₀ ~ (kh s)²/4.
double integrand(double s, void* vp) {
  const auto* p = static_cast<const Params*>(vp);
  if (s <= 0) return 0.0;
  return (1 - gsl_sf_bessel_J0(p->kh * s)) * p->piece->value(s) / s;
}
}  // namespace

double laplacian_smoothing_error(const WeightFunction& w, double kh) {
  require_positive(kh, "kh");
  constexpr std::size_t kLimit = 200;
  std::unique_ptr<gsl_integration_workspace, void (*)(gsl_integration_workspace*)> ws(
      gsl_integration_workspace_alloc(kLimit), gsl_integration_workspace_free);
  double sum = 0;
  gsl_error_handler_t* old = gsl_set_error_handler_off();
  for (const PolyPiece& pc : w.scaled_pieces()) {
    Params params{&pc, kh};
    gsl_function f{&integrand, &params};
    double result = 0, abserr = 0;
    const int status = gsl_integration_qags(&f, pc.r_begin, pc.r_end, 1e-13, 1e-12, kLimit,
                                            ws.get(), &result, &abserr);
    if (status != GSL_SUCCESS && abserr > 1e-10 * std::max(1.0, std::fabs(result))) {
      gsl_set_error_handler(old);
      throw NumericalError("smoothing error of " + w.name + ": quadrature failed (" +
                           gsl_strerror(status) + ")");
    }
    sum += result;
  }
  gsl_set_error_handler(old);
  return 1 - 8 * std::numbers::pi / (kh * kh) * sum;
}

}  // namespace gpm
