// Koba & Sato, "Truncation error analysis of approximate operators for a moving particle
// semi-implicit method": the operators of Definition 1.2 and the constants c₁ … c₁₂ of
// Theorems 1.3–1.6, evaluated on actual Voronoi cells.
//
// The operators weight neighbour i of a_k by V_i(a_k) = |σ_i ∩ B_{h,δ}(a_k)|, the area of
// its Voronoi cell cut by the annulus δ < |y − a_k| < h, and the constants are ratios of
// L¹ norms ‖|a_k − ·|ⁿ w(a_k − ·)‖ over regions built from discs and the cell σ_k.  Both
// reduce to one integral, ∫_{P ∩ B_R(c)} |y − c|^q dy over a polygon P, which has a closed
// form: split P into the signed triangles (c, v_j, v_{j+1}); inside the disc each triangle
// contributes an elementary integral along its edge, outside it a circular sector.  The
// areas are therefore exact up to rounding, with no quadrature anywhere.
//
// Notation follows the paper: h the radius of the interaction area, δ the inner radius
// (B_δ(a_k) ⊂ σ_k), r_σ = max_i max_{y∈σ̄_i} |y − a_i|, λ ∈ (0,1) the ring split,
// R(a_k, h) = {i ≠ k : |a_k − a_i| < h}.
#pragma once
#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "gpm/geometry/domain.hpp"
#include "gpm/geometry/voronoi.hpp"
#include "gpm/weights/weights.hpp"

namespace gpm {

// A polygon as vertex arrays, counter-clockwise (voronoi_cells' orientation).  A clockwise
// polygon gives the negative of every integral below.
struct PolygonView {
  const double* x = nullptr;
  const double* y = nullptr;
  std::size_t n = 0;
};
// Cell i of a decomposition computed with keep_polygons (InputError otherwise).
PolygonView cell_polygon(const VoronoiCells& cells, std::size_t i);

// ∫_{P ∩ B_R(c)} |y − c|^q dy for an integer q ≥ −1 (closed form; q = 0 is the area).
double polygon_disc_moment(const PolygonView& P, double cx, double cy, double R, int q);
double polygon_disc_area(const PolygonView& P, double cx, double cy, double R);
// |P ∩ B_{r_out, r_in}(c)| = outer disc minus inner disc.
double polygon_annulus_area(const PolygonView& P, double cx, double cy, double r_in,
                            double r_out);
// ∫_{B_R} |y|^q dy = 2π R^{q+2}/(q+2).
double disc_moment(double R, int q);
// Distance from (cx, cy) to the boundary of P (the largest δ with B_δ(c) ⊂ P, c inside P).
double polygon_boundary_distance(const PolygonView& P, double cx, double cy);

// A radial weight w(x) = ŵ(|x|) on the closed annulus δ ≤ |x| ≤ h, zero elsewhere
// (Assumption 1.1 (ii), (iv)), stored as Laurent-polynomial pieces in r itself.
struct KsWeight {
  std::string name;
  double delta = 0, h = 0;
  std::vector<PolyPiece> pieces;  // cover [δ, h]; no power below r^0 (w bounded)
  double lipschitz = 0;           // L_w of Assumption 1.1 (iii) on the closed annulus
  double value(double r) const;   // ŵ(r) for δ ≤ r ≤ h, else 0
  // ‖|·|ⁿ w‖ over the annulus r_in < |y| < r_out (n ≥ −1): closed form.
  double norm_annulus(int n, double r_in, double r_out) const;
  // ‖|c − ·|ⁿ w(c − ·)‖ over P ∩ {r_in < |y − c| < r_out}.
  double norm_polygon(int n, const PolygonView& P, double cx, double cy, double r_in,
                      double r_out) const;
};
// Section 7: w = 1 on the closed annulus, L_w = 0.
KsWeight ks_step_weight(double delta, double h);
// ŵ(r) = W(r/h) on [δ, h] for a registry weight W (its constant included; the operators and
// constants are ratios, so the scale drops out).  L_w = max |ŵ'| on [δ, h], from the pieces'
// derivative at the ends and at the real roots of ŵ''.  InputError if W is unbounded at 0
// or has a jump inside [δ, h] (not Lipschitz).
KsWeight ks_scaled_weight(const WeightFunction& W, double delta, double h);
// "step" or a registry name.
KsWeight ks_weight(const std::string& name, double delta, double h);

// Everything about the neighbourhood of a_k that does not depend on the weight.
struct KsSite {
  std::size_t k = 0;
  double ax = 0, ay = 0, h = 0, delta = 0, r_sigma = 0;
  std::vector<std::size_t> idx;        // R(a_k, h)
  std::vector<double> dx, dy, dist, V;  // a_i − a_k, |a_i − a_k|, V_i(a_k)
  double cell_area = 0;                 // |σ_k|
  double delta_max = 0;                 // dist(a_k, ∂σ_k): B_δ(a_k) ⊂ σ_k iff δ ≤ this
  // The paper assumes B_h(a_k) ⊂ ∪_{i∈R̄(a_k,h)} σ̄_i.  uncovered = πh² − Σ_{R̄}|σ_i ∩ B_h(a_k)|
  // is the area of B_h(a_k) in cells of particles at distance ≥ h (0 iff the assumption holds).
  double uncovered = 0;
  // (2.6) claims sup_{y∈σ_i}|y − a_i| ≤ |a_k − a_i| for i ∈ R(a_k, h); the largest ratio.
  double ratio_2_6 = 0;
};
// Checks the paper's standing assumptions that can be checked (InputError naming the one
// violated): r_σ < h, 0 < δ ≤ dist(a_k, ∂σ_k), a_k ∈ Ω, B_δ(a_k) ⊂ Ω, B_{h+r_σ+δ}(a_k) ⊂ Ω_H.
KsSite ks_site(const Particles& p, const VoronoiCells& cells, std::size_t k, double h,
               double delta, double r_sigma, const Domain& dom = Domain{});

// Definition 1.2 at a_k.  f_nb[j] = f(a_i) for i = site.idx[j]; w_nb[j] = ŵ(|a_k − a_i|).
struct KsOps {
  double pi = 0, gx = 0, gy = 0, lap = 0, box = 0;
};
std::vector<double> ks_neighbour_weights(const KsSite& s, const KsWeight& w);
KsOps ks_operators(const KsSite& s, const std::vector<double>& w_nb, const double* f_nb,
                   double f_k);

// The constants of Theorems 1.3–1.6 (c[1..12]) and the norms they are made of; index
// n + 1 holds the norm of |a_k − ·|ⁿ w(a_k − ·) for n = −1, 0, 1, 2.
struct KsConstants {
  std::array<double, 13> c{};  // c[0] unused
  std::array<double, 4> A{};   // over B_h(a_k) \ B_δ(a_k)
  std::array<double, 4> S{};   // over σ_k \ B_δ(a_k)
  std::array<double, 4> O{};   // over B_h(a_k) \ σ_k
  std::array<double, 4> Lam{};  // over B_{λh+r_σ}(a_k) \ σ_k
  double D0 = 0, D1 = 0, D2 = 0;  // Σ_{R(a_k,h)} V_j |a_k − a_j|^m w(a_k − a_j), m = 0, 1, 2
  double Dlam = 0;                // Σ_{R(a_k,λh)} V_i w(a_k − a_i)/|a_k − a_i|
  bool lambda_ok = false;         // R(a_k, λh) ≠ ∅ (hypothesis of Theorems 1.4–1.6)
};
KsConstants ks_constants(const KsSite& s, const std::vector<double>& w_nb, const KsWeight& w,
                         const PolygonView& cell_k, double lambda);

// The right-hand sides of Theorems 1.3–1.6 for seminorms |f|_{C^j}, j = 0..3.
// lap is Theorem 1.5 as printed (4 Σ_{i=4}^{7} c_i); lap_lemmas adds the 4c₈ of (5.4).
struct KsBounds {
  double pi = 0, grad = 0, lap = 0, lap_lemmas = 0, box = 0;
};
KsBounds ks_bounds(const KsConstants& c, double h, double r_sigma, double lambda,
                   const std::array<double, 4>& seminorm);

// Test functions with every derivative known and the seminorms |f|_{C^j(Ω̄_H)}, j = 0..3,
// in closed form for Ω_H = (−0.1, 1.1)² (Domain{}).
struct KsFunction {
  std::string name, formula;
  double (*d)(int a1, int a2, double x, double y);  // D^α f, |α| ≤ 3
  std::array<double, 4> seminorm;
};
const std::vector<KsFunction>& ks_functions();
const KsFunction& ks_function(const std::string& name);  // InputError listing valid names

}  // namespace gpm
