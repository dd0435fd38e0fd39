// The polynomial algebra of the weight functions' pieces: arithmetic on coefficient vectors,
// pieces and their derivatives, GSL quadrature of moments, real roots and signs, continuity
// at the knots (piece_algebra.hpp).
#include "gpm/weights/piece_algebra.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_poly.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include "gpm/error.hpp"

namespace gpm::pieces {

constexpr double kInf = std::numeric_limits<double>::infinity();

// ---------------------------------------------------------------------------------
// Polynomial arithmetic on coefficient vectors: p[k] multiplies r^k.


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

Poly monomial(int p, double c) {
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

PolyPiece piece(double a, double b, const Poly& poly, int p_min) {
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

namespace {
struct MomentParams {
  const PolyPiece* p;
  int m;
};

double moment_integrand(double r, void* params) {
  auto* mp = static_cast<const MomentParams*>(params);
  return std::pow(r, mp->m) * mp->p->value(r);
}

}  // namespace

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
namespace {
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
}  // namespace

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

}  // namespace gpm::pieces
