// The weight registry: every weight named in the three documents, by name, with the
// documents' formulas (corrected where the printed form is wrong: the errata,
// weight_errata.cpp, give the evidence).  Built once, on first use.
//
// Every formula is entered the way the document prints it — a prefactor and a bracketed
// product such as (1−r)²(4−7r) — and expanded into monomials by the polynomial algebra
// (piece_algebra.hpp) and the document forms (weight_forms.hpp), so that no coefficient is
// typed by hand.
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "gpm/error.hpp"
#include "gpm/weights/piece_algebra.hpp"
#include "gpm/weights/weight_forms.hpp"
#include "gpm/weights/weights.hpp"

namespace gpm {
namespace {

using namespace pieces;  // the polynomial algebra (piece_algebra.hpp)
using namespace forms;   // the document forms (weight_forms.hpp)

constexpr double kPi = std::numbers::pi;

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

}  // namespace

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

}  // namespace gpm
