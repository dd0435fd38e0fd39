// The documents' weight formulas as they are printed: the builders that both the registry
// (weight_registry.cpp: the corrected forms) and the errata (weight_errata.cpp: the printed
// forms that do not normalize) need, so that a printed and a corrected form differ only in
// the argument that the erratum names.  Internal to the weights layer.
#pragma once
#include <string>
#include <vector>

#include "gpm/weights/weights.hpp"

namespace gpm::forms {

// Cubic B-spline (q = 2r, support 1): 1 − 6r² + 6r³ on [0,½), 2(1−r)³ on [½,1).
// The thesis prints the second piece as 2(1−r)²; `printed` builds that form.
std::vector<PolyPiece> cubic_bspline_shape(bool printed);

// Quintic B-spline with q = 3r: (3−q)⁵ + s·6(2−q)⁵ + 15(1−q)⁵, each bracket present
// while it is positive.  The standard spline has s = −1; the thesis prints s = +1.
std::vector<PolyPiece> quintic_bspline_shape(double s);

// −(r/2) d/dr of each piece: the thesis' piecewise cubic/quintic polynomials (§4.1.2).
std::vector<PolyPiece> minus_half_r_derivative(const std::vector<PolyPiece>& shape);

// A weight from its document entry: name, label, source, role, the prefactor and the
// bracketed shape, and the dimension d in which the prefactor normalizes it.
WeightFunction make(std::string name, std::string label, std::string source, std::string role,
                    double constant, std::vector<PolyPiece> shape, int dimension = 2);

}  // namespace gpm::forms
