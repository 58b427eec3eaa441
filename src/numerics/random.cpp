// A portable random source (numerics/random.hpp).
#include "inerta/numerics/random.hpp"

#include <cmath>

namespace inerta::numerics {

namespace {
std::uint64_t splitmix64(std::uint64_t& x) {
  std::uint64_t z = (x += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}
std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
}  // namespace

Xoshiro256::Xoshiro256(std::uint64_t seed) {
  std::uint64_t x = seed;
  for (std::uint64_t& s : s_) s = splitmix64(x);
}

std::uint64_t Xoshiro256::next() {
  const std::uint64_t result = rotl(s_[1] * 5, 7) * 9, t = s_[1] << 17;
  s_[2] ^= s_[0];
  s_[3] ^= s_[1];
  s_[1] ^= s_[2];
  s_[0] ^= s_[3];
  s_[2] ^= t;
  s_[3] = rotl(s_[3], 45);
  return result;
}

double Xoshiro256::uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

// ln x = e ln 2 + 2 atanh(f), f = (m − 1)/(m + 1), m ∈ [√½, √2): |f| <= 0.1716, the series to f²¹.
double portable_log(double x) {
  int e = 0;
  double m = std::frexp(x, &e);  // exact
  if (m < 0.70710678118654752440) m *= 2, e -= 1;
  const double f = (m - 1) / (m + 1), f2 = f * f;
  double p = 1.0 / 21;
  for (int k = 19; k >= 1; k -= 2) p = std::fma(p, f2, 1.0 / k);
  const double lnm = 2 * (f * p);
  return std::fma(static_cast<double>(e), 0.69314718055994530942, lnm);
}

double Xoshiro256::normal() {
  for (;;) {
    const double v1 = 2 * uniform() - 1, v2 = 2 * uniform() - 1;
    const double s = std::fma(v1, v1, v2 * v2);
    if (s >= 1 || s == 0) continue;
    return v1 * std::sqrt(-2 * portable_log(s) / s);
  }
}

double Xoshiro256::truncated_normal(double limit) {
  for (;;)
    if (const double z = normal(); std::abs(z) <= limit) return z;
}

}  // namespace inerta::numerics
