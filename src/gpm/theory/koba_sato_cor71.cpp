#include "gpm/theory/koba_sato_cor71.hpp"

#include <cctype>
#include <cstdlib>

#include "gpm/error.hpp"

namespace gpm {
namespace {

// ‖|·|ⁿ w‖_{L¹(B_p \ B_q)} / π for the step weight (Section 7's four formulas).
mpq_class step_norm_over_pi(int n, const mpq_class& p, const mpq_class& q) {
  switch (n) {
    case -1: return mpq_class(2) * (p - q);
    case 0: return p * p - q * q;
    case 1: return mpq_class(2, 3) * (p * p * p - q * q * q);
    case 2: return mpq_class(1, 2) * (p * p * p * p - q * q * q * q);
  }
  throw InputError("step_norm_over_pi: n must be -1..2");
}

mpq_class power(const mpq_class& b, long e) {
  mpq_class r(1);
  for (long i = 0; i < (e < 0 ? -e : e); ++i) r *= b;
  return e < 0 ? mpq_class(1) / r : r;
}

// Recursive-descent parser for the printed coefficients.
class Printed {
 public:
  Printed(const std::string& text, int m) : s_(text), m_(m) {}
  mpq_class parse() {
    mpq_class v = expr();
    skip();
    if (i_ != s_.size()) fail("unexpected '" + s_.substr(i_, 1) + "'");
    return v;
  }

 private:
  const std::string& s_;
  int m_;
  std::size_t i_ = 0;

  [[noreturn]] void fail(const std::string& why) const {
    throw InputError("printed coefficient '" + s_ + "': " + why);
  }
  void skip() {
    while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_]))) ++i_;
  }
  bool eat(char c) {
    skip();
    if (i_ < s_.size() && s_[i_] == c) return ++i_, true;
    return false;
  }
  bool digit() const { return i_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[i_])); }
  long integer() {
    skip();
    if (!digit()) fail("number expected at position " + std::to_string(i_));
    long v = 0;
    while (digit()) v = 10 * v + (s_[i_++] - '0');
    return v;
  }
  // Exponent: [−] (k·m | k | (linear in m)).
  long exponent() {
    const bool neg = eat('-');
    long v;
    if (eat('(')) {
      v = linear();
      if (!eat(')')) fail("')' expected");
    } else {
      v = lin_atom();
    }
    return neg ? -v : v;
  }
  long lin_atom() {
    skip();
    long k = 1;
    bool any = false;
    if (digit()) k = integer(), any = true;
    if (eat('m')) k *= m_, any = true;
    if (!any) fail("exponent expected");
    return k;
  }
  long linear() {
    long v = eat('-') ? -lin_atom() : lin_atom();
    for (;;) {
      if (eat('+')) v += lin_atom();
      else if (eat('-')) v -= lin_atom();
      else return v;
    }
  }
  mpq_class factor() {
    mpq_class b(integer());
    if (eat('^')) b = power(b, exponent());
    return b;
  }
  mpq_class term() {
    mpq_class v = factor();
    for (;;) {
      if (eat('*')) v *= factor();
      else if (eat('/')) v /= factor();
      else return v;
    }
  }
  mpq_class expr() {
    mpq_class v = term();
    for (;;) {
      if (eat('+')) v += term();
      else if (eat('-')) v -= term();
      else return v;
    }
  }
};

}  // namespace

Cor71Coefficients<mpq_class> cor71_from_theorems(const mpq_class& r, const mpq_class& C,
                                                 const mpq_class& lam) {
  const mpq_class delta = r / 2, h = C * r;
  mpq_class A[4], S[4], O[4], L[4];
  for (int n = -1; n <= 2; ++n) {
    A[n + 1] = step_norm_over_pi(n, h, delta);          // B_h \ B_δ
    S[n + 1] = step_norm_over_pi(n, r, delta);          // σ_k \ B_δ ⊂ B_{r_σ} \ B_δ
    O[n + 1] = A[n + 1];                                // Section 7: B_h \ σ_k ~ B_h \ B_δ
    L[n + 1] = step_norm_over_pi(n, lam * h + r, delta);  // B_{λh+r_σ} \ σ_k
  }
  const mpq_class D1_over_D2 = A[2] / A[3];  // Section 7's second assumption
  const mpq_class c1 = S[1] / A[1], c3 = L[1] / O[1];
  const mpq_class c4 = S[2] / A[3] * (1 + r * A[2] / O[3]);
  const mpq_class c5 = r / (lam * h) * O[2] / O[3];
  const mpq_class c6 = r * L[1] / O[3];
  const mpq_class c7 = 2 * r * h * O[1] / O[3] * D1_over_D2;
  const mpq_class c9 = S[0] / A[1] + S[1] / A[1] * O[0] / O[1];
  const mpq_class c10 = r / (lam * h) * O[0] / O[1];
  const mpq_class c11 = L[0] / O[1];
  // L_w = 0: c₂ = c₈ = c₁₂ = 0.
  Cor71Coefficients<mpq_class> k;
  k.pi_c1 = h + r;
  k.pi_c0 = 2 * c1;
  k.grad_c2 = 4 * h;
  k.grad_c1 = 8 * r / (lam * h) + 4 * c1 + 8 * c3;
  k.lap_c3 = 24 * h;
  k.lap_c1 = 4 * (c4 + c5 + c6 + c7);
  k.box_c3 = 24 * h;
  k.box_c1 = 4 * c9 + 12 * c10 + 12 * c11;
  return k;
}

mpq_class cor71_printed_value(const std::string& text, int m) { return Printed(text, m).parse(); }

std::string exact_string(const mpq_class& q) {
  mpq_class c = q;
  c.canonicalize();
  return c.get_str();
}

double exact_to_double(const mpq_class& q) {
  const mpf_class f(q, 256);
  char buf[128];
  gmp_snprintf(buf, sizeof buf, "%.40Fe", f.get_mpf_t());
  return std::strtod(buf, nullptr);
}

mpq_class exact_parse(const std::string& text, const std::string& what) {
  const auto dot = text.find('.');
  try {
    if (dot == std::string::npos) {
      mpq_class q(text);
      q.canonicalize();
      return q;
    }
    const std::string digits = text.substr(0, dot) + text.substr(dot + 1);
    mpq_class q(digits);
    q /= power(mpq_class(10), static_cast<long>(text.size() - dot - 1));
    return q;
  } catch (const std::invalid_argument&) {
    throw InputError(what + ": cannot parse '" + text + "' as an exact rational");
  }
}

}  // namespace gpm
