// The weight errata: the printed formulas of the documents that are wrong (a constant that
// does not normalize, a piece that breaks continuity), each with its printed and corrected
// form and the evidence computed from both (normalization, continuity at the knots,
// comparison with the other document's weight).  The registry (weight_registry.cpp) holds
// the corrected forms; here the printed ones are rebuilt with the same builders
// (weight_forms.hpp) and measured.
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "gpm/weights/weight_forms.hpp"
#include "gpm/weights/weights.hpp"

namespace gpm {
namespace {

using namespace forms;  // the document forms (weight_forms.hpp)

constexpr double kPi = std::numbers::pi;

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

// Each erratum: the weight's name and source, its printed and corrected forms, the computed
// evidence, and the two normalizations (WeightErratum's fields, in order).

WeightErratum erratum_pi3() {
  const WeightFunction& fixed = weight("Pi3");
  WeightFunction printed = fixed;
  printed.constant = 5 / kPi;
  const double shape_norm = compute_properties(make("", "", "", "", 1, fixed.shape)).norm_2d;
  const auto pp = compute_properties(printed), fp = compute_properties(fixed);
  std::string evidence = "printed form integrates to " + fmt6(pp.norm_2d) +
                         " (5/6); 1/(2π∫r(1−r)(2−3r)dr) = " + fmt6(kPi / shape_norm) +
                         "/π, so the constant is 6/π; the shape is right (order k = " +
                         std::to_string(fp.order_k) + " as stated)";
  return {"Pi3", "imoto §5 (Π3)", "5/π (1−r)(2−3r)", "6/π (1−r)(2−3r)", std::move(evidence),
          pp.norm_2d, fp.norm_2d};
}

WeightErratum erratum_cubic_bspline() {
  const WeightFunction& fixed = weight("cubic_bspline");
  WeightFunction printed = fixed;
  printed.shape = cubic_bspline_shape(true);
  const auto pp = compute_properties(printed), fp = compute_properties(fixed);
  const auto [x, jump] = largest_knot_jump(printed.shape);
  std::string evidence =
      "printed form integrates to " + fmt6(pp.norm_2d) + " and is discontinuous at r=" +
      fmt6(x) + " (bracket jumps by " + fmt6(jump) + ", w by " + fmt6(fixed.constant * jump) +
      "); with 2(1−r)³ it integrates to " + fmt6(fp.norm_2d) +
      (fp.c1 ? ", is C¹" : ", is not C¹") +
      (same_pieces(fixed.shape, weight("Pi2").shape) ? " and equals imoto (Π2)"
                                                     : " but differs from imoto (Π2)");
  return {"cubic_bspline", "thesis §4.1.1 w^CB",
          "40/(7π){1−6r²+6r³ on [0,½); 2(1−r)² on [½,1)}",
          "40/(7π){1−6r²+6r³ on [0,½); 2(1−r)³ on [½,1)}", std::move(evidence), pp.norm_2d,
          fp.norm_2d};
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
  const double printed_norm = compute_properties(printed).norm_2d;
  std::string evidence =
      "printed form integrates to " + fmt6(printed_norm) + "; fixing only 578→478 gives " +
      fmt6(norm_of(63 / (478 * kPi), +1)) + ", only +6→−6 gives " +
      fmt6(norm_of(printed_const, -1)) + ", both give " + fmt6(fp.norm_2d) +
      " (the standard quintic B-spline, 7/(478πh²) with q = 3r); " + "w(0) printed " +
      fmt6(printed.value(0)) + " vs corrected " + fmt6(fixed.value(0));
  return {"quintic_bspline", "thesis §4.1.1 w^QB",
          "63/(578π){(3−3r)⁵+6(2−3r)⁵+15(1−3r)⁵; (3−3r)⁵+6(2−3r)⁵; (3−3r)⁵}",
          "63/(478π){(3−3r)⁵−6(2−3r)⁵+15(1−3r)⁵; (3−3r)⁵−6(2−3r)⁵; (3−3r)⁵}",
          std::move(evidence), printed_norm, fp.norm_2d};
}

}  // namespace

std::vector<WeightErratum> weight_errata() {
  return {erratum_pi3(), erratum_cubic_bspline(), erratum_quintic_bspline()};
}

}  // namespace gpm
