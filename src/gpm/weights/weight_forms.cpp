// The documents' weight formulas as printed (weight_forms.hpp): each entered as a
// prefactor and a bracketed product and expanded by the polynomial algebra
// (piece_algebra.hpp), so that no coefficient is typed by hand.
#include "gpm/weights/weight_forms.hpp"

#include <utility>

#include "gpm/weights/piece_algebra.hpp"

namespace gpm::forms {

using namespace pieces;  // the polynomial algebra (piece_algebra.hpp)

std::vector<PolyPiece> cubic_bspline_shape(bool printed) {
  const Poly first = add(add(Poly{1}, monomial(2, -6)), monomial(3, 6));
  const Poly second = scaled(2, power(lin(1, -1), printed ? 2 : 3));
  return {piece(0, 0.5, first), piece(0.5, 1, second)};
}

std::vector<PolyPiece> quintic_bspline_shape(double s) {
  const Poly t3 = power(lin(3, -3), 5);
  const Poly t2 = scaled(6 * s, power(lin(2, -3), 5));
  const Poly t1 = scaled(15, power(lin(1, -3), 5));
  return {piece(0, 1.0 / 3, add(add(t3, t2), t1)), piece(1.0 / 3, 2.0 / 3, add(t3, t2)),
          piece(2.0 / 3, 1, t3)};
}

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
                    double constant, std::vector<PolyPiece> shape, int dimension) {
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

}  // namespace gpm::forms
