// thesis_table4_2: Figure 4.5 and Table 4.2 of the thesis (Section 4.1.1) — the interpolant
// errors of Table 4.1 plus the cubic spike (order k = 3, O(h⁴) by Theorem 1.11), with
// h = (3.1³ · 2^-10 · Δx)^(1/5), Δx = 2^-5 … 2^-12, Voronoi volumes.
//
// Two readings of h run side by side: the printed one (h > H = 0.1 up to Δx = 2^-11, which
// the thesis' own setting 0 < h < H excludes) and the scaled one, h = 3.1 · 2^(5/5−5) Δx^(1/5),
// which keeps h(2^-5) = 3.1·2^-5 as in Table 4.1.  The paper profile is heavy: the printed
// reading at Δx = 2^-12 has about 8·10^12 neighbour pairs (see the cost file).
#include "gpm/io/args.hpp"
#include "apps/tables/thesis_truncation.hpp"

// The table's weights, readings of h and levels are defined once, in thesis_table_specs()
// (src/gpm/studies/run/thesis_truncation.cpp), which `make plan` and the tests read too.
int main(int argc, char** argv) {
  return gpm::run_main("thesis_table4_2", [](int c, char** v) {
    return gpm::run_thesis_table(gpm::thesis_table_spec("thesis_table4_2"), c, v);
  }, argc, argv);
}
