// Splitting a fused pass over shares of the targets (what the ranks of a cluster do with one
// unit, runner.hpp): the shares' maxima, merged in target order, are exactly those of one
// pass over all targets — the errors, the worst particle and the pair count — for any number
// of shares.  Checked here on one process, without MPI.
#include <catch2/catch.hpp>
#include <cmath>

#include "gpm/error.hpp"
#include "gpm/geometry/domain.hpp"
#include "gpm/operators/fused_errors.hpp"

using namespace gpm;

TEST_CASE("fused pass: merged target shares equal one pass", "[fused][share]") {
  const Particles p = jittered_grid(std::ldexp(1.0, -6), 2);
  const std::vector<double> V(p.size(), std::ldexp(1.0, -12));
  const std::vector<ErrorRequest> req = {{"quartic_polynomial", Operator::interp},
                                         {"quartic_polynomial", Operator::lap},
                                         {"piecewise_cubic_polynomial", Operator::grad}};
  const std::vector<std::string> fns = {"sin2pi", "quartic"};
  const double h = 0.08;
  const ErrorMaxima whole = fused_error_maxima(p, V, h, req, fns);
  for (int parts : {2, 3, 7}) {
    INFO(parts << " shares");
    ErrorMaxima merged = fused_error_maxima(p, V, h, req, fns, true, {0, parts});
    for (int k = 1; k < parts; ++k)
      merged.merge_following(fused_error_maxima(p, V, h, req, fns, true, {k, parts}));
    CHECK(merged.error == whole.error);
    CHECK(merged.exact == whole.exact);
    CHECK(merged.worst == whole.worst);
    CHECK(merged.pairs == whole.pairs);
    const FusedErrors a = relative_errors(merged, req, fns), b = fused_errors(p, V, h, req, fns);
    for (std::size_t i = 0; i < a.errors.size(); ++i) CHECK(a.errors[i].rel_error == b.errors[i].rel_error);
  }
  // A share that does not exist is refused.
  CHECK_THROWS_AS(fused_error_maxima(p, V, h, req, fns, true, {3, 3}), InputError);
}

TEST_CASE("merge keeps the first worst particle in target order", "[fused][share]") {
  ErrorMaxima a{{0.5, 0.2}, {1.0, 1.0}, {10, 11}, 4, 0}, b{{0.5, 0.3}, {2.0, 0.5}, {20, 21}, 6, 0};
  a.merge_following(b);
  CHECK(a.error == std::vector<double>{0.5, 0.3});
  CHECK(a.worst == std::vector<int32_t>{10, 21});  // a tie stays with the earlier share
  CHECK(a.exact == std::vector<double>{2.0, 1.0});
  CHECK(a.pairs == 10);
}
