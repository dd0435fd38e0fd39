// The interpolant's smoothing part for the thesis' Case 1 (theory/smoothing.hpp) against a
// brute-force polar quadrature of the continuous convolution at the centre and at a corner of Ω.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "gpm/theory/smoothing.hpp"
#include "gpm/weights/weights.hpp"

using namespace gpm;

namespace {

// (Π_h v − v)(x) for v = X⁴ + Y⁴ by the midpoint rule in polar coordinates about x, nr radii.
double midpoint_error(const WeightFunction& w, double h, double X, double Y, int nr) {
  const int nt = 16;  // v is a quartic: 16 equally spaced angles integrate it exactly
  double s = 0;
  for (int i = 0; i < nr; ++i) {
    const double r = (i + 0.5) / nr;  // in units of h
    const double wr = w.value(r) / (h * h);
    for (int j = 0; j < nt; ++j) {
      const double t = 2 * M_PI * (j + 0.5) / nt;
      const double a = X - h * r * std::cos(t), b = Y - h * r * std::sin(t);
      s += (std::pow(a, 4) + std::pow(b, 4)) * wr * (h * h * r) * (1.0 / nr) * (2 * M_PI / nt);
    }
  }
  return s - (std::pow(X, 4) + std::pow(Y, 4));
}

// The midpoint rule's error is O(nr⁻²) (w is smooth on each piece): one Richardson step.
double convolution_error(const WeightFunction& w, double h, double X, double Y) {
  return (4 * midpoint_error(w, h, X, Y, 20000) - midpoint_error(w, h, X, Y, 10000)) / 3;
}

}  // namespace

TEST_CASE("smoothing: the Case 1 interpolant error is 3 m2 h^2 (X^2+Y^2) + (3/4) m4 h^4",
          "[unit][smoothing]") {
  for (const char* name : {"quadratic_spike", "cubic_spike", "cubic_bspline"}) {
    INFO(name);
    const WeightFunction& w = weight(name);
    const double h = 0.05;
    const double centre = convolution_error(w, h, 0, 0), corner = convolution_error(w, h, 0.5, 0.5);
    CHECK(centre == Approx(0.75 * radial_moment(w, 4) * std::pow(h, 4)).epsilon(1e-5));
    CHECK(corner == Approx(1.5 * radial_moment(w, 2) * h * h + 0.75 * radial_moment(w, 4) * std::pow(h, 4))
                        .epsilon(1e-5).margin(1e-14));
    CHECK(interpolant_smoothing_error_case1(w, h) ==
          Approx(std::max(std::fabs(centre), std::fabs(corner)) / 0.125).epsilon(1e-5));
  }
  // The cubic spike has order k = 3: no h² term, so the error is O(h⁴) exactly.
  CHECK(std::fabs(radial_moment(weight("cubic_spike"), 2)) < 1e-12);
  CHECK(radial_moment(weight("cubic_spike"), 0) == Approx(1).epsilon(1e-12));
}
