// Reference weight functions: the registry, the printed forms that are wrong (errata),
// and the properties computed from the pieces.
//
// Every formula is entered the way the document prints it — a prefactor and a bracketed
// product such as (1−r)²(4−7r) — and expanded into monomials by the small polynomial
// helpers below, so that no coefficient is typed by hand.  Every property in
// WeightProperties is computed from the pieces (GSL quadrature, GSL polynomial roots,
// knot comparisons); nothing is copied from the documents.
#include "gpm/weights/weights.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_poly.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <numbers>

#include "gpm/error.hpp"

namespace gpm {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kInf = std::numeric_limits<double>::infinity();

// ---------------------------------------------------------------------------------
// Polynomial arithmetic on coefficient vectors: p[k] multiplies r^k.

using Poly = std::vector<double>;

Poly add(Poly a, const Poly& b) {
  if (b.size() > a.size()) a.resize(b.size(), 0.0);
  for (std::size_t k = 0; k < b.size(); ++k) a[k] += b[k];
  return a;
}

Poly scaled(double s, Poly a) {
  for (double& x : a) x *= s;
  return a;
}

Poly mul(const Poly& a, const Poly& b) {
  if (a.empty() || b.empty()) return {};
  Poly out(a.size() + b.size() - 1, 0.0);
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) out[i + j] += a[i] * b[j];
  return out;
}

Poly power(const Poly& a, int n) {
  Poly out{1.0};
  for (int k = 0; k < n; ++k) out = mul(out, a);
  return out;
}

Poly lin(double a, double b) { return {a, b}; }  // a + b·r

Poly monomial(int p, double c = 1.0) {
  Poly out(static_cast<std::size_t>(p) + 1, 0.0);
  out[static_cast<std::size_t>(p)] = c;
  return out;
}

// ---------------------------------------------------------------------------------
// Piece helpers.

// A coefficient this small next to the largest one is a cancellation residue, not a term.
// (The documents' coefficients are integers, so expansions cancel exactly; the guard is
// for the derived pieces only.)
bool negligible(double c, double largest) { return std::abs(c) <= 1e-14 * largest; }

// Drops zero coefficients at both ends.  Leading zeros raise p_min, so that afterwards
// c[0] multiplies the true lowest power: boundedness at r = 0 and the value of w/r^k at 0
// are then read off p_min alone, and no 0·r^(−1) term is ever evaluated at r = 0.
PolyPiece trimmed(PolyPiece p) {
  double largest = 0;
  for (double x : p.c) largest = std::max(largest, std::abs(x));
  std::size_t lo = 0, hi = p.c.size();
  while (lo < hi && negligible(p.c[lo], largest)) ++lo;
  while (hi > lo && negligible(p.c[hi - 1], largest)) --hi;
  p.p_min += static_cast<int>(lo);
  p.c = Poly(p.c.begin() + static_cast<long>(lo), p.c.begin() + static_cast<long>(hi));
  return p;
}

PolyPiece piece(double a, double b, const Poly& poly, int p_min = 0) {
  PolyPiece p;
  p.r_begin = a;
  p.r_end = b;
  p.p_min = p_min;
  p.c = poly;
  return trimmed(p);
}

std::vector<PolyPiece> whole(const Poly& poly) { return {piece(0, 1, poly)}; }

// d/dr of Σ c_k r^(p+k) = Σ (p+k) c_k r^(p+k−1); exact for Laurent pieces.
PolyPiece derivative_piece(const PolyPiece& p) {
  PolyPiece d = p;
  d.p_min = p.p_min - 1;
  for (std::size_t k = 0; k < p.c.size(); ++k) d.c[k] = p.c[k] * (p.p_min + static_cast<int>(k));
  return trimmed(d);
}

std::vector<PolyPiece> derivative_pieces(const std::vector<PolyPiece>& ps) {
  std::vector<PolyPiece> out;
  for (auto& p : ps) out.push_back(derivative_piece(p));
  return out;
}

// Lowest power with a nonzero coefficient (pieces are kept trimmed); a zero piece has
// no lowest power and counts as bounded everywhere.
int lowest_power(const PolyPiece& p) {
  return p.c.empty() ? std::numeric_limits<int>::max() : trimmed(p).p_min;
}

// Σ |c_k| r^(p+k): the size of the terms summed when evaluating at r.  Knot comparisons
// are made relative to it, because a difference of large cancelling terms cannot be
// more accurate than this.
double term_scale(const PolyPiece& p, double r) {
  double s = 0;
  for (std::size_t k = 0; k < p.c.size(); ++k)
    s += std::abs(p.c[k]) * std::pow(r, p.p_min + static_cast<int>(k));
  return s;
}

// The value at r = 0 from the lowest nonzero term: ±∞ for a negative power.
double value_at_zero(int p_min, const Poly& c) {
  for (std::size_t k = 0; k < c.size(); ++k) {
    if (c[k] == 0) continue;
    const int q = p_min + static_cast<int>(k);
    if (q < 0) return std::copysign(kInf, c[k]);
    return q == 0 ? c[k] : 0.0;
  }
  return 0.0;
}

// ---------------------------------------------------------------------------------
// GSL quadrature of r^m · p(r) over one piece.

struct MomentParams {
  const PolyPiece* p;
  int m;
};

double moment_integrand(double r, void* params) {
  auto* mp = static_cast<const MomentParams*>(params);
  return std::pow(r, mp->m) * mp->p->value(r);
}

// ∫_{r_begin}^{r_end} r^m p(r) dr by adaptive Gauss–Kronrod with extrapolation (qags),
// which also copes with integrable endpoint singularities.  Tolerances 1e-13 abs/rel give
// results good to 1e-12.  GSL's abort-on-error handler is switched off around the call
// (not thread-safe: properties are computed on one thread).
double integrate_piece(const PolyPiece& p, int m) {
  constexpr double kTol = 1e-13;
  constexpr std::size_t kLimit = 200;
  if (p.c.empty()) return 0.0;
  if (p.r_begin == 0 && lowest_power(p) + m <= -1)
    throw NumericalError("divergent integral of r^" + std::to_string(m) + "·w at r = 0");
  MomentParams params{&p, m};
  gsl_function f{&moment_integrand, &params};
  std::unique_ptr<gsl_integration_workspace, void (*)(gsl_integration_workspace*)> ws(
      gsl_integration_workspace_alloc(kLimit), gsl_integration_workspace_free);
  double result = 0, abserr = 0;
  gsl_error_handler_t* old = gsl_set_error_handler_off();
  const int status = gsl_integration_qags(&f, p.r_begin, p.r_end, kTol, kTol, kLimit, ws.get(),
                                          &result, &abserr);
  gsl_set_error_handler(old);
  if (status != GSL_SUCCESS && abserr > 1e-12 * std::max(1.0, std::abs(result)))
    throw NumericalError("quadrature of r^" + std::to_string(m) + "·w on [" +
                         std::to_string(p.r_begin) + ", " + std::to_string(p.r_end) +
                         "] failed: " + gsl_strerror(status));
  return result;
}

double integrate(const std::vector<PolyPiece>& ps, int m) {
  double s = 0;
  for (auto& p : ps) s += integrate_piece(p, m);
  return s;
}

// ---------------------------------------------------------------------------------
// Real roots and signs.

// Removes the factor (r − x0)^m when x0 is a root of multiplicity m (up to rounding).
// A root of multiplicity m comes back from the eigenvalue solver as a ring of radius
// ~eps^(1/m) around x0 (7e-4 for the quintic B-spline's (1−r)⁵), which would put spurious
// near-roots inside the piece; the pieces' endpoint roots are therefore divided out first.
Poly deflate(Poly q, double x0) {
  double scale = 0;
  for (std::size_t k = 0; k < q.size(); ++k) scale += std::abs(q[k]) * std::pow(std::abs(x0), k);
  while (q.size() > 1) {
    // Synthetic division q = (r − x0)·s + remainder.
    Poly s(q.size() - 1);
    double acc = q.back();
    for (std::size_t k = q.size() - 1; k-- > 0;) {
      s[k] = acc;
      acc = q[k] + x0 * acc;
    }
    if (std::abs(acc) > 1e-10 * scale) break;
    q = std::move(s);
  }
  return q;
}

// Real roots of the polynomial part of p strictly inside (r_begin, r_end).  The factor
// r^p_min has no roots there (r_begin ≥ 0).  Roots whose imaginary part is tiny are kept:
// an interior double root comes back as a pair ±1e-8·i, and w then touches 0 there.
std::vector<double> interior_roots(const PolyPiece& p) {
  const Poly c = deflate(deflate(trimmed(p).c, p.r_end), p.r_begin);
  if (c.size() < 2) return {};
  const std::size_t n = c.size();
  std::vector<double> z(2 * (n - 1));
  std::unique_ptr<gsl_poly_complex_workspace, void (*)(gsl_poly_complex_workspace*)> ws(
      gsl_poly_complex_workspace_alloc(n), gsl_poly_complex_workspace_free);
  gsl_error_handler_t* old = gsl_set_error_handler_off();
  const int status = gsl_poly_complex_solve(c.data(), n, ws.get(), z.data());
  gsl_set_error_handler(old);
  if (status != GSL_SUCCESS)
    throw NumericalError(std::string("polynomial root finding failed: ") + gsl_strerror(status));
  std::vector<double> roots;
  for (std::size_t k = 0; k + 1 < n; ++k) {
    const double re = z[2 * k], im = z[2 * k + 1];
    if (std::abs(im) <= 1e-6 * (1 + std::abs(re)) && re > p.r_begin && re < p.r_end)
      roots.push_back(re);
  }
  std::sort(roots.begin(), roots.end());
  return roots;
}

// [r_begin, roots..., r_end]: between consecutive points the piece has one sign.
std::vector<double> sign_intervals(const PolyPiece& p) {
  std::vector<double> pts{p.r_begin};
  for (double x : interior_roots(p)) pts.push_back(x);
  pts.push_back(p.r_end);
  return pts;
}

// Hypothesis 1.4, decided from the roots: no zero inside any piece, a positive value at
// every interior knot, and then one midpoint sample per piece settles the sign.
bool positive_on_open_unit_interval(const std::vector<PolyPiece>& ps) {
  for (auto& p : ps) {
    if (p.r_begin > 0 && !(p.value(p.r_begin) > 0)) return false;
    if (!interior_roots(p).empty()) return false;
    if (!(p.value(0.5 * (p.r_begin + p.r_end)) > 0)) return false;
  }
  return true;
}

// ∫ |r^m w| dr: the pieces split at their roots, so each part has one sign.
double integrate_abs(const std::vector<PolyPiece>& ps, int m) {
  double s = 0;
  for (auto& p : ps) {
    const auto pts = sign_intervals(p);
    for (std::size_t k = 0; k + 1 < pts.size(); ++k) {
      PolyPiece part = p;
      part.r_begin = pts[k];
      part.r_end = pts[k + 1];
      s += std::abs(integrate_piece(part, m));
    }
  }
  return s;
}

// ---------------------------------------------------------------------------------
// Continuity at knots.

bool agree(double left, double right, double scale) {
  return std::abs(left - right) <= 1e-12 * std::max(1.0, scale);
}

// The pieces, extended by 0 beyond r = 1, form a continuous function on [0,∞): bounded at
// r = 0, equal limits at every interior knot, and value 0 at r = 1⁻.
bool extends_continuously(const std::vector<PolyPiece>& ps) {
  if (ps.empty()) return true;
  if (ps.front().r_begin == 0 && lowest_power(ps.front()) < 0) return false;
  for (std::size_t i = 0; i + 1 < ps.size(); ++i) {
    const double x = ps[i].r_end;
    if (!agree(ps[i].value(x), ps[i + 1].value(x),
               std::max(term_scale(ps[i], x), term_scale(ps[i + 1], x))))
      return false;
  }
  const PolyPiece& last = ps.back();
  return agree(last.value(last.r_end), 0.0, term_scale(last, last.r_end));
}

// C¹ on [0,∞) after extension by 0: the function and its derivative extend continuously
// (a finite derivative at 0, matching one-sided derivatives at the knots, w'(1⁻) = 0).
bool extends_c1(const std::vector<PolyPiece>& ps) {
  return extends_continuously(ps) && extends_continuously(derivative_pieces(ps));
}

// sup over (0,1) is finite: only a piece that starts at r = 0 can blow up, and it does
// iff it has a negative power.
bool bounded_on_unit_interval(const std::vector<PolyPiece>& ps) {
  for (auto& p : ps)
    if (p.r_begin == 0 && lowest_power(p) < 0) return false;
  return true;
}

// imoto Hypothesis 2 with k (eq. (8)): sup|w/r^(k+1)| < ∞ and sup|(w/r^k)'| < ∞ on (0,1).
bool imoto_hypothesis2(const WeightFunction& w, int k) {
  return bounded_on_unit_interval(w.divided_by_power(k + 1)) &&
         bounded_on_unit_interval(derivative_pieces(w.divided_by_power(k)));
}

// Largest even-moment order of Hypothesis 1.1 (thesis Prop. 1.4): k = (first even l whose
// moment ∫ r^(d−1+l) w dr is nonzero) − 1; 99 if l = 2..10 all vanish.
int order_of(const std::vector<PolyPiece>& ps, int d) {
  for (int l = 2; l <= 10; l += 2) {
    const int m = d - 1 + l;
    if (std::abs(integrate(ps, m)) >= 1e-12 * integrate_abs(ps, m)) return l - 1;
  }
  return 99;
}

// ---------------------------------------------------------------------------------
// The document forms.

// Cubic B-spline (q = 2r, support 1): 1 − 6r² + 6r³ on [0,½), 2(1−r)³ on [½,1).
// The thesis prints the second piece as 2(1−r)²; `printed` builds that form.
std::vector<PolyPiece> cubic_bspline_shape(bool printed) {
  const Poly first = add(add(Poly{1}, monomial(2, -6)), monomial(3, 6));
  const Poly second = scaled(2, power(lin(1, -1), printed ? 2 : 3));
  return {piece(0, 0.5, first), piece(0.5, 1, second)};
}

// Quintic B-spline with q = 3r: (3−q)⁵ + s·6(2−q)⁵ + 15(1−q)⁵, each bracket present
// while it is positive.  The standard spline has s = −1; the thesis prints s = +1.
std::vector<PolyPiece> quintic_bspline_shape(double s) {
  const Poly t3 = power(lin(3, -3), 5);
  const Poly t2 = scaled(6 * s, power(lin(2, -3), 5));
  const Poly t1 = scaled(15, power(lin(1, -3), 5));
  return {piece(0, 1.0 / 3, add(add(t3, t2), t1)), piece(1.0 / 3, 2.0 / 3, add(t3, t2)),
          piece(2.0 / 3, 1, t3)};
}

// −(r/2) d/dr of each piece: the thesis' piecewise cubic/quintic polynomials (§4.1.2).
std::vector<PolyPiece> minus_half_r_derivative(const std::vector<PolyPiece>& shape) {
  std::vector<PolyPiece> out;
  for (auto& p : shape) {
    PolyPiece d = derivative_piece(p);
    d.p_min += 1;  // times r
    for (double& c : d.c) c *= -0.5;
    out.push_back(trimmed(d));
  }
  return out;
}

WeightFunction make(std::string name, std::string label, std::string source, std::string role,
                    double constant, std::vector<PolyPiece> shape, int dimension = 2) {
  WeightFunction w;
  w.name = std::move(name);
  w.label = std::move(label);
  w.source = std::move(source);
  w.role = std::move(role);
  w.constant = constant;
  w.shape = std::move(shape);
  w.dimension = dimension;
  return w;
}

const Poly one_minus_r = lin(1, -1);

std::vector<WeightFunction> build_registry() {
  const auto cb = cubic_bspline_shape(false);
  const auto qb = quintic_bspline_shape(-1);
  const double cb_const = 40 / (7 * kPi), qb_const = 63 / (478 * kPi);
  const Poly sq = power(one_minus_r, 2);                               // (1−r)²
  const Poly grad2_first = add(monomial(2, 6), monomial(3, -9));       // 6r² − 9r³
  const std::vector<PolyPiece> grad2{piece(0, 0.5, grad2_first),
                                     piece(0.5, 1, scaled(3, mul(monomial(1), sq)))};
  const std::string im = "imoto §5 ";
  std::vector<WeightFunction> r;
  // imoto §5: interpolant, gradient and Laplacian weights.
  r.push_back(make("Pi1", "(Π1) linear", im + "(Π1)", "interpolant", 3 / kPi, whole(one_minus_r)));
  r.push_back(make("Pi2", "(Π2) cubic B-spline", im + "(Π2)", "interpolant", cb_const, cb));
  r.push_back(make("Pi3", "(Π3) order-3 quadratic", im + "(Π3), constant corrected 5/π→6/π",
                   "interpolant", 6 / kPi, whole(mul(one_minus_r, lin(2, -3)))));
  r.push_back(make("Grad1", "(∇1) r(1−r)", im + "(∇1)", "gradient", 6 / kPi,
                   whole(mul(monomial(1), one_minus_r))));
  r.push_back(make("Grad2", "(∇2) SPH cubic B-spline gradient", im + "(∇2)", "gradient",
                   cb_const, grad2));
  r.push_back(make("Grad3", "(∇3) order-3 cubic", im + "(∇3)", "gradient", 15 / (2 * kPi),
                   whole(mul(mul(monomial(1), one_minus_r), lin(5, -7)))));
  r.push_back(make("Lap1", "(Δ1) r²(1−r)", im + "(Δ1)", "laplacian", 10 / kPi,
                   whole(mul(monomial(2), one_minus_r))));
  r.push_back(make("Lap2", "(Δ2) SPH cubic B-spline Laplacian", im + "(Δ2)", "laplacian",
                   cb_const, grad2));
  r.push_back(make("Lap3", "(Δ3) order-3 quartic", im + "(Δ3)", "laplacian", 30 / kPi,
                   whole(mul(mul(monomial(2), one_minus_r), lin(3, -4)))));
  // thesis Ch. 4.
  r.push_back(make("cubic_bspline", "cubic B-spline",
                   "thesis §4.1.1 w^CB, 2nd piece corrected 2(1−r)²→2(1−r)³", "interpolant",
                   cb_const, cb));
  r.push_back(make("quintic_bspline", "quintic B-spline",
                   "thesis §4.1.1 w^QB, corrected 578→478 and +6→−6", "interpolant", qb_const,
                   qb));
  r.push_back(make("quadratic_spike", "quadratic spike", "thesis (4.1)", "interpolant", 6 / kPi,
                   whole(sq)));
  r.push_back(make("cubic_spike", "cubic spike", "thesis §4.1.1", "interpolant", 5 / kPi,
                   whole(mul(sq, lin(4, -7)))));
  r.push_back(make("quartic_polynomial", "quartic polynomial", "thesis §4.1.2 w^QP",
                   "gradient+laplacian", 60 / (2 * kPi), whole(mul(monomial(2), sq))));
  r.push_back(make("piecewise_cubic_polynomial", "piecewise cubic polynomial",
                   "thesis §4.1.2 w^PCP = −(r/2) dw^CB/dr", "gradient+laplacian", cb_const,
                   minus_half_r_derivative(cb)));
  r.push_back(make("piecewise_quintic_polynomial", "piecewise quintic polynomial",
                   "thesis §4.1.2 w^PQP = −(r/2) dw^QB/dr", "gradient+laplacian", qb_const,
                   minus_half_r_derivative(qb)));
  // thesis Example 1.7: minimal-degree constructions of Hypothesis 1.1 with k = 1 and 3.
  r.push_back(make("example17_quadratic_2d", "Ex. 1.7 quadratic (d=2)", "thesis Example 1.7",
                   "interpolant", 6 / kPi, whole(sq)));
  r.push_back(make("example17_cubic_2d", "Ex. 1.7 cubic (d=2)", "thesis Example 1.7",
                   "interpolant", 35 / (7 * kPi), whole(mul(sq, lin(4, -7)))));
  r.push_back(make("example17_quadratic_3d", "Ex. 1.7 quadratic (d=3)", "thesis Example 1.7",
                   "interpolant", 15 / (2 * kPi), whole(sq), 3));
  r.push_back(make("example17_cubic_3d", "Ex. 1.7 cubic (d=3)", "thesis Example 1.7",
                   "interpolant", 15 / (2 * kPi), whole(mul(sq, lin(5, -8))), 3));
  // MPS: 1/r − 1 = r^(−1)·(1 − r); unbounded at 0, outside the admissible set.
  r.push_back(make("mps", "MPS 1/r − 1", "thesis (A.13); imoto Remark 6", "mps", 1,
                   {piece(0, 1, one_minus_r, -1)}));
  return r;
}

std::string fmt6(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6f", v);
  return buf;
}

// Largest |jump| of the value at an interior knot, and where.
std::pair<double, double> largest_knot_jump(const std::vector<PolyPiece>& ps) {
  std::pair<double, double> out{0, 0};
  for (std::size_t i = 0; i + 1 < ps.size(); ++i) {
    const double x = ps[i].r_end, jump = ps[i + 1].value(x) - ps[i].value(x);
    if (std::abs(jump) > std::abs(out.second)) out = {x, jump};
  }
  return out;
}

bool same_pieces(const std::vector<PolyPiece>& a, const std::vector<PolyPiece>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i].r_begin != b[i].r_begin || a[i].r_end != b[i].r_end || a[i].p_min != b[i].p_min ||
        a[i].c != b[i].c)
      return false;
  return true;
}

WeightErratum erratum_pi3() {
  const WeightFunction& fixed = weight("Pi3");
  WeightFunction printed = fixed;
  printed.constant = 5 / kPi;
  const double shape_norm = compute_properties(make("", "", "", "", 1, fixed.shape)).norm_2d;
  const auto pp = compute_properties(printed), fp = compute_properties(fixed);
  WeightErratum e;
  e.name = "Pi3";
  e.source = "imoto §5 (Π3)";
  e.printed = "5/π (1−r)(2−3r)";
  e.corrected = "6/π (1−r)(2−3r)";
  e.printed_norm_2d = pp.norm_2d;
  e.corrected_norm_2d = fp.norm_2d;
  e.evidence = "printed form integrates to " + fmt6(pp.norm_2d) + " (5/6); 1/(2π∫r(1−r)(2−3r)dr) = " + fmt6(kPi / shape_norm) +
               "/π, so the constant is 6/π; the shape is right (order k = " +
               std::to_string(fp.order_k) + " as stated)";
  return e;
}

WeightErratum erratum_cubic_bspline() {
  const WeightFunction& fixed = weight("cubic_bspline");
  WeightFunction printed = fixed;
  printed.shape = cubic_bspline_shape(true);
  const auto pp = compute_properties(printed), fp = compute_properties(fixed);
  const auto [x, jump] = largest_knot_jump(printed.shape);
  WeightErratum e;
  e.name = "cubic_bspline";
  e.source = "thesis §4.1.1 w^CB";
  e.printed = "40/(7π){1−6r²+6r³ on [0,½); 2(1−r)² on [½,1)}";
  e.corrected = "40/(7π){1−6r²+6r³ on [0,½); 2(1−r)³ on [½,1)}";
  e.printed_norm_2d = pp.norm_2d;
  e.corrected_norm_2d = fp.norm_2d;
  e.evidence = "printed form integrates to " + fmt6(pp.norm_2d) + " and is discontinuous at r=" +
               fmt6(x) + " (bracket jumps by " + fmt6(jump) + ", w by " +
               fmt6(fixed.constant * jump) + "); with 2(1−r)³ it integrates to " +
               fmt6(fp.norm_2d) + (fp.c1 ? ", is C¹" : ", is not C¹") +
               (same_pieces(fixed.shape, weight("Pi2").shape) ? " and equals imoto (Π2)"
                                                              : " but differs from imoto (Π2)");
  return e;
}

WeightErratum erratum_quintic_bspline() {
  const WeightFunction& fixed = weight("quintic_bspline");
  const double printed_const = 63 / (578 * kPi);
  const auto norm_of = [](double c, double s) {
    return compute_properties(make("", "", "", "", c, quintic_bspline_shape(s))).norm_2d;
  };
  WeightFunction printed = fixed;
  printed.constant = printed_const;
  printed.shape = quintic_bspline_shape(+1);
  const auto fp = compute_properties(fixed);
  WeightErratum e;
  e.name = "quintic_bspline";
  e.source = "thesis §4.1.1 w^QB";
  e.printed = "63/(578π){(3−3r)⁵+6(2−3r)⁵+15(1−3r)⁵; (3−3r)⁵+6(2−3r)⁵; (3−3r)⁵}";
  e.corrected = "63/(478π){(3−3r)⁵−6(2−3r)⁵+15(1−3r)⁵; (3−3r)⁵−6(2−3r)⁵; (3−3r)⁵}";
  e.printed_norm_2d = compute_properties(printed).norm_2d;
  e.corrected_norm_2d = fp.norm_2d;
  e.evidence = "printed form integrates to " + fmt6(e.printed_norm_2d) +
               "; fixing only 578→478 gives " + fmt6(norm_of(63 / (478 * kPi), +1)) +
               ", only +6→−6 gives " + fmt6(norm_of(printed_const, -1)) + ", both give " +
               fmt6(fp.norm_2d) + " (the standard quintic B-spline, 7/(478πh²) with q = 3r); " +
               "w(0) printed " + fmt6(printed.value(0)) + " vs corrected " + fmt6(fixed.value(0));
  return e;
}

}  // namespace

// ---------------------------------------------------------------------------------
// PolyPiece and WeightFunction.

double PolyPiece::value(double r) const {
  if (r == 0) return value_at_zero(p_min, c);
  double s = 0;
  for (std::size_t k = c.size(); k-- > 0;) s = s * r + c[k];
  return s * std::pow(r, p_min);
}

double PolyPiece::derivative(double r) const {
  if (r == 0) return derivative_piece(*this).value(0);
  double s = 0;
  for (std::size_t k = c.size(); k-- > 0;) s = s * r + c[k] * (p_min + static_cast<int>(k));
  return s * std::pow(r, p_min - 1);
}

// Support is [0,1): outside it (r ≥ 1, and r < 0, which is no distance) w = w' = 0.
double WeightFunction::value(double r) const {
  if (!(r >= 0 && r < 1)) return 0.0;
  for (auto& p : shape)
    if (r < p.r_end) return constant * p.value(r);
  return 0.0;
}

double WeightFunction::derivative(double r) const {
  if (!(r >= 0 && r < 1)) return 0.0;
  for (auto& p : shape)
    if (r < p.r_end) return constant * p.derivative(r);
  return 0.0;
}

std::vector<PolyPiece> WeightFunction::scaled_pieces() const {
  std::vector<PolyPiece> out = shape;
  for (auto& p : out)
    for (double& x : p.c) x *= constant;
  return out;
}

std::vector<PolyPiece> WeightFunction::divided_by_power(int k) const {
  std::vector<PolyPiece> out = scaled_pieces();
  for (auto& p : out) p.p_min -= k;
  return out;
}

// ---------------------------------------------------------------------------------
// Registry.

const std::vector<WeightFunction>& weight_registry() {
  static const std::vector<WeightFunction> registry = build_registry();
  return registry;
}

const WeightFunction& weight(const std::string& name) {
  for (auto& w : weight_registry())
    if (w.name == name) return w;
  std::string valid;
  for (auto& n : weight_names()) valid += (valid.empty() ? "" : ", ") + n;
  throw InputError("unknown weight '" + name + "'; valid: " + valid);
}

std::vector<std::string> weight_names() {
  std::vector<std::string> out;
  for (auto& w : weight_registry()) out.push_back(w.name);
  return out;
}

// ---------------------------------------------------------------------------------
// Properties.

WeightProperties compute_properties(const WeightFunction& w) {
  const auto ps = w.scaled_pieces();
  WeightProperties p;
  p.norm_2d = 2 * kPi * integrate(ps, 1);
  p.norm_3d = 4 * kPi * integrate(ps, 2);
  p.order_k = order_of(ps, w.dimension);
  p.positive = positive_on_open_unit_interval(ps);
  p.p0 = lowest_power(ps.front());
  p.continuous = extends_continuously(ps);
  p.c1 = extends_c1(ps);
  p.hyp_1_2 = extends_c1(w.divided_by_power(1));
  p.hyp_1_3 = extends_c1(w.divided_by_power(2));
  for (int k = 0; k <= 3; ++k)
    if (imoto_hypothesis2(w, k)) p.imoto_hyp2_k = k;
  // w/r is integrable at 0 iff p0 ≥ 1; decide divergence from p0, not from the quadrature.
  p.inv_r2_integral = p.p0 <= 0 ? std::copysign(kInf, trimmed(ps.front()).c.front())
                                : 2 * kPi * integrate(ps, -1);
  bool nonnegative_powers = true;
  for (auto& piece : ps) nonnegative_powers = nonnegative_powers && lowest_power(piece) >= 0;
  p.admissible = p.continuous && std::abs(p.norm(w.dimension) - 1) < 1e-12 && nonnegative_powers;
  return p;
}

std::vector<WeightErratum> weight_errata() {
  return {erratum_pi3(), erratum_cubic_bspline(), erratum_quintic_bspline()};
}

}  // namespace gpm
