// thesis_table4_2: Figure 4.5 and Table 4.2 of the thesis (Section 4.1.1) — the interpolant
// errors of Table 4.1 plus the cubic spike (order k = 3, O(h⁴) by Theorem 1.11), with
// h = (3.1³ · 2^-10 · Δx)^(1/5), Δx = 2^-5 … 2^-12, Voronoi volumes.
//
// Two readings of h run side by side: the printed one (h > H = 0.1 up to Δx = 2^-11, which
// the thesis' own setting 0 < h < H excludes) and the scaled one, h = 3.1 · 2^(5/5−5) Δx^(1/5),
// which keeps h(2^-5) = 3.1·2^-5 as in Table 4.1.  The paper profile is heavy: the printed
// reading at Δx = 2^-12 has about 8·10^12 neighbour pairs (see the cost file).
#include "gpm/args.hpp"
#include "gpm/thesis_truncation.hpp"

using namespace gpm;

namespace {

int body(int argc, char** argv) {
  ThesisTableSpec s;
  s.program = "thesis_table4_2";
  s.summary =
      "Thesis Figure 4.5 / Table 4.2: interpolant errors incl. the cubic spike,\n"
      "h = (3.1^3 2^-10 dx)^(1/5) (printed) and 3.1*2^(5/5-5) dx^(1/5) (scaled).";
  s.table = "Table 4.2 (Section 4.1.1)";
  s.c = 3;
  s.p = 5;
  s.requests = {{"cubic_bspline", Operator::interp},
                {"quintic_bspline", Operator::interp},
                {"quadratic_spike", Operator::interp},
                {"cubic_spike", Operator::interp}};
  s.readings = {HReading::printed, HReading::scaled};
  // Pairs grow ≈ 12x per level; the printed reading has ~6x the pairs of the scaled one.
  s.quick_printed = {5, 6, 7, 8};
  s.quick_scaled = {5, 6, 7, 8, 9};
  s.paper_levels = {5, 6, 7, 8, 9, 10, 11, 12};
  s.rate_levels = "11,12";
  return run_thesis_table(s, argc, argv);
}

}  // namespace

int main(int argc, char** argv) { return run_main("thesis_table4_2", body, argc, argv); }
