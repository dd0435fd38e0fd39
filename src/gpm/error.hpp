// Errors the core reports to the user.  Every program catches gpm::Error in main(),
// prints its one-line message prefixed by the program name, and exits non-zero.
#pragma once
#include <stdexcept>
#include <string>

namespace gpm {

// Bad input (a value the user gave): the message names the value.
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Numerical failure: non-finite values, divergence, a singular system.  The message
// says where it happened (level, particle, step).
struct NumericalError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A unit's computation whose numerical failure names the unit: `where` (e.g. "h10,
// quartic_polynomial, level 9") is put before the message of a NumericalError thrown by `f`.
template <class F>
auto naming_unit(const std::string& where, F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const NumericalError& e) {
    throw NumericalError(where + ": " + e.what());
  }
}

// A result store whose rows disagree with what the current code computes for the same
// units (store.hpp: --verify, --recheck).  The message names the file, unit and column.
struct StoreMismatch : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Checks that x is finite and positive; otherwise throws InputError naming `what`.
void require_positive(double x, const std::string& what);
void require_finite(double x, const std::string& what);

}  // namespace gpm
