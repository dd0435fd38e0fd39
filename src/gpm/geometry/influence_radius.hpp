// Every rule for the influence radius h in the three documents, each written once.
//
//   imoto §5 (Figure 5, Table 1)      h_N = 2.6 · 2^(5/m − 5) · Δx^(1/m)          imoto_h
//   thesis §4.1 (Tables 4.1–4.3)      printed: h = (3.1^c · 2^-10 · Δx)^(1/p)     thesis_h
//                                     scaled:  h = 3.1 · 2^(5/p − 5) · Δx^(1/p)
//   thesis §4.2–4.3 (Tables 4.4–4.7)  h10: h = (2.6⁴ · 2^-10 · Δx)^(1/4), as printed      pde_h
//                                     h15: h = (2.6⁴ · 2^-15 · Δx)^(1/4), the other reading
//
// Why two readings: for p = 4, 5 the printed 2^-10 gives h > H = 0.1 on the coarse levels,
// although the thesis defines w_h for 0 < h < H only; the second reading keeps
// h(2^-5) = 3.1·2^-5 (resp. 2.6·2^-5 for h15), as imoto's h_N does for every m.  For p = 3
// the printed and scaled formulas coincide.  Which one the thesis ran is decided from data.
#pragma once
#include <string>
#include <vector>

namespace gpm {

// imoto §5.  InputError naming m or dx unless both are finite and positive.
double imoto_h(double m, double dx);

enum class HReading { printed, scaled };
std::string h_reading_name(HReading r);
HReading parse_h_reading(const std::string& s);  // InputError listing the valid names
// thesis §4.1 in the given reading.
double thesis_h(HReading r, int c, int p, double dx);

// thesis §4.2–4.3 in the given rule.  Its name (h10, h15) is what data files, options and
// the set-up readings say.
enum class HRule { h10, h15 };
std::string h_rule_name(HRule r);
// InputError "OPTION: 'x' is not h10 or h15".
HRule parse_h_rule(const std::string& s, const std::string& option = "--h-rule");
double pde_h(HRule rule, double dx);
std::string pde_h_formula(HRule rule);  // "(2.6^4 2^-10 dx)^(1/4)"
const std::vector<HRule>& pde_h_rules();  // h10, h15

}  // namespace gpm
