// thesis_table4_3: Figures 4.6–4.7 and Table 4.3 of the thesis (Section 4.1.2) — relative
// errors of the approximate gradient ∇_h and Laplacian Δ_h for the quartic polynomial and the
// piecewise cubic and quintic polynomials w = −(r/2) dw^B/dr of the two B-splines (O(h²) by
// Theorems 1.13 and 1.15), with h = (3.1⁴ · 2^-10 · Δx)^(1/4), Δx = 2^-5 … 2^-11, Voronoi
// volumes.  The piecewise polynomials derive from the corrected B-splines (see errata).
//
// Two readings of h: printed (h > H at Δx ≥ 2^-9) and scaled, h = 3.1 · 2^(5/4−5) Δx^(1/4).
#include "gpm/io/args.hpp"
#include "apps/tables/thesis_truncation.hpp"

// The table's weights, readings of h and levels are defined once, in thesis_table_specs()
// (src/gpm/studies/run/thesis_truncation.cpp), which `make plan` and the tests read too.
int main(int argc, char** argv) {
  return gpm::run_main("thesis_table4_3", [](int c, char** v) {
    return gpm::run_thesis_table(gpm::thesis_table_spec("thesis_table4_3"), c, v);
  }, argc, argv);
}
