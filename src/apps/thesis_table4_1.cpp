// thesis_table4_1: Figure 4.3 and Table 4.1 of the thesis (Section 4.1.1) — relative errors of
// the interpolant Π_h v for the quadratic spike (4.1), the cubic B-spline and the quintic
// B-spline (all of order k = 1, so O(h²) by Theorem 1.11), Voronoi volumes V_i = Ṽ_i, on the
// jittered grid with Δx = 2^-5 … 2^-11 and h = (3.1³ · 2^-10 · Δx)^(1/3).
//
// The two B-splines are used as corrected by the weight registry: the thesis prints the
// cubic B-spline with 2(1−r)² on [½, 1) (discontinuous, integrates to 1.38) and the quintic
// one with 63/(578π) and +6(2−3r)⁵ (integrates to 1.71); see the report's errata.
//
// For p = 3 both readings of h (printed, scaled) are the same formula, so only the printed one
// runs.  Beyond the thesis: the same passes with V_i = |Ω_H|/N.
#include "gpm/io/args.hpp"
#include "apps/tables/thesis_truncation.hpp"

// The table's weights, readings of h and levels are defined once, in thesis_table_specs()
// (src/gpm/studies/run/thesis_truncation.cpp), which `make plan` and the tests read too.
int main(int argc, char** argv) {
  return gpm::run_main("thesis_table4_1", [](int c, char** v) {
    return gpm::run_thesis_table(gpm::thesis_table_spec("thesis_table4_1"), c, v);
  }, argc, argv);
}
