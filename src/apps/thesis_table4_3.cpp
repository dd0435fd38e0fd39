// thesis_table4_3: Figures 4.6–4.7 and Table 4.3 of the thesis (Section 4.1.2) — relative
// errors of the approximate gradient ∇_h and Laplacian Δ_h for the quartic polynomial and the
// piecewise cubic and quintic polynomials w = −(r/2) dw^B/dr of the two B-splines (O(h²) by
// Theorems 1.13 and 1.15), with h = (3.1⁴ · 2^-10 · Δx)^(1/4), Δx = 2^-5 … 2^-11, Voronoi
// volumes.  The piecewise polynomials derive from the corrected B-splines (see errata).
//
// Two readings of h: printed (h > H at Δx ≥ 2^-9) and scaled, h = 3.1 · 2^(5/4−5) Δx^(1/4).
#include "gpm/args.hpp"
#include "gpm/thesis_truncation.hpp"

using namespace gpm;

namespace {

int body(int argc, char** argv) {
  ThesisTableSpec s;
  s.program = "thesis_table4_3";
  s.summary =
      "Thesis Figures 4.6-4.7 / Table 4.3: gradient and Laplacian errors, quartic and\n"
      "piecewise cubic/quintic polynomials, h = (3.1^4 2^-10 dx)^(1/4) and the scaled reading.";
  s.table = "Table 4.3 (Section 4.1.2)";
  s.c = 4;
  s.p = 4;
  for (const char* w : {"quartic_polynomial", "piecewise_cubic_polynomial",
                        "piecewise_quintic_polynomial"}) {
    s.requests.push_back({w, Operator::grad});
    s.requests.push_back({w, Operator::lap});
  }
  s.readings = {HReading::printed, HReading::scaled};
  s.quick_printed = {5, 6, 7, 8};
  s.quick_scaled = {5, 6, 7, 8, 9};
  s.paper_levels = {5, 6, 7, 8, 9, 10, 11};
  s.rate_levels = "10,11";
  return run_thesis_table(s, argc, argv);
}

}  // namespace

int main(int argc, char** argv) { return run_main("thesis_table4_3", body, argc, argv); }
