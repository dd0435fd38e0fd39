// The polynomial algebra behind the weight registry (weight_forms.cpp,
// weight_registry.cpp): a weight is entered as the document prints it and expanded here,
// and every property (weights.cpp) is computed here from its pieces.  A polynomial is a
// coefficient vector, p[k] multiplying r^k.
#pragma once
#include <vector>

#include "gpm/weights/weights.hpp"

namespace gpm::pieces {

using Poly = std::vector<double>;

// Arithmetic.
Poly add(Poly a, const Poly& b);
Poly scaled(double s, Poly a);
Poly mul(const Poly& a, const Poly& b);
Poly power(const Poly& a, int n);
Poly monomial(int p, double c = 1.0);  // c·r^p
Poly lin(double a, double b);          // a + b·r

// Pieces: one polynomial on [a, b), times r^p_min (p_min < 0: a negative power).
PolyPiece trimmed(PolyPiece p);
PolyPiece piece(double a, double b, const Poly& poly, int p_min = 0);
std::vector<PolyPiece> whole(const Poly& poly);  // one piece on [0, 1)
PolyPiece derivative_piece(const PolyPiece& p);
std::vector<PolyPiece> derivative_pieces(const std::vector<PolyPiece>& ps);
int lowest_power(const PolyPiece& p);
double term_scale(const PolyPiece& p, double r);
double value_at_zero(int p_min, const Poly& c);

// Moments ∫ r^m p(r) dr (GSL adaptive quadrature), of one piece, of all, of |p|.
double integrate_piece(const PolyPiece& p, int m);
double integrate(const std::vector<PolyPiece>& ps, int m);
double integrate_abs(const std::vector<PolyPiece>& ps, int m);

// Real roots and signs.
std::vector<double> interior_roots(const PolyPiece& p);
std::vector<double> sign_intervals(const PolyPiece& p);
bool positive_on_open_unit_interval(const std::vector<PolyPiece>& ps);

// Continuity at the knots and boundedness on (0, 1).
bool agree(double left, double right, double scale);
bool extends_continuously(const std::vector<PolyPiece>& ps);
bool extends_c1(const std::vector<PolyPiece>& ps);
bool bounded_on_unit_interval(const std::vector<PolyPiece>& ps);

}  // namespace gpm::pieces
