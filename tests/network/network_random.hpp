#pragma once
// Random series–parallel networks for the tests of the positive-real test and the synthesis.
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "inerta/network/network.hpp"
#include "inerta/network/realisation.hpp"

namespace inerta::network {

struct RandomNetwork {
  std::string text;
  Network net;  ///< parsed, values assigned, simplified
};

// n elements, types and series/parallel joins at random, values log-uniform in [0.2, 5].
inline RandomNetwork random_network(std::mt19937& rng, int n) {
  int counter = 0;
  Params params;
  std::uniform_int_distribution<int> type(0, 2), coin(0, 1);
  std::uniform_real_distribution<double> lv(std::log(0.2), std::log(5.0));
  auto gen = [&](auto&& self, int m) -> std::string {
    if (m == 1) {
      const std::string name = std::string(1, "kcb"[type(rng)]) + std::to_string(++counter);
      params[name] = std::exp(lv(rng));
      return name;
    }
    const int a = std::uniform_int_distribution<int>(1, m - 1)(rng);
    return "(" + self(self, a) + (coin(rng) ? "|" : "-") + self(self, m - a) + ")";
  };
  RandomNetwork r;
  r.text = gen(gen, n);
  r.net = simplify(assign(parse(r.text), params));
  return r;
}

inline std::vector<double> log_grid(double lo, double hi, int n) {
  std::vector<double> w(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) w[static_cast<std::size_t>(i)] = lo * std::pow(hi / lo, i / (n - 1.0));
  return w;
}

}  // namespace inerta::network
