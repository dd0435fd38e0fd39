// Reference implementations of the approximate operators, one target at a time.
//
// These are the documents' formulas transcribed literally (clear per-target loops over
// the neighbours found with a CellList), used to check the fused kernel (kernel.hpp) and
// for small ad hoc evaluations.  Nothing here is fast; the studies use the kernel.
//
// Conventions: d = 2; w_h(r) = w(r/h)/h^d; the arrays V (volumes) and v (a function
// sampled at the particles) are in the particles' ORIGINAL order, the order of the
// coordinates the CellList was built from; the target point is p and v(p) is passed as
// `vp` (for a target that is a particle j, vp = v[j]).
//
// Generalized particle method (imoto (2)–(4), Λ0 = {0 ≤ r < h}, Λ = {0 < r < h}):
//   Π_h v(p) = Σ_{Λ0} V_i v_i w_h(r_i)
//   ∇_h v(p) = d Σ_Λ V_i (v_i − v(p))/r_i · (x_i − p)/r_i · w_h(r_i)
//   Δ_h v(p) = 2d Σ_Λ V_i (v_i − v(p))/r_i² · w_h(r_i)
// The thesis (1.2)–(1.4) writes the same sums with v(p) − v_i, p − x_i and a minus sign on
// Δ; every term is the exact negative, so both give bitwise identical numbers.
//
// SPH (thesis (A.6)–(A.8), imoto (57)–(59)), ∇ = gradient with respect to p:
//   Π^S v(p) = Σ V_i v_i w^S_h(r_i)
//   ∇^S v(p) = Σ_Λ V_i (v_i − v(p)) ∇w^S_h(|p − x_i|),   ∇w^S_h(|p − x_i|) = w^S_h'(r_i)(p − x_i)/r_i
//   Δ^S v(p) = 2 Σ_Λ V_i (v(p) − v_i)/r_i · (p − x_i)/r_i · ∇w^S_h(|p − x_i|)
// With the generalized weight w = −(r/d) dw^S/dr (thesis (A.9), imoto after (59)) they are
// ∇_h and Δ_h.  SIGN: thesis (A.7) has (v_i − v(p)) and approximates +∇v.  imoto (58) prints
// {v(p) − v_i} with the same ∇w^S_h(|p − x_i|); read literally it approximates −∇v
// (sph_gradient_imoto58 below).  It is right only if ∇ there means the gradient with
// respect to x_i.  The Laplacians (A.8) and (59) agree.
//
// MPS (thesis (A.14)–(A.15), imoto (61)–(62)):
//   ∇^M v(p) = (d/n0) Σ_Λ (v(p) − v_i)/r_i · (p − x_i)/r_i · w^M_h(r_i)
//   Δ^M v(p) = −(2d/λ0) Σ_Λ (v(p) − v_i) w^M_h(r_i)
// With V_i = |Ω_H|/N (A.10): ∇^M = ∇_h for w = w^M/∫w^M (A.16) and n0 = (N/|Ω_H|)∫w^M (A.17);
// Δ^M = Δ_h for w = r² w^M/∫|x|²w^M (A.18) and λ0 = (N/|Ω_H|) h² ∫|x|² w^M (mps_lambda0).
// The h² is missing from the printed (A.19) and from imoto's λ̂ in (62) (both have
// λ0 = (N/|Ω_H|)∫|x|²w^M): with w_h(r) = h^-d w(r/h) the substitution (A.18) gives
// w_h(r) = (r/h)² w^M_h(r)/∫|x|²w^M, so the printed λ0 makes Δ^M too large by 1/h².
// The "representative particle" λ0 = Σ_i |x_i' − x_i|² w^M_h(|x_i' − x_i|) of the thesis
// does scale with h² (mps_lambda0_sum), consistent with the correction.
// imoto (61)–(62) also write w^MPS_h(|x − x_j|) inside a sum over i ≠ j: read x = x_j and
// w^MPS_h(|x − x_i|).
#pragma once
#include <cstddef>
#include <vector>

#include "gpm/geometry/cells.hpp"
#include "gpm/weights/weights.hpp"

namespace gpm {

struct Vec2 {
  double x = 0, y = 0;
};

// Generalized operators, imoto (2)–(4).
double interpolant(const CellList& cl, const std::vector<double>& V,
                   const std::vector<double>& v, const WeightFunction& w, double h, Vec2 p);
Vec2 gradient(const CellList& cl, const std::vector<double>& V, const std::vector<double>& v,
              const WeightFunction& w, double h, Vec2 p, double vp);
double laplacian(const CellList& cl, const std::vector<double>& V,
                 const std::vector<double>& v, const WeightFunction& w, double h, Vec2 p,
                 double vp);

// The same operators as the thesis writes them, (1.2)–(1.4).
double interpolant_thesis(const CellList& cl, const std::vector<double>& V,
                          const std::vector<double>& v, const WeightFunction& w, double h,
                          Vec2 p);
Vec2 gradient_thesis(const CellList& cl, const std::vector<double>& V,
                     const std::vector<double>& v, const WeightFunction& w, double h, Vec2 p,
                     double vp);
double laplacian_thesis(const CellList& cl, const std::vector<double>& V,
                        const std::vector<double>& v, const WeightFunction& w, double h,
                        Vec2 p, double vp);

// SPH, thesis (A.6)–(A.8); wS is the SPH weight (smoothing function) itself.
double sph_interpolant(const CellList& cl, const std::vector<double>& V,
                       const std::vector<double>& v, const WeightFunction& wS, double h,
                       Vec2 p);
Vec2 sph_gradient(const CellList& cl, const std::vector<double>& V,
                  const std::vector<double>& v, const WeightFunction& wS, double h, Vec2 p,
                  double vp);
// imoto (58) read literally: {v(p) − v_i} ∇w^S_h(|p − x_i|) = −sph_gradient.
Vec2 sph_gradient_imoto58(const CellList& cl, const std::vector<double>& V,
                          const std::vector<double>& v, const WeightFunction& wS, double h,
                          Vec2 p, double vp);
double sph_laplacian(const CellList& cl, const std::vector<double>& V,
                     const std::vector<double>& v, const WeightFunction& wS, double h, Vec2 p,
                     double vp);

// MPS, thesis (A.14)–(A.15); wM is the MPS weight; no volumes.
Vec2 mps_gradient(const CellList& cl, const std::vector<double>& v, const WeightFunction& wM,
                  double h, Vec2 p, double vp, double n0);
double mps_laplacian(const CellList& cl, const std::vector<double>& v,
                     const WeightFunction& wM, double h, Vec2 p, double vp, double lambda0);
// n0 of (A.17) = (N/area) ∫_{R²} w^M(|x|) dx.
double mps_n0(const WeightFunction& wM, std::size_t n, double area);
// λ0 = (N/area) h² ∫_{R²} |x|² w^M(|x|) dx: (A.19) with the h² the substitution needs.
double mps_lambda0(const WeightFunction& wM, std::size_t n, double area, double h);
// (A.19) as printed (no h²), for the errata.
double mps_lambda0_printed(const WeightFunction& wM, std::size_t n, double area);
// The representative-particle forms after (A.15), summed over i ≠ i' (r > 0).
double mps_n0_sum(const CellList& cl, const WeightFunction& wM, double h, Vec2 p);
double mps_lambda0_sum(const CellList& cl, const WeightFunction& wM, double h, Vec2 p);

// Weight substitutions between the forms (exact piecewise-polynomial arithmetic).
// (A.9): w = −(r/d) dw^S/dr.
WeightFunction sph_generalized_weight(const WeightFunction& wS, int d = 2);
// (A.16): w = w^M / ∫w^M.
WeightFunction mps_gradient_weight(const WeightFunction& wM);
// (A.18): w = r² w^M / ∫|x|² w^M.
WeightFunction mps_laplacian_weight(const WeightFunction& wM);
// ∫_{R^d} |x|^k w(|x|) dx from the pieces (exact; +inf if the integral diverges at 0).
double radial_moment(const WeightFunction& w, int k, int d = 2);

}  // namespace gpm
