#include "gpm/operators/operators.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

#include "gpm/error.hpp"

namespace gpm {

namespace {

constexpr int kD = 2;  // space dimension of every study

void check_sizes(const CellList& cl, const std::vector<double>& a, const char* what) {
  if (a.size() != cl.size()) {
    std::ostringstream s;
    s << "operators: " << what << " has " << a.size() << " entries for " << cl.size()
      << " particles";
    throw InputError(s.str());
  }
}

// w_h(r) = w(r/h)/h^d and its derivative w_h'(r) = w'(r/h)/h^(d+1).
double wh(const WeightFunction& w, double r, double h) { return w.value(r / h) / (h * h); }
double dwh(const WeightFunction& w, double r, double h) {
  return w.derivative(r / h) / (h * h * h);
}

// ∫_a^b r^e dr for integer e (e = −1: log).
double power_integral(int e, double a, double b) {
  if (e == -1) return (a > 0) ? std::log(b / a) : std::numeric_limits<double>::infinity();
  if (e < -1 && a == 0) return std::numeric_limits<double>::infinity();
  return (std::pow(b, e + 1) - std::pow(a, e + 1)) / (e + 1);
}

// Pieces of r^k · w(r)·factor (without the constant, which the caller keeps).
std::vector<PolyPiece> shifted(const std::vector<PolyPiece>& ps, int k) {
  std::vector<PolyPiece> out = ps;
  for (auto& p : out) p.p_min += k;
  return out;
}

WeightFunction derived(const WeightFunction& base, const std::string& suffix,
                       const std::string& source, double constant,
                       std::vector<PolyPiece> shape) {
  WeightFunction w;
  w.name = base.name + suffix;
  w.label = base.label + suffix;
  w.source = source;
  w.role = "derived";
  w.constant = constant;
  w.shape = std::move(shape);
  w.dimension = base.dimension;
  return w;
}

}  // namespace

// ---------------------------------------------------------------------------------
// Generalized operators, imoto (2)–(4).

double interpolant(const CellList& cl, const std::vector<double>& V,
                   const std::vector<double>& v, const WeightFunction& w, double h, Vec2 p) {
  check_sizes(cl, V, "V");
  check_sizes(cl, v, "v");
  double s = 0;
  cl.for_each_neighbour(p.x, p.y, h, [&](int32_t k, double, double, double r2) {
    const int32_t i = cl.index()[k];
    s += V[i] * v[i] * wh(w, std::sqrt(r2), h);
  });
  return s;
}

Vec2 gradient(const CellList& cl, const std::vector<double>& V, const std::vector<double>& v,
              const WeightFunction& w, double h, Vec2 p, double vp) {
  check_sizes(cl, V, "V");
  check_sizes(cl, v, "v");
  Vec2 g;
  cl.for_each_neighbour(p.x, p.y, h, [&](int32_t k, double dx, double dy, double r2) {
    if (r2 == 0) return;  // Λ excludes r = 0
    const int32_t i = cl.index()[k];
    const double r = std::sqrt(r2);
    // dx = x_i − p
    const double a = V[i] * (v[i] - vp) / r * wh(w, r, h);
    g.x += a * (dx / r);
    g.y += a * (dy / r);
  });
  g.x *= kD;
  g.y *= kD;
  return g;
}

double laplacian(const CellList& cl, const std::vector<double>& V,
                 const std::vector<double>& v, const WeightFunction& w, double h, Vec2 p,
                 double vp) {
  check_sizes(cl, V, "V");
  check_sizes(cl, v, "v");
  double s = 0;
  cl.for_each_neighbour(p.x, p.y, h, [&](int32_t k, double, double, double r2) {
    if (r2 == 0) return;
    const int32_t i = cl.index()[k];
    s += V[i] * (v[i] - vp) / r2 * wh(w, std::sqrt(r2), h);
  });
  return 2 * kD * s;
}

// ---------------------------------------------------------------------------------
// Thesis (1.2)–(1.4): same sums, terms written with v(p) − v_i and p − x_i.

double interpolant_thesis(const CellList& cl, const std::vector<double>& V,
                          const std::vector<double>& v, const WeightFunction& w, double h,
                          Vec2 p) {
  check_sizes(cl, V, "V");
  check_sizes(cl, v, "v");
  double s = 0;
  cl.for_each_neighbour(p.x, p.y, h, [&](int32_t k, double dx, double dy, double) {
    const int32_t i = cl.index()[k];
    const double ex = -dx, ey = -dy;  // p − x_i
    s += V[i] * v[i] * wh(w, std::sqrt(dist2(ex, ey)), h);
  });
  return s;
}

Vec2 gradient_thesis(const CellList& cl, const std::vector<double>& V,
                     const std::vector<double>& v, const WeightFunction& w, double h, Vec2 p,
                     double vp) {
  check_sizes(cl, V, "V");
  check_sizes(cl, v, "v");
  Vec2 g;
  cl.for_each_neighbour(p.x, p.y, h, [&](int32_t k, double dx, double dy, double r2) {
    if (r2 == 0) return;  // Λ*_x: i with x_i ≠ p
    const int32_t i = cl.index()[k];
    const double ex = -dx, ey = -dy;  // p − x_i
    const double r = std::sqrt(r2);
    const double a = V[i] * (vp - v[i]) / r * wh(w, r, h);
    g.x += a * (ex / r);
    g.y += a * (ey / r);
  });
  g.x *= kD;
  g.y *= kD;
  return g;
}

double laplacian_thesis(const CellList& cl, const std::vector<double>& V,
                        const std::vector<double>& v, const WeightFunction& w, double h,
                        Vec2 p, double vp) {
  check_sizes(cl, V, "V");
  check_sizes(cl, v, "v");
  double s = 0;
  cl.for_each_neighbour(p.x, p.y, h, [&](int32_t k, double, double, double r2) {
    if (r2 == 0) return;
    const int32_t i = cl.index()[k];
    s += V[i] * (vp - v[i]) / r2 * wh(w, std::sqrt(r2), h);
  });
  return -2 * kD * s;
}

// ---------------------------------------------------------------------------------
// SPH, thesis (A.6)–(A.8).

double sph_interpolant(const CellList& cl, const std::vector<double>& V,
                       const std::vector<double>& v, const WeightFunction& wS, double h,
                       Vec2 p) {
  return interpolant(cl, V, v, wS, h, p);  // (A.6) is (1.2) with w = w^S
}

namespace {
// Σ_Λ V_i · sgn·(v_i − v(p)) · ∇_p w^S_h(|p − x_i|)
Vec2 sph_gradient_signed(const CellList& cl, const std::vector<double>& V,
                         const std::vector<double>& v, const WeightFunction& wS, double h,
                         Vec2 p, double vp, bool imoto58) {
  check_sizes(cl, V, "V");
  check_sizes(cl, v, "v");
  Vec2 g;
  cl.for_each_neighbour(p.x, p.y, h, [&](int32_t k, double dx, double dy, double r2) {
    if (r2 == 0) return;  // ∇w^S_h(|p − x_i|) at r = 0 is 0 for w^S ∈ C¹ with w'(0) = 0
    const int32_t i = cl.index()[k];
    const double r = std::sqrt(r2);
    const double gx = dwh(wS, r, h) * (-dx / r);  // ∇_p w^S_h(|p − x_i|)
    const double gy = dwh(wS, r, h) * (-dy / r);
    const double dv = imoto58 ? (vp - v[i]) : (v[i] - vp);
    g.x += V[i] * dv * gx;
    g.y += V[i] * dv * gy;
  });
  return g;
}
}  // namespace

Vec2 sph_gradient(const CellList& cl, const std::vector<double>& V,
                  const std::vector<double>& v, const WeightFunction& wS, double h, Vec2 p,
                  double vp) {
  return sph_gradient_signed(cl, V, v, wS, h, p, vp, false);
}

Vec2 sph_gradient_imoto58(const CellList& cl, const std::vector<double>& V,
                          const std::vector<double>& v, const WeightFunction& wS, double h,
                          Vec2 p, double vp) {
  return sph_gradient_signed(cl, V, v, wS, h, p, vp, true);
}

double sph_laplacian(const CellList& cl, const std::vector<double>& V,
                     const std::vector<double>& v, const WeightFunction& wS, double h, Vec2 p,
                     double vp) {
  check_sizes(cl, V, "V");
  check_sizes(cl, v, "v");
  double s = 0;
  cl.for_each_neighbour(p.x, p.y, h, [&](int32_t k, double dx, double dy, double r2) {
    if (r2 == 0) return;
    const int32_t i = cl.index()[k];
    const double r = std::sqrt(r2);
    const double ex = -dx / r, ey = -dy / r;                 // (p − x_i)/r
    const double gx = dwh(wS, r, h) * ex, gy = dwh(wS, r, h) * ey;  // ∇w^S_h(|p − x_i|)
    s += V[i] * (vp - v[i]) / r * (ex * gx + ey * gy);
  });
  return 2 * s;
}

// ---------------------------------------------------------------------------------
// MPS, thesis (A.14)–(A.15).

Vec2 mps_gradient(const CellList& cl, const std::vector<double>& v, const WeightFunction& wM,
                  double h, Vec2 p, double vp, double n0) {
  check_sizes(cl, v, "v");
  Vec2 g;
  cl.for_each_neighbour(p.x, p.y, h, [&](int32_t k, double dx, double dy, double r2) {
    if (r2 == 0) return;
    const int32_t i = cl.index()[k];
    const double r = std::sqrt(r2);
    const double a = (vp - v[i]) / r * wh(wM, r, h);
    g.x += a * (-dx / r);
    g.y += a * (-dy / r);
  });
  g.x *= kD / n0;
  g.y *= kD / n0;
  return g;
}

double mps_laplacian(const CellList& cl, const std::vector<double>& v,
                     const WeightFunction& wM, double h, Vec2 p, double vp, double lambda0) {
  check_sizes(cl, v, "v");
  double s = 0;
  cl.for_each_neighbour(p.x, p.y, h, [&](int32_t k, double, double, double r2) {
    if (r2 == 0) return;
    const int32_t i = cl.index()[k];
    s += (vp - v[i]) * wh(wM, std::sqrt(r2), h);
  });
  return -(2.0 * kD / lambda0) * s;
}

double mps_n0(const WeightFunction& wM, std::size_t n, double area) {
  return static_cast<double>(n) / area * radial_moment(wM, 0);
}

double mps_lambda0(const WeightFunction& wM, std::size_t n, double area, double h) {
  return static_cast<double>(n) / area * h * h * radial_moment(wM, 2);
}

double mps_lambda0_printed(const WeightFunction& wM, std::size_t n, double area) {
  return static_cast<double>(n) / area * radial_moment(wM, 2);
}

double mps_n0_sum(const CellList& cl, const WeightFunction& wM, double h, Vec2 p) {
  double s = 0;
  cl.for_each_neighbour(p.x, p.y, h, [&](int32_t, double, double, double r2) {
    if (r2 > 0) s += wh(wM, std::sqrt(r2), h);
  });
  return s;
}

double mps_lambda0_sum(const CellList& cl, const WeightFunction& wM, double h, Vec2 p) {
  double s = 0;
  cl.for_each_neighbour(p.x, p.y, h, [&](int32_t, double, double, double r2) {
    if (r2 > 0) s += r2 * wh(wM, std::sqrt(r2), h);
  });
  return s;
}

// ---------------------------------------------------------------------------------
// Weight substitutions.

double radial_moment(const WeightFunction& w, int k, int d) {
  // |S^(d−1)| ∫_0^1 r^(d−1+k) w(r) dr
  const double pi = std::numbers::pi;
  const double sphere = (d == 2) ? 2 * pi : (d == 3) ? 4 * pi : (d == 1) ? 2.0 : NAN;
  if (std::isnan(sphere)) throw InputError("radial_moment: dimension must be 1, 2 or 3");
  double s = 0;
  for (const auto& p : w.shape)
    for (std::size_t j = 0; j < p.c.size(); ++j) {
      if (p.c[j] == 0) continue;
      const int e = p.p_min + static_cast<int>(j) + d - 1 + k;
      s += p.c[j] * power_integral(e, p.r_begin, p.r_end);
    }
  return sphere * w.constant * s;
}

WeightFunction sph_generalized_weight(const WeightFunction& wS, int d) {
  std::vector<PolyPiece> shape;
  for (const auto& p : wS.shape) {
    // −(r/d) d/dr Σ c_j r^(p+j) = Σ −(p+j)/d · c_j r^(p+j)
    PolyPiece q = p;
    for (std::size_t j = 0; j < q.c.size(); ++j)
      q.c[j] = -(p.p_min + static_cast<int>(j)) * p.c[j] / d;
    shape.push_back(q);
  }
  return derived(wS, "_sph_A9", "thesis (A.9): w = -(r/d) dw^S/dr of " + wS.name,
                 wS.constant, std::move(shape));
}

WeightFunction mps_gradient_weight(const WeightFunction& wM) {
  const double m0 = radial_moment(wM, 0);
  return derived(wM, "_mps_A16", "thesis (A.16): w^M / int w^M of " + wM.name,
                 wM.constant / m0, wM.shape);
}

WeightFunction mps_laplacian_weight(const WeightFunction& wM) {
  const double m2 = radial_moment(wM, 2);
  return derived(wM, "_mps_A18", "thesis (A.18): r^2 w^M / int |x|^2 w^M of " + wM.name,
                 wM.constant / m2, shifted(wM.shape, 2));
}

}  // namespace gpm
