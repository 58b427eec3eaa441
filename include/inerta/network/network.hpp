#pragma once
// Series–parallel spring (k) / damper (c) / inerter (b) networks (spec/03 §3.1), written as
// expressions: "|" parallel, "-" series, parentheses, element names starting with k, c or b
// ("k", "k1", "c_2", "b"). Mixing "|" and "-" at one level without parentheses is an error.
// Element values are bound by name; 0 means open and inf rigid, simplified algebraically.
// An Admittance leaf is a given rational admittance Y(s) = num(s)/den(s) (the positive-real
// admittance of optim/admittance_search.hpp), not written in expressions.
#include <complex>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace inerta::network {

/// Malformed expression or parameter set; `column` (1-based) points at the problem, 0 if none.
struct NetworkError : std::runtime_error {
  NetworkError(const std::string& what, int column) : std::runtime_error(what), column(column) {}
  int column;
};

struct Network {
  enum class Kind { Spring, Damper, Inerter, Series, Parallel, Open, Rigid, Admittance };
  Kind kind = Kind::Open;
  std::string name;   ///< element name (leaves)
  double value = 0;   ///< element value, SI (N/m, N·s/m, kg); set by assign()
  std::vector<Network> children;
  int column = 0;     ///< position in the expression, 1-based
  std::vector<double> num{}, den{};  ///< Admittance: Y(s) = num(s)/den(s), ascending powers of s, SI

  bool is_element() const { return kind == Kind::Spring || kind == Kind::Damper || kind == Kind::Inerter; }
};

using Params = std::map<std::string, double>;

/// Limits of parse (issue 15): characters of an expression and depth of nested parentheses.
inline constexpr std::size_t max_expression_length = 10000;
inline constexpr int max_nesting = 64;

/// Parses an expression such as "b-(k|c)". Throws NetworkError with the column of the error (also
/// beyond max_expression_length characters or max_nesting nested parentheses).
Network parse(const std::string& text);
/// Element names in order of appearance (each once).
std::vector<std::string> parameter_names(const Network& net);
/// Sets every element's value from `params`; throws NetworkError naming missing, unknown or
/// negative parameters.
Network assign(const Network& net, const Params& params);
/// Removes open (value 0) and rigid (value ∞) elements algebraically: a parallel branch with a
/// rigid member is rigid, a series chain with an open member is open; open parallel members and
/// rigid series members drop out. The result is a network without 0/∞ values, or Open or Rigid.
Network simplify(const Network& net);
/// Readable form, e.g. "b-(k|c)", with values when `with_values`.
std::string to_string(const Network& net, bool with_values = false);

/// A network of one Admittance leaf Y(s) = num(s)/den(s) (coefficients ascending, SI); throws
/// NetworkError unless they are finite, den is not zero and the leading ones are not zero.
Network admittance_leaf(std::vector<double> num, std::vector<double> den);

/// Admittance Y(s) = F / relative velocity (spec/03 §3.1), evaluated directly on the tree.
std::complex<double> admittance(const Network& net, std::complex<double> s);

}  // namespace inerta::network
