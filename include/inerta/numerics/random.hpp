#pragma once
// A portable random source: the same numbers on every platform and compiler (docs/catenary-fe.md
// "Irregularities"). xoshiro256** (Blackman & Vigna) seeded through splitmix64; uniform doubles from
// the top 53 bits; standard normal deviates by Marsaglia's polar form of Box–Muller with the
// logarithm written out (atanh series, fused multiply-adds called explicitly), so that no result
// depends on a math library or on the compiler contracting a·b + c. Not std::normal_distribution,
// whose algorithm the standard leaves to the implementation.
#include <cstdint>

namespace inerta::numerics {

class Xoshiro256 {
 public:
  explicit Xoshiro256(std::uint64_t seed);
  std::uint64_t next();
  double uniform();  ///< [0, 1), a multiple of 2⁻⁵³
  double normal();   ///< N(0, 1), polar method
  /// N(0, 1) truncated to [−limit, limit]: a draw outside is drawn again.
  double truncated_normal(double limit);

 private:
  std::uint64_t s_[4];
};

/// ln x for x > 0, finite: portable (header comment); |error| < 2 ulp of the result.
double portable_log(double x);

}  // namespace inerta::numerics
