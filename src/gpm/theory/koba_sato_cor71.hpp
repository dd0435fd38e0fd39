// Koba & Sato, Corollary 7.1: the four bounds for the step weight of Section 7,
//   w = 1 on B̄_{h,δ}, δ = r_σ/2, h = C* r_σ,
// evaluated exactly in rational arithmetic (GMP's mpq_class), three ways:
//   cor71_formula       the corollary's general coefficients as printed (C*, λ, r_σ);
//   cor71_from_theorems the constants c₁ … c₁₁ of Theorems 1.3–1.6 with Section 7's
//                       L¹ norms and assumptions substituted (π cancels from every ratio),
//                       which must reproduce cor71_formula if the corollary follows;
//   cor71_printed_value the simplified value the paper prints for cases (i) and (ii),
//                       parsed from its transcription (e.g. "5*10^-(m-1)").
#pragma once
#include <gmpxx.h>

#include <string>

namespace gpm {

// The coefficient of each seminorm in the four bounds, in the order
// Π̃: |f|_{C¹}, |f|_{C⁰};  ∇̃: |f|_{C²}, |f|_{C¹};  Δ̃: |f|_{C³}, |f|_{C¹};  □̃: |f|_{C³}, |f|_{C¹}.
template <class T>
struct Cor71Coefficients {
  T pi_c1, pi_c0, grad_c2, grad_c1, lap_c3, lap_c1, box_c3, box_c1;
};

// Corollary 7.1's general formulas, transcribed term by term.
template <class T>
Cor71Coefficients<T> cor71_formula(const T& r, const T& C, const T& lam) {
  const T q4 = T(1) / T(4), q16 = T(1) / T(16);
  const T C2 = C * C, C3 = C2 * C, C4 = C2 * C2, lC = lam * C, lC1 = lC + T(1);
  Cor71Coefficients<T> k;
  k.pi_c1 = C * r + r;
  k.pi_c0 = (T(3) / T(2)) / (C2 - q4);
  k.grad_c2 = T(4) * C * r;
  k.grad_c1 = T(8) / lC + (T(8) * lC1 * lC1 + T(1)) / (C2 - q4);
  k.lap_c3 = T(24) * C * r;
  const T lap_bracket = T(8) + T(24) * lC1 * lC1 + (T(56) * C3 - T(7)) / (T(3) * (C4 - q16)) +
                        C * (T(64) * C3 - T(8)) / (C2 + q4) + (T(16) * C3 - T(2)) / lC;
  k.lap_c1 = lap_bracket / (T(3) * r * (C4 - q16));
  k.box_c3 = T(24) * C * r;
  const T box_bracket = T(12) / (T(2) * C + T(1)) + T(16) + T(24) * lC + (T(24) * C - T(12)) / lC;
  k.box_c1 = box_bracket / (r * (C2 - q4));
  return k;
}

// Theorems 1.3–1.6 with Section 7 substituted; exact.
Cor71Coefficients<mpq_class> cor71_from_theorems(const mpq_class& r, const mpq_class& C,
                                                 const mpq_class& lam);

// Exact value of a printed coefficient such as "1/20", "10^-m + 10^-5m", "4*10^-m",
// "10^-(8m-1)" at the given m (integers, + − * /, integer powers, m in exponents).
// Throws InputError naming the text on a syntax error.
mpq_class cor71_printed_value(const std::string& text, int m);

// "p/q" (or "p" for integers).
std::string exact_string(const mpq_class& q);
// The double nearest to q (mpq_class::get_d truncates; this rounds, via 40 digits).
double exact_to_double(const mpq_class& q);
// Parses "p/q", "p" or a terminating decimal such as "0.01" exactly; InputError otherwise.
mpq_class exact_parse(const std::string& text, const std::string& what);

}  // namespace gpm
