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
#include "gpm/weights/piece_algebra.hpp"

namespace gpm {
namespace {

using namespace pieces;  // the polynomial algebra (piece_algebra.hpp)

constexpr double kPi = std::numbers::pi;
constexpr double kInf = std::numeric_limits<double>::infinity();

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
