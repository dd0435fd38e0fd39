// Reference weight functions w(r), supported on [0,1), and their computed properties.
//
// Every weight named in the three documents is a piecewise Laurent polynomial in r:
//   w(r) = Σ_k c[k] · r^(p_min + k)   on [r_begin, r_end)
// (p_min = −1 only for the MPS weight 1/r − 1).  The kernel evaluates the pieces as plain
// coefficients; nothing calls through a function pointer per pair.  Each weight carries
// the prefactor the document prints (`constant`) separately from the bracketed
// polynomial (`shape`), so the normalization can be *computed* and a printed constant
// that does not normalize to 1 is caught (see weight_errata()).
//
// Where: the registry in weight_registry.cpp, the errata in weight_errata.cpp (both built
// from the printed formulas of weight_forms.hpp), evaluation and properties in weights.cpp,
// the polynomial algebra under them in piece_algebra.hpp.
#pragma once
#include <string>
#include <vector>

namespace gpm {

struct PolyPiece {
  double r_begin = 0, r_end = 1;  // the piece holds on [r_begin, r_end)
  int p_min = 0;                  // power of the first coefficient
  std::vector<double> c;          // c[k] multiplies r^(p_min + k)
  double value(double r) const;
  double derivative(double r) const;
};

struct WeightFunction {
  std::string name;     // registry key, e.g. "quadratic_spike", "Pi3"
  std::string label;    // for figures and tables, e.g. "quadratic spike"
  std::string source;   // document and equation, e.g. "thesis (4.1)"
  std::string role;     // "interpolant", "gradient", "laplacian", "any", "mps"
  double constant = 1;  // the prefactor (γ) as used: w = constant · shape
  std::vector<PolyPiece> shape;  // pieces without the prefactor, covering [0,1)
  int dimension = 2;    // d in which the constant normalizes w (3 for the 3-D examples)

  double value(double r) const;       // w(r); 0 for r ≥ 1
  double derivative(double r) const;  // dw/dr; 0 for r > 1
  // The pieces with the constant folded in (what the kernel uses).
  std::vector<PolyPiece> scaled_pieces() const;
  // w(r)/r^k as pieces (shifts p_min); exact for polynomial pieces.
  std::vector<PolyPiece> divided_by_power(int k) const;
};

// Properties computed from the pieces (normalization by GSL quadrature).
struct WeightProperties {
  double norm_2d = 0;          // 2π ∫₀¹ r w(r) dr          (must be 1 for w ∈ W, d = 2)
  double norm_3d = 0;          // 4π ∫₀¹ r² w(r) dr         (for the d = 3 examples)
  int order_k = 0;             // Hypothesis 1.1 / imoto Hypothesis 1: largest k (in w.dimension); 99 = all tested
  bool positive = false;       // Hypothesis 1.4: w(r) > 0 on (0,1)
  int p0 = 0;                  // lowest power of r at 0 (first piece)
  bool continuous = false;     // w continuous on [0,∞) (incl. w(1) = 0)
  bool c1 = false;             // w ∈ C¹ on [0,∞) (thesis W requires it)
  bool hyp_1_2 = false;        // thesis Hypothesis 1.2: w/r  extends to C¹(R₀⁺)
  bool hyp_1_3 = false;        // thesis Hypothesis 1.3: w/r² extends to C¹(R₀⁺)
  int imoto_hyp2_k = -1;       // largest k ≤ 3 with imoto Hypothesis 2 (−1: none)
  double inv_r2_integral = 0;  // ∫_{R²} w(|x|)/|x|² dx = 2π ∫ w(r)/r dr (inf if divergent)
  bool admissible = false;     // in the admissible set W (continuous, normalized, w(1)=0)
  // The normalization in dimension d (norm_2d or norm_3d).
  double norm(int d) const { return d == 3 ? norm_3d : norm_2d; }
};

const std::vector<WeightFunction>& weight_registry();
// Throws InputError listing the valid names if `name` is unknown.
const WeightFunction& weight(const std::string& name);
std::vector<std::string> weight_names();
WeightProperties compute_properties(const WeightFunction& w);

// One row per formula whose printed form is wrong (normalization or shape), with the
// printed and corrected forms and the computed evidence.
struct WeightErratum {
  std::string name, source, printed, corrected, evidence;
  double printed_norm_2d = 0, corrected_norm_2d = 0;
};
std::vector<WeightErratum> weight_errata();

}  // namespace gpm
