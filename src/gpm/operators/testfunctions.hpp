// The test functions of the documents, with exact gradient and Laplacian.
//   sin2pi  : v = sin(2π(x+y))                   imoto §5, thesis Case 2, Poisson §4.2
//   quartic : v = (x−½)⁴ + (y−½)⁴                 thesis Case 1
//   linear  : v = 1 + 2x − 3y                     exactness checks
// The relative errors divide by ‖v‖, ‖∇v‖, ‖Δv‖ over the particles in Ω (the discrete
// maxima, as the thesis writes; imoto writes the continuous max over Ω̄ — for sin2pi
// both are 1, 2√2π and 8π² up to O(Δx²); data files record which was used).
#pragma once
#include <string>
#include <vector>

namespace gpm {

struct TestFunction {
  std::string name;
  double (*v)(double, double);
  double (*vx)(double, double);
  double (*vy)(double, double);
  double (*lap)(double, double);
};

const TestFunction& test_function(const std::string& name);  // InputError if unknown

// sin2pi is the Fourier mode e^{ik·x} with k = 2π(1, 1): |k| = 2π√2 (for smoothing.hpp).
inline constexpr double kSin2piWaveNumber = 8.885765876316732;
std::vector<std::string> test_function_names();

}  // namespace gpm
