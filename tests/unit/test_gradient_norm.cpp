// The relative gradient error uses the documents' norm: the Euclidean length of the error
// vector, maximized over the particles in Ω (imoto §1 and §5; thesis (1.27) and §4.1.2),
// divided by the maximum Euclidean length of the exact gradient.  Checked against a
// brute-force evaluation with the reference operator, and on the known exact gradient of
// sin 2π(x+y), whose length is 2π√2·|cos 2π(x+y)| (maximum 2π√2, reached on x + y = 1/2).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "gpm/geometry/cells.hpp"
#include "gpm/geometry/domain.hpp"
#include "gpm/geometry/volumes.hpp"
#include "gpm/kernel/kernel.hpp"
#include "gpm/operators/fused_errors.hpp"
#include "gpm/operators/operators.hpp"
#include "gpm/operators/testfunctions.hpp"
#include "gpm/weights/weights.hpp"

using namespace gpm;

TEST_CASE("gradient error: Euclidean norm, brute force reference", "[unit][norm]") {
  const double dx = std::ldexp(1.0, -5), h = 3.1 * dx;
  const Particles p = jittered_grid(dx, 1, 0.25);
  const std::vector<double> V = uniform_volumes(p);
  const auto& f = test_function("sin2pi");
  const WeightFunction& w = weight("Grad1");
  std::vector<double> v(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) v[i] = f.v(p.x[i], p.y[i]);
  const CellList cl(p.x, p.y, h / 4);

  double euclid = 0, comp = 0, ref_e = 0, ref_c = 0;
  int32_t worst = -1;
  for (int32_t i : omega_targets(p)) {
    const Vec2 g = gradient(cl, V, v, w, h, {p.x[i], p.y[i]}, v[i]);
    const double ex = f.vx(p.x[i], p.y[i]) - g.x, ey = f.vy(p.x[i], p.y[i]) - g.y;
    if (std::sqrt(ex * ex + ey * ey) > euclid) worst = i;
    euclid = std::max(euclid, std::sqrt(ex * ex + ey * ey));
    comp = std::max({comp, std::fabs(ex), std::fabs(ey)});
    const double gx = f.vx(p.x[i], p.y[i]), gy = f.vy(p.x[i], p.y[i]);
    ref_e = std::max(ref_e, std::sqrt(gx * gx + gy * gy));
    ref_c = std::max({ref_c, std::fabs(gx), std::fabs(gy)});
  }
  // The exact gradient's largest length over the particles approaches 2π√2 (the
  // continuous maximum); the component maximum approaches 2π — the two denominators differ
  // by √2, the numerators by between 1 and √2.
  const double two_pi = 2 * std::numbers::pi;
  CHECK(ref_e == Approx(two_pi * std::sqrt(2.0)).epsilon(1e-2));
  CHECK(ref_c == Approx(two_pi).epsilon(1e-2));
  REQUIRE(euclid >= comp);
  REQUIRE(euclid <= std::sqrt(2.0) * comp * (1 + 1e-12));

  const FusedErrors fe = fused_errors(p, V, h, {{"Grad1", Operator::grad}}, {"sin2pi"});
  REQUIRE(fe.errors.size() == 1);
  // The fused kernel sums in another order than the reference operator: agreement to
  // rounding, and clearly not the component-wise value.
  CHECK(fe.errors[0].rel_error == Approx(euclid / ref_e).epsilon(1e-10));
  CHECK(std::fabs(fe.errors[0].rel_error - comp / ref_c) > 1e-6 * comp / ref_c);
  // Where the maximum sits: the same particle as the reference's (gpm trunc reports it).
  CHECK(fe.errors[0].worst == worst);
}
