#include "inerta/network/network.hpp"

#include <cctype>
#include <cmath>
#include <fmt/format.h>
#include <set>

namespace inerta::network {

namespace {

class Parser {
 public:
  explicit Parser(const std::string& text) : s_(text) {}

  Network parse_all() {
    if (s_.size() > max_expression_length)
      throw NetworkError(fmt::format("the expression has {} characters; at most {} are accepted", s_.size(),
                                     max_expression_length),
                         1);
    skip();
    if (pos_ >= s_.size()) throw NetworkError("empty network expression; expected e.g. b-(k|c)", 1);
    Network n = expr();
    skip();
    if (pos_ < s_.size())
      throw NetworkError(fmt::format("unexpected '{}' at column {}; expected '|', '-' or the end", s_[pos_], col()), col());
    return n;
  }

 private:
  const std::string& s_;
  std::size_t pos_ = 0;
  int depth_ = 0;

  int col() const { return static_cast<int>(pos_) + 1; }
  void skip() {
    while (pos_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[pos_]))) ++pos_;
  }

  // expr := atom (op atom)*, all ops at one level equal.
  Network expr() {
    Network first = atom();
    skip();
    if (pos_ >= s_.size() || (s_[pos_] != '|' && s_[pos_] != '-')) return first;
    const char op = s_[pos_];
    Network group;
    group.kind = op == '|' ? Network::Kind::Parallel : Network::Kind::Series;
    group.column = first.column;
    group.children.push_back(std::move(first));
    while (pos_ < s_.size() && (s_[pos_] == '|' || s_[pos_] == '-')) {
      if (s_[pos_] != op)
        throw NetworkError(fmt::format("'{}' and '{}' mixed without parentheses at column {}; write e.g. "
                                       "b-(k|c) or (b-k)|c",
                                       op, s_[pos_], col()),
                           col());
      ++pos_;
      group.children.push_back(atom());
      skip();
    }
    return group;
  }

  Network atom() {
    skip();
    if (pos_ >= s_.size()) throw NetworkError(fmt::format("expression ends at column {}; expected an element or '('", col()), col());
    if (s_[pos_] == '(') {
      int open = col();
      if (++depth_ > max_nesting)  // bounded recursion (issue 15)
        throw NetworkError(fmt::format("parentheses nested more than {} deep at column {}", max_nesting, open), open);
      ++pos_;
      Network n = expr();
      --depth_;
      skip();
      if (pos_ >= s_.size() || s_[pos_] != ')')
        throw NetworkError(fmt::format("missing ')' for the '(' at column {}", open), pos_ < s_.size() ? col() : open);
      ++pos_;
      return n;
    }
    const char c = s_[pos_];
    if (c != 'k' && c != 'c' && c != 'b')
      throw NetworkError(fmt::format("unexpected '{}' at column {}; expected an element name starting with k "
                                     "(spring), c (damper) or b (inerter), or '('",
                                     c, col()),
                         col());
    Network leaf;
    leaf.column = col();
    leaf.kind = c == 'k' ? Network::Kind::Spring : c == 'c' ? Network::Kind::Damper : Network::Kind::Inerter;
    std::size_t start = pos_;
    while (pos_ < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[pos_])) || s_[pos_] == '_')) ++pos_;
    leaf.name = s_.substr(start, pos_ - start);
    return leaf;
  }
};

void collect(const Network& n, std::vector<std::string>& out, std::set<std::string>& seen) {
  if (n.is_element()) {
    if (seen.insert(n.name).second) out.push_back(n.name);
  }
  for (const auto& c : n.children) collect(c, out, seen);
}

}  // namespace

Network parse(const std::string& text) { return Parser(text).parse_all(); }

std::vector<std::string> parameter_names(const Network& net) {
  std::vector<std::string> out;
  std::set<std::string> seen;
  collect(net, out, seen);
  return out;
}

Network assign(const Network& net, const Params& params) {
  std::vector<std::string> names = parameter_names(net), missing;
  for (const auto& [name, value] : params) {
    bool known = false;
    for (const auto& n : names) known = known || n == name;
    if (!known) {
      std::string list;
      for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
      throw NetworkError(fmt::format("parameter '{}' is not an element of the network; its elements are: {}", name, list), 0);
    }
    if (!(value >= 0)) throw NetworkError(fmt::format("parameter '{}' = {} must be >= 0 (0 = open, inf = rigid)", name, value), 0);
  }
  for (const auto& n : names)
    if (!params.count(n)) missing.push_back(n);
  if (!missing.empty()) {
    std::string list;
    for (const auto& n : missing) list += (list.empty() ? "" : ", ") + n;
    throw NetworkError(fmt::format("no value for element(s) {}", list), 0);
  }
  Network out = net;
  auto set = [&](auto&& self, Network& n) -> void {
    if (n.is_element()) n.value = params.at(n.name);
    for (auto& c : n.children) self(self, c);
  };
  set(set, out);
  return out;
}

Network simplify(const Network& net) {
  using K = Network::Kind;
  if (net.is_element()) {
    if (net.value == 0) return Network{K::Open, net.name, 0, {}, net.column};
    if (std::isinf(net.value)) return Network{K::Rigid, net.name, 0, {}, net.column};
    return net;
  }
  if (net.kind == K::Open || net.kind == K::Rigid || net.kind == K::Admittance) return net;
  const bool parallel = net.kind == K::Parallel;
  const K absorbing = parallel ? K::Rigid : K::Open;  // one of these decides the whole group
  const K neutral = parallel ? K::Open : K::Rigid;    // these drop out
  Network out{net.kind, "", 0, {}, net.column};
  for (const auto& c : net.children) {
    Network s = simplify(c);
    if (s.kind == absorbing) return Network{absorbing, "", 0, {}, net.column};
    if (s.kind == neutral) continue;
    if (s.kind == net.kind) {  // flatten (a|b)|c
      for (auto& g : s.children) out.children.push_back(std::move(g));
    } else {
      out.children.push_back(std::move(s));
    }
  }
  if (out.children.empty()) return Network{neutral, "", 0, {}, net.column};
  if (out.children.size() == 1) return out.children.front();
  return out;
}

std::string to_string(const Network& net, bool with_values) {
  using K = Network::Kind;
  switch (net.kind) {
    case K::Open: return "open";
    case K::Rigid: return "rigid";
    case K::Admittance: {
      auto poly = [](const std::vector<double>& p) {
        std::string s;
        for (std::size_t i = 0; i < p.size(); ++i)
          if (p[i] != 0)
            s += fmt::format("{}{:.6g}{}", s.empty() ? "" : " + ", p[i], i == 0 ? "" : i == 1 ? " s" : fmt::format(" s^{}", i));
        return s.empty() ? std::string("0") : s;
      };
      return fmt::format("Y(s) = ({}) / ({})", poly(net.num), poly(net.den));
    }
    case K::Spring:
    case K::Damper:
    case K::Inerter: return with_values ? fmt::format("{}={:g}", net.name, net.value) : net.name;
    case K::Series:
    case K::Parallel: {
      std::string s;
      for (const auto& c : net.children) {
        std::string part = to_string(c, with_values);
        if (!c.is_element() && c.kind != K::Open && c.kind != K::Rigid) part = "(" + part + ")";
        s += (s.empty() ? "" : (net.kind == K::Series ? "-" : "|")) + part;
      }
      return s;
    }
  }
  return "?";
}

namespace {
std::complex<double> eval(const Network& net, std::complex<double> s) {
  using K = Network::Kind;
  switch (net.kind) {
    case K::Spring: return net.value / s;
    case K::Damper: return net.value;
    case K::Inerter: return net.value * s;
    case K::Open: return 0.0;
    case K::Rigid: return std::complex<double>(INFINITY, 0.0);
    case K::Admittance: {
      auto at = [&](const std::vector<double>& p) {
        std::complex<double> v = 0;
        for (std::size_t i = p.size(); i-- > 0;) v = v * s + p[i];
        return v;
      };
      return at(net.num) / at(net.den);
    }
    case K::Parallel: {
      std::complex<double> y = 0;
      for (const auto& c : net.children) y += eval(c, s);
      return y;
    }
    case K::Series: {
      std::complex<double> z = 0;
      for (const auto& c : net.children) z += 1.0 / eval(c, s);
      return 1.0 / z;
    }
  }
  return 0.0;
}
}  // namespace

Network admittance_leaf(std::vector<double> num, std::vector<double> den) {
  auto check = [](std::vector<double>& p, const char* what) {
    for (double c : p)
      if (!std::isfinite(c)) throw NetworkError(fmt::format("admittance: a {} coefficient is {}", what, c), 0);
    while (!p.empty() && p.back() == 0) p.pop_back();
    if (p.empty()) throw NetworkError(fmt::format("admittance: the {} is zero", what), 0);
  };
  check(num, "numerator");
  check(den, "denominator");
  Network n;
  n.kind = Network::Kind::Admittance;
  n.num = std::move(num), n.den = std::move(den);
  return n;
}

std::complex<double> admittance(const Network& net, std::complex<double> s) { return eval(simplify(net), s); }

}  // namespace inerta::network
