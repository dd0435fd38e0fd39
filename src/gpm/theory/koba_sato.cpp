#include "gpm/theory/koba_sato.hpp"

#include <gsl/gsl_poly.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "gpm/error.hpp"

namespace gpm {
namespace {

constexpr double kPi = 3.14159265358979323846;

// K_m(τ) = ∫ (τ² + d²)^{(m−2)/2} dτ for m ≥ 1, d > 0, by the reduction formula
//   K_m = [τ (τ² + d²)^{(m−2)/2} + (m − 2) d² K_{m−2}] / (m − 1),
// with K_1 = asinh(τ/d) and K_2 = τ (even m stay polynomial, odd m pick up one asinh).
double reduction_K(int m, double t, double d) {
  if (m == 1) return std::asinh(t / d);
  if (m == 2) return t;
  const double s2 = t * t + d * d;
  return (t * std::pow(s2, 0.5 * (m - 2)) + (m - 2) * d * d * reduction_K(m - 2, t, d)) /
         (m - 1);
}

// The part of ∫_{P ∩ B_R} ρ^q dy that the polar sweep of one edge (a → b, relative to the
// centre) contributes, m = q + 2:
//   ∫ over the swept angles of  min(ρ_edge(θ), R)^m / m  dθ.
// Along the edge, y(τ) = a + (τ − τ_a)u with |y|² = τ² + d², dθ = s dτ/(τ² + d²), s = a×u
// (signed, |s| = d): the part inside the disc gives (s/m)[K_m]; the parts outside give the
// sector R^m/m · Δθ.
double edge_moment(double ax, double ay, double bx, double by, double R, int m) {
  const double ex = bx - ax, ey = by - ay, L = std::hypot(ex, ey);
  if (L == 0) return 0.0;
  const double ux = ex / L, uy = ey / L;
  const double ta = ax * ux + ay * uy, tb = ta + L;
  const double s = ax * uy - ay * ux, d = std::abs(s);
  const double Rm = std::pow(R, m) / m;
  auto sector = [&](double t1, double t2) {
    if (!(t2 > t1)) return 0.0;
    const double x1 = ax + (t1 - ta) * ux, y1 = ay + (t1 - ta) * uy;
    const double x2 = ax + (t2 - ta) * ux, y2 = ay + (t2 - ta) * uy;
    return Rm * std::atan2(x1 * y2 - y1 * x2, x1 * x2 + y1 * y2);
  };
  if (d < R) {
    const double w = std::sqrt((R - d) * (R + d));
    const double t1 = std::max(ta, -w), t2 = std::min(tb, w);
    if (t1 < t2) {
      // s = 0: the edge lies on a ray through the centre and sweeps no angle.
      const double inside =
          s != 0 ? s / m * (reduction_K(m, t2, d) - reduction_K(m, t1, d)) : 0.0;
      return inside + sector(ta, t1) + sector(t2, tb);
    }
  }
  return sector(ta, tb);
}

double pow_int(double x, int p) {
  double r = 1;
  for (int i = 0; i < p; ++i) r *= x;
  return r;
}

// Polynomial value and derivatives of a piece with p_min ≥ 0, as a plain polynomial.
std::vector<double> as_polynomial(const PolyPiece& p) {
  std::vector<double> c(static_cast<std::size_t>(p.p_min), 0.0);
  c.insert(c.end(), p.c.begin(), p.c.end());
  return c;
}
std::vector<double> derive(const std::vector<double>& c) {
  std::vector<double> d;
  for (std::size_t k = 1; k < c.size(); ++k) d.push_back(c[k] * static_cast<double>(k));
  return d;
}
double eval(const std::vector<double>& c, double x) {
  double s = 0;
  for (std::size_t k = c.size(); k-- > 0;) s = s * x + c[k];
  return s;
}

// Real roots of the polynomial c in [lo, hi].
std::vector<double> real_roots(std::vector<double> c, double lo, double hi) {
  while (!c.empty() && c.back() == 0) c.pop_back();
  std::vector<double> out;
  if (c.size() < 2) return out;
  if (c.size() == 2) {
    out.push_back(-c[0] / c[1]);
  } else {
    std::vector<double> z(2 * (c.size() - 1));
    gsl_poly_complex_workspace* ws = gsl_poly_complex_workspace_alloc(c.size());
    const int status = gsl_poly_complex_solve(c.data(), c.size(), ws, z.data());
    gsl_poly_complex_workspace_free(ws);
    if (status != 0) throw NumericalError("koba_sato: root finding for L_w failed");
    for (std::size_t i = 0; i + 1 < z.size(); i += 2)
      if (std::abs(z[i + 1]) <= 1e-12 * (1 + std::abs(z[i]))) out.push_back(z[i]);
  }
  std::vector<double> in;
  for (double r : out)
    if (r >= lo && r <= hi) in.push_back(r);
  return in;
}

}  // namespace

// ---------------------------------------------------------------------------------
// Geometry.

PolygonView cell_polygon(const VoronoiCells& cells, std::size_t i) {
  if (cells.offset.size() != cells.area.size() + 1)
    throw InputError("koba_sato: the Voronoi cells were computed without polygons "
                     "(call voronoi_cells(p, dom, true))");
  const uint64_t b = cells.offset[i], e = cells.offset[i + 1];
  return PolygonView{cells.px.data() + b, cells.py.data() + b, static_cast<std::size_t>(e - b)};
}

double polygon_disc_moment(const PolygonView& P, double cx, double cy, double R, int q) {
  if (q < -1) throw InputError("polygon_disc_moment: q = " + std::to_string(q) +
                               " < -1 is not integrable at the centre");
  if (!(R >= 0)) throw InputError("polygon_disc_moment: radius must be >= 0");
  if (R == 0 || P.n < 3) return 0.0;
  const int m = q + 2;
  double sum = 0;
  for (std::size_t j = 0; j < P.n; ++j) {
    const std::size_t k = j + 1 == P.n ? 0 : j + 1;
    sum += edge_moment(P.x[j] - cx, P.y[j] - cy, P.x[k] - cx, P.y[k] - cy, R, m);
  }
  return sum;
}

double polygon_disc_area(const PolygonView& P, double cx, double cy, double R) {
  return polygon_disc_moment(P, cx, cy, R, 0);
}

double polygon_annulus_area(const PolygonView& P, double cx, double cy, double r_in,
                            double r_out) {
  if (!(r_out >= r_in)) return 0.0;
  return polygon_disc_area(P, cx, cy, r_out) - polygon_disc_area(P, cx, cy, r_in);
}

double disc_moment(double R, int q) {
  if (q < -1) throw InputError("disc_moment: q < -1 is not integrable");
  return 2 * kPi * std::pow(R, q + 2) / (q + 2);
}

double polygon_boundary_distance(const PolygonView& P, double cx, double cy) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t j = 0; j < P.n; ++j) {
    const std::size_t k = j + 1 == P.n ? 0 : j + 1;
    const double ex = P.x[k] - P.x[j], ey = P.y[k] - P.y[j];
    const double L2 = ex * ex + ey * ey;
    double t = L2 > 0 ? ((cx - P.x[j]) * ex + (cy - P.y[j]) * ey) / L2 : 0.0;
    t = std::clamp(t, 0.0, 1.0);
    best = std::min(best, std::hypot(cx - P.x[j] - t * ex, cy - P.y[j] - t * ey));
  }
  return best;
}

// ---------------------------------------------------------------------------------
// Weights.

double KsWeight::value(double r) const {
  if (!(r >= delta && r <= h)) return 0.0;
  for (auto& p : pieces)
    if (r <= p.r_end) return p.value(r);
  return pieces.empty() ? 0.0 : pieces.back().value(r);
}

double KsWeight::norm_annulus(int n, double r_in, double r_out) const {
  double sum = 0;
  for (auto& p : pieces) {
    const double a = std::max({r_in, p.r_begin, delta}), b = std::min({r_out, p.r_end, h});
    if (!(b > a)) continue;
    for (std::size_t k = 0; k < p.c.size(); ++k) {
      const int q = p.p_min + static_cast<int>(k) + n;
      if (q < -1) throw InputError("weight " + name + ": |x|^" + std::to_string(n) +
                                   " w(x) is not integrable");
      sum += p.c[k] * 2 * kPi * (std::pow(b, q + 2) - std::pow(a, q + 2)) / (q + 2);
    }
  }
  return sum;
}

double KsWeight::norm_polygon(int n, const PolygonView& P, double cx, double cy, double r_in,
                              double r_out) const {
  double sum = 0;
  for (auto& p : pieces) {
    const double a = std::max({r_in, p.r_begin, delta}), b = std::min({r_out, p.r_end, h});
    if (!(b > a)) continue;
    for (std::size_t k = 0; k < p.c.size(); ++k) {
      if (p.c[k] == 0) continue;
      const int q = p.p_min + static_cast<int>(k) + n;
      sum += p.c[k] * (polygon_disc_moment(P, cx, cy, b, q) - polygon_disc_moment(P, cx, cy, a, q));
    }
  }
  return sum;
}

KsWeight ks_step_weight(double delta, double h) {
  require_positive(delta, "delta");
  if (!(h > delta)) throw InputError("step weight: h must exceed delta");
  KsWeight w;
  w.name = "step";
  w.delta = delta;
  w.h = h;
  PolyPiece p;
  p.r_begin = delta;
  p.r_end = h;
  p.p_min = 0;
  p.c = {1.0};
  w.pieces = {p};
  w.lipschitz = 0;
  return w;
}

KsWeight ks_scaled_weight(const WeightFunction& W, double delta, double h) {
  require_positive(delta, "delta");
  if (!(h > delta)) throw InputError("weight " + W.name + ": h must exceed delta");
  KsWeight w;
  w.name = W.name;
  w.delta = delta;
  w.h = h;
  for (const PolyPiece& s : W.scaled_pieces()) {
    const double b = std::max(s.r_begin * h, delta), e = std::min(s.r_end * h, h);
    if (!(e > b)) continue;
    if (s.p_min < 0)
      throw InputError("weight " + W.name +
                       " is unbounded at r = 0; Assumption 1.1 needs w in L^inf");
    PolyPiece p;
    p.r_begin = b;
    p.r_end = e;
    p.p_min = s.p_min;
    p.c = s.c;
    for (std::size_t k = 0; k < p.c.size(); ++k)
      p.c[k] /= pow_int(h, s.p_min + static_cast<int>(k));  // W(r/h) as a polynomial in r
    w.pieces.push_back(p);
  }
  if (w.pieces.empty()) throw InputError("weight " + W.name + " vanishes on [delta, h]");
  // L_w: |ŵ'| is largest at a piece end or where ŵ'' = 0.  A jump at a knot inside the
  // annulus would make w non-Lipschitz on the closed annulus.
  double L = 0;
  for (std::size_t i = 0; i < w.pieces.size(); ++i) {
    const auto c = as_polynomial(w.pieces[i]);
    const auto d1 = derive(c), d2 = derive(d1);
    std::vector<double> at = {w.pieces[i].r_begin, w.pieces[i].r_end};
    for (double r : real_roots(d2, w.pieces[i].r_begin, w.pieces[i].r_end)) at.push_back(r);
    for (double r : at) L = std::max(L, std::abs(eval(d1, r)));
    if (i + 1 < w.pieces.size()) {
      const double x = w.pieces[i].r_end;
      const double jump = eval(as_polynomial(w.pieces[i + 1]), x) - eval(c, x);
      if (std::abs(jump) > 1e-12 * (1 + std::abs(eval(c, x))))
        throw InputError("weight " + W.name + " jumps at r = " + std::to_string(x) +
                         " inside the annulus: not Lipschitz (Assumption 1.1 (iii))");
    }
  }
  w.lipschitz = L;
  return w;
}

KsWeight ks_weight(const std::string& name, double delta, double h) {
  if (name == "step") return ks_step_weight(delta, h);
  return ks_scaled_weight(weight(name), delta, h);
}

// ---------------------------------------------------------------------------------
// The neighbourhood of a_k.

KsSite ks_site(const Particles& p, const VoronoiCells& cells, std::size_t k, double h,
               double delta, double r_sigma, const Domain& dom) {
  if (k >= p.size()) throw InputError("koba_sato: particle index out of range");
  const PolygonView ck = cell_polygon(cells, k);
  KsSite s;
  s.k = k;
  s.ax = p.x[k];
  s.ay = p.y[k];
  s.h = h;
  s.delta = delta;
  s.r_sigma = r_sigma;
  const std::string where = "a_k = particle " + std::to_string(k);
  if (!(h > r_sigma)) throw InputError(where + ": need r_sigma < h");
  s.delta_max = polygon_boundary_distance(ck, s.ax, s.ay);
  if (!(delta > 0 && delta <= s.delta_max))
    throw InputError(where + ": need 0 < delta <= dist(a_k, boundary of sigma_k) = " +
                     std::to_string(s.delta_max));
  if (!Domain::in_omega(s.ax, s.ay) ||
      std::min({s.ax, 1 - s.ax, s.ay, 1 - s.ay}) < delta)
    throw InputError(where + ": B_delta(a_k) is not inside Omega");
  const double room =
      std::min({s.ax - dom.lo(), dom.hi() - s.ax, s.ay - dom.lo(), dom.hi() - s.ay});
  if (h + r_sigma + delta > room)
    throw InputError(where + ": B_{h+r_sigma}(x) leaves Omega_H for some x in B_delta(a_k)"
                     " (h + r_sigma + delta = " + std::to_string(h + r_sigma + delta) +
                     " > " + std::to_string(room) + ")");
  s.cell_area = cells.area[k];
  double covered = polygon_disc_area(ck, s.ax, s.ay, h);
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (i == k) continue;
    const double dx = p.x[i] - s.ax, dy = p.y[i] - s.ay, r = std::hypot(dx, dy);
    if (!(r < h)) continue;
    const PolygonView ci = cell_polygon(cells, i);
    const double in_h = polygon_disc_area(ci, s.ax, s.ay, h);
    covered += in_h;
    s.idx.push_back(i);
    s.dx.push_back(dx);
    s.dy.push_back(dy);
    s.dist.push_back(r);
    s.V.push_back(in_h - polygon_disc_area(ci, s.ax, s.ay, delta));
    s.ratio_2_6 = std::max(s.ratio_2_6, cells.cover[i] / r);
  }
  s.uncovered = kPi * h * h - covered;
  return s;
}

std::vector<double> ks_neighbour_weights(const KsSite& s, const KsWeight& w) {
  std::vector<double> out(s.dist.size());
  for (std::size_t j = 0; j < out.size(); ++j) out[j] = w.value(s.dist[j]);
  return out;
}

KsOps ks_operators(const KsSite& s, const std::vector<double>& w_nb, const double* f_nb,
                   double f_k) {
  double D0 = 0, D2 = 0, pi = 0, gx = 0, gy = 0, lap = 0, box = 0;
  for (std::size_t j = 0; j < s.idx.size(); ++j) {
    const double Vw = s.V[j] * w_nb[j], r = s.dist[j], r2 = r * r, df = f_k - f_nb[j];
    D0 += Vw;
    D2 += Vw * r2;
    pi += Vw * f_nb[j];
    // (f(a_k) − f(a_i))/|a_k − a_i| · (a_k − a_i)/|a_k − a_i|, and a_k − a_i = −(dx, dy).
    gx -= Vw * df * s.dx[j] / r2;
    gy -= Vw * df * s.dy[j] / r2;
    lap += Vw * df;
    box += Vw * df / r2;
  }
  if (!(D0 > 0)) throw NumericalError("koba_sato: sum of V_j w_j is zero (Assumption 1.1 (v))");
  KsOps o;
  o.pi = pi / D0;
  o.gx = 2 * gx / D0;
  o.gy = 2 * gy / D0;
  o.lap = -4 * lap / D2;
  o.box = -4 * box / D0;
  return o;
}

// ---------------------------------------------------------------------------------
// Constants and bounds.

KsConstants ks_constants(const KsSite& s, const std::vector<double>& w_nb, const KsWeight& w,
                         const PolygonView& cell_k, double lambda) {
  if (!(lambda > 0 && lambda < 1)) throw InputError("lambda must lie in (0, 1)");
  KsConstants c;
  const double h = s.h, r = s.r_sigma, d = s.delta, L = w.lipschitz;
  const double rho = std::min(lambda * h + r, h);  // w = 0 beyond h
  for (int n = -1; n <= 2; ++n) {
    const int i = n + 1;
    c.A[i] = w.norm_annulus(n, d, h);
    c.S[i] = w.norm_polygon(n, cell_k, s.ax, s.ay, d, h);  // σ_k ⊂ B_{r_σ} ⊂ B_h
    c.O[i] = c.A[i] - c.S[i];                              // B_δ ⊂ σ_k, w = 0 in B_δ
    c.Lam[i] = w.norm_annulus(n, d, rho) - w.norm_polygon(n, cell_k, s.ax, s.ay, d, rho);
  }
  for (std::size_t j = 0; j < s.idx.size(); ++j) {
    const double Vw = s.V[j] * w_nb[j], rj = s.dist[j];
    c.D0 += Vw;
    c.D1 += Vw * rj;
    c.D2 += Vw * rj * rj;
    if (rj < lambda * h) {
      c.Dlam += Vw / rj;
      c.lambda_ok = true;
    }
  }
  const auto& A = c.A;
  const auto& S = c.S;
  const auto& O = c.O;
  const auto& Lm = c.Lam;
  const double ratio12 = c.D1 / c.D2;
  auto& k = c.c;
  k[1] = S[1] / A[1];
  k[2] = kPi * L * r * h * h / O[1];
  k[3] = Lm[1] / O[1];
  k[4] = S[2] / A[3] * (1 + r * A[2] / O[3]);
  k[5] = r / (lambda * h) * O[2] / O[3];
  k[6] = r * Lm[1] / O[3];
  k[7] = 2 * r * h * O[1] / O[3] * ratio12;
  k[8] = kPi * L * r * h * h * h / O[3] * (1 + h * ratio12);
  k[9] = S[0] / A[1] + S[1] / A[1] * O[0] / O[1];
  k[10] = r / (lambda * h) * O[0] / O[1];
  k[11] = Lm[0] / O[1];
  k[12] = kPi * L / O[1] *
          (2 * r * h / lambda + (lambda * h + r) * (lambda * h + r) + r * h * h * c.Dlam / c.D0);
  return c;
}

KsBounds ks_bounds(const KsConstants& c, double h, double r_sigma, double lambda,
                   const std::array<double, 4>& f) {
  const auto& k = c.c;
  KsBounds b;
  b.pi = (h + r_sigma) * f[1] + (2 * k[1] + 2 * k[2]) * f[0];                    // Thm 1.3
  b.grad = 4 * h * f[2] +
           (8 * r_sigma / (lambda * h) + 4 * k[1] + 4 * k[2] + 8 * k[3]) * f[1];  // Thm 1.4
  b.lap = 24 * h * f[3] + 4 * (k[4] + k[5] + k[6] + k[7]) * f[1];               // Thm 1.5
  b.lap_lemmas = b.lap + 4 * k[8] * f[1];                                          // + (5.4)
  b.box = 24 * h * f[3] + (4 * k[9] + 12 * k[10] + 12 * k[11] + 4 * k[12]) * f[1];  // 1.6
  return b;
}

// ---------------------------------------------------------------------------------
// Test functions.  Seminorms on Ω̄_H = [−0.1, 1.1]²:
//   sin2pi  sin(2π(x+y)): D^α f = (2π)^j sin(2π(x+y) + jπ/2); the phase covers more than a
//           period, so |f|_{C^j} = (2π)^j.
//   wave    cos(k(x cos θ + y sin θ)), k = 20, θ = 0.3: D^α f = k^j cos^{α₁}θ sin^{α₂}θ ×
//           cos(φ + jπ/2); the phase spans k·1.2(cos θ + sin θ) > 2π, and cos θ > sin θ,
//           so |f|_{C^j} = (k cos θ)^j (at α = (j, 0)).
//   quartic (x−½)⁴ + (y−½)⁴: mixed derivatives vanish, |x − ½| ≤ 0.6, so |f|_{C^0} = 2·0.6⁴,
//           |f|_{C^1} = 4·0.6³, |f|_{C^2} = 12·0.6², |f|_{C^3} = 24·0.6.
//   linear  1 + 2x − 3y: |f|_{C^0} = 1 + 2.2 + 0.3 = 3.5 at (1.1, −0.1), |f|_{C^1} = 3.
namespace {
constexpr double kWaveK = 20.0, kWaveTheta = 0.3;

double d_sin2pi(int a1, int a2, double x, double y) {
  const int j = a1 + a2;
  return std::pow(2 * kPi, j) * std::sin(2 * kPi * (x + y) + j * kPi / 2);
}
double d_wave(int a1, int a2, double x, double y) {
  const int j = a1 + a2;
  const double c = std::cos(kWaveTheta), s = std::sin(kWaveTheta);
  return std::pow(kWaveK, j) * pow_int(c, a1) * pow_int(s, a2) *
         std::cos(kWaveK * (x * c + y * s) + j * kPi / 2);
}
double d_quartic_1d(int a, double t) {
  static const double fall[5] = {1, 4, 12, 24, 24};  // 4!/(4 − a)!
  return a > 4 ? 0.0 : fall[a] * pow_int(t - 0.5, 4 - a);
}
double d_quartic(int a1, int a2, double x, double y) {
  if (a1 > 0 && a2 > 0) return 0.0;
  if (a1 == 0 && a2 == 0) return d_quartic_1d(0, x) + d_quartic_1d(0, y);
  return a1 > 0 ? d_quartic_1d(a1, x) : d_quartic_1d(a2, y);
}
double d_linear(int a1, int a2, double x, double y) {
  if (a1 == 0 && a2 == 0) return 1 + 2 * x - 3 * y;
  if (a1 + a2 > 1) return 0.0;
  return a1 == 1 ? 2.0 : -3.0;
}
}  // namespace

const std::vector<KsFunction>& ks_functions() {
  static const std::vector<KsFunction> fs = [] {
    const double kc = kWaveK * std::cos(kWaveTheta);
    return std::vector<KsFunction>{
        {"sin2pi", "sin(2π(x+y))", d_sin2pi,
         {1, 2 * kPi, 4 * kPi * kPi, 8 * kPi * kPi * kPi}},
        {"wave", "cos(20(x cos 0.3 + y sin 0.3))", d_wave, {1, kc, kc * kc, kc * kc * kc}},
        {"quartic", "(x−½)⁴ + (y−½)⁴", d_quartic,
         {2 * pow_int(0.6, 4), 4 * pow_int(0.6, 3), 12 * 0.36, 24 * 0.6}},
        {"linear", "1 + 2x − 3y", d_linear, {3.5, 3, 0, 0}},
    };
  }();
  return fs;
}

const KsFunction& ks_function(const std::string& name) {
  std::string valid;
  for (auto& f : ks_functions()) {
    if (f.name == name) return f;
    valid += (valid.empty() ? "" : ", ") + f.name;
  }
  throw InputError("unknown test function '" + name + "'; valid: " + valid);
}

}  // namespace gpm
