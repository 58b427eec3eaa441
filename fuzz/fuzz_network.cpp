// Fuzz target: network expressions (network::parse, docs/networks.md). A parsed expression is
// printed and parsed again (the printed form must parse to the same form: a finding otherwise),
// its elements are given unit values (and, for every second input, one open and one rigid) and
// its admittance is evaluated at a few frequencies, raw and simplified.
#include <cmath>
#include <complex>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <limits>
#include <numbers>

#include "fuzz_common.hpp"
#include "inerta/network/network.hpp"

namespace net = inerta::network;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text = inerta::fuzz::as_text(data, size);
  net::Network n;
  try {
    n = net::parse(text);
  } catch (const std::exception&) {
    return 0;
  }
  const std::string printed = net::to_string(n);
  try {
    const std::string again = net::to_string(net::parse(printed));
    if (again != printed) {
      std::fprintf(stderr, "to_string is not stable: '%s' -> '%s'\n", printed.c_str(), again.c_str());
      std::abort();
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "to_string(parse(x)) = '%s' does not parse: %s\n", printed.c_str(), e.what());
    std::abort();
  }
  try {
    net::Params params;
    const auto names = net::parameter_names(n);
    for (const auto& name : names) params[name] = 1.0;
    if (size % 2 == 1 && names.size() >= 2) {
      params[names.front()] = 0.0;
      params[names.back()] = std::numeric_limits<double>::infinity();
    }
    const net::Network valued = net::assign(n, params);
    (void)net::to_string(valued, true);
    const net::Network simple = net::simplify(valued);
    (void)net::to_string(simple, true);
    for (double f : {0.0, 0.1, 1.0, 50.0}) {
      const std::complex<double> s(0.0, 2 * std::numbers::pi * f);
      (void)net::admittance(valued, s);
      (void)net::admittance(simple, s);
    }
  } catch (const std::exception&) {
  }
  return 0;
}
