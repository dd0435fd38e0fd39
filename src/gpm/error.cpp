#include "gpm/error.hpp"

#include <cmath>
#include <sstream>

namespace gpm {

void require_finite(double x, const std::string& what) {
  if (!std::isfinite(x)) {
    std::ostringstream s;
    s << what << " must be a finite number, got " << x;
    throw InputError(s.str());
  }
}

void require_positive(double x, const std::string& what) {
  require_finite(x, what);
  if (!(x > 0)) {
    std::ostringstream s;
    s << what << " must be > 0, got " << x;
    throw InputError(s.str());
  }
}

}  // namespace gpm
