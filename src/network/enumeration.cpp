#include "inerta/network/enumeration.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace inerta::network {

namespace {
using K = Network::Kind;

int type_rank(K k) { return k == K::Spring ? 0 : k == K::Damper ? 1 : 2; }
char type_letter(K k) { return k == K::Spring ? 'k' : k == K::Damper ? 'c' : 'b'; }

void check_simplified(const Network& n) {
  if (n.kind == K::Open || n.kind == K::Rigid)
    throw NetworkError("canonical form: the network has open or rigid parts; simplify it first", n.column);
  if (n.kind == K::Admittance) throw NetworkError("canonical form: the network is a given admittance, not elements", 0);
}

// The structure string of a network already in canonical form (its members canonical too, so
// nothing is put in canonical form again: the enumeration sorts thousands of such trees).
std::string canonical_structure(const Network& c) {
  if (c.is_element()) return std::string(1, type_letter(c.kind));
  std::string s;
  for (const auto& m : c.children) {
    if (!s.empty()) s += c.kind == K::Series ? '-' : '|';
    if (m.is_element()) {
      s += type_letter(m.kind);
    } else {  // appended piecewise: "(" + string trips GCC 12's -Wrestrict false positive
      s += '(';
      s += canonical_structure(m);
      s += ')';
    }
  }
  return s;
}

// Members in canonical order: elements by type (k, c, b), then groups by size, then structure. The
// key of a member already in canonical form.
std::pair<int, std::string> order_key(const Network& n);

// A pole of Y at s = 0 (a static stiffness): the denominator's constant term vanishes.
bool n_den_constant(const Network& n) { return !n.den.empty() && n.den[0] != 0; }

double combine(double a, double b, bool parallel) {
  if (parallel) return a + b;
  if (a == 0 || b == 0) return 0;  // unassigned values stay unassigned
  return 1 / (1 / a + 1 / b);
}
}  // namespace

ElementCounts count_elements(const Network& net) {
  ElementCounts c;
  if (net.is_element()) {
    c.elements = 1;
    (net.kind == K::Spring ? c.springs : net.kind == K::Damper ? c.dampers : c.inerters) = 1;
    return c;
  }
  for (const auto& m : net.children) {
    const ElementCounts d = count_elements(m);
    c.elements += d.elements, c.springs += d.springs, c.dampers += d.dampers, c.inerters += d.inerters;
  }
  return c;
}

namespace {
std::pair<int, std::string> order_key(const Network& n) {
  if (n.is_element()) return {type_rank(n.kind) - 3, ""};
  return {count_elements(n).elements, canonical_structure(n)};
}
}  // namespace

bool static_path(const Network& net) {
  switch (net.kind) {
    case K::Spring: return true;
    case K::Rigid: return true;
    case K::Admittance: return !n_den_constant(net);
    case K::Series: return std::all_of(net.children.begin(), net.children.end(), static_path);
    case K::Parallel: return std::any_of(net.children.begin(), net.children.end(), static_path);
    default: return false;
  }
}

Network canonical(const Network& net) {
  check_simplified(net);
  if (net.is_element()) return net;
  const bool parallel = net.kind == K::Parallel;
  std::vector<Network> members;
  for (const auto& c : net.children) {
    Network m = canonical(c);
    if (m.kind == net.kind) {  // flatten (a|b)|c
      for (auto& g : m.children) members.push_back(std::move(g));
    } else {
      members.push_back(std::move(m));
    }
  }
  Network out{net.kind, "", 0, {}, net.column};
  for (auto& m : members) {
    if (m.is_element()) {
      auto same = std::find_if(out.children.begin(), out.children.end(),
                               [&](const Network& o) { return o.kind == m.kind; });
      if (same != out.children.end()) {  // k1|k2 = k (eq. of spec/03 §3.1: admittances add)
        same->value = combine(same->value, m.value, parallel);
        continue;
      }
    }
    out.children.push_back(std::move(m));
  }
  if (out.children.size() == 1) return out.children.front();
  // Each member's key once, then a stable sort of the members by it.
  std::vector<std::pair<std::pair<int, std::string>, std::size_t>> keys;
  for (std::size_t i = 0; i < out.children.size(); ++i) keys.push_back({order_key(out.children[i]), i});
  std::stable_sort(keys.begin(), keys.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<Network> sorted;
  sorted.reserve(keys.size());
  for (const auto& k : keys) sorted.push_back(std::move(out.children[k.second]));
  out.children = std::move(sorted);
  return out;
}

std::string structure(const Network& net) {
  check_simplified(net);
  return canonical_structure(canonical(net));
}

namespace {
void count_types(const Network& n, std::map<char, int>& total) {
  if (n.is_element()) ++total[type_letter(n.kind)];
  for (const auto& c : n.children) count_types(c, total);
}
void rename(Network& n, const std::map<char, int>& total, std::map<char, int>& next) {
  if (n.is_element()) {
    const char t = type_letter(n.kind);
    n.name = total.at(t) == 1 ? std::string(1, t) : fmt::format("{}{}", t, ++next[t]);
  }
  for (auto& c : n.children) rename(c, total, next);
}

// All canonical networks of exactly n elements whose root is of `kind` (an element type for
// n = 1, Series or Parallel), over the allowed element types. Memoised per (n, kind).
class Generator {
 public:
  explicit Generator(std::vector<K> types) : types_(std::move(types)) {}

  const std::vector<Network>& trees(int n, K kind) {
    auto key = std::make_pair(n, static_cast<int>(kind));
    if (auto it = memo_.find(key); it != memo_.end()) return it->second;
    std::vector<Network> out;
    if (kind == K::Series || kind == K::Parallel) {
      const K other = kind == K::Series ? K::Parallel : K::Series;
      // A group: a set of distinct element types (merged ones are one element) and a multiset of
      // groups of the other kind with the remaining elements; at least two members.
      const int nt = static_cast<int>(types_.size());
      for (unsigned mask = 0; mask < (1u << nt); ++mask) {
        std::vector<Network> leaves;
        for (int t = 0; t < nt; ++t)
          if ((mask >> t) & 1u) leaves.push_back(Network{types_[static_cast<std::size_t>(t)], "", 0, {}, 0});
        const int rest = n - static_cast<int>(leaves.size());
        if (rest < 0) continue;
        std::vector<std::vector<const Network*>> sets;
        std::vector<const Network*> cur;
        multisets(rest, other, 2, 0, n - 1, cur, sets);
        for (const auto& set : sets) {
          if (leaves.size() + set.size() < 2) continue;
          Network g{kind, "", 0, leaves, 0};
          for (const Network* m : set) g.children.push_back(*m);
          out.push_back(canonical(g));
        }
      }
      // By structure, each tree's string made once (its members are canonical already).
      std::vector<std::pair<std::string, std::size_t>> keys;
      for (std::size_t i = 0; i < out.size(); ++i) keys.push_back({canonical_structure(out[i]), i});
      std::sort(keys.begin(), keys.end());
      std::vector<Network> sorted;
      sorted.reserve(out.size());
      for (const auto& k : keys) sorted.push_back(std::move(out[k.second]));
      out = std::move(sorted);
    } else if (n == 1) {
      out.push_back(Network{kind, "", 0, {}, 0});
    }
    return memo_[key] = std::move(out);
  }

 private:
  // Multisets of groups of `kind` with sizes in [min_size, max_size] summing to `total`, as
  // nondecreasing (size, index) sequences so that each multiset appears once.
  void multisets(int total, K kind, int min_size, std::size_t min_index, int max_size, std::vector<const Network*>& cur,
                 std::vector<std::vector<const Network*>>& out) {
    if (total == 0) {
      out.push_back(cur);
      return;
    }
    for (int s = min_size; s <= std::min(total, max_size); ++s) {
      const std::vector<Network>& ts = trees(s, kind);
      for (std::size_t i = s == min_size ? min_index : 0; i < ts.size(); ++i) {
        cur.push_back(&ts[i]);
        multisets(total - s, kind, s, i, max_size, cur, out);
        cur.pop_back();
      }
    }
  }

  std::vector<K> types_;
  std::map<std::pair<int, int>, std::vector<Network>> memo_;
};
}  // namespace

Network renamed(const Network& net) {
  std::map<char, int> total, next;
  count_types(net, total);
  Network out = net;
  rename(out, total, next);
  return out;
}

std::vector<std::string> enumerate(const EnumerationOptions& o) {
  if (o.max_elements < 1 || o.max_elements > max_enumerated_elements)
    throw NetworkError(fmt::format("networks: max_elements must be 1 … {}, not {}", max_enumerated_elements,
                                   o.max_elements),
                       0);
  for (int limit : {o.max_springs, o.max_dampers, o.max_inerters})
    if (limit < -1) throw NetworkError(fmt::format("networks: a type limit must be ≥ 0 (or -1: none), not {}", limit), 0);
  std::vector<K> types;
  if (o.springs) types.push_back(K::Spring);
  if (o.dampers) types.push_back(K::Damper);
  if (o.inerters) types.push_back(K::Inerter);
  if (types.empty()) throw NetworkError("networks: no element type allowed (springs, dampers, inerters all off)", 0);
  Generator gen(types);
  auto within = [](int n, int limit) { return limit < 0 || n <= limit; };
  std::vector<std::string> out;
  for (int n = 1; n <= o.max_elements; ++n) {
    std::vector<Network> all;
    if (n == 1)
      for (K t : types) all.push_back(Network{t, "", 0, {}, 0});
    for (K kind : {K::Series, K::Parallel})
      for (const auto& t : gen.trees(n, kind)) all.push_back(t);
    std::vector<std::pair<std::string, std::string>> layer;  // (structure, expression)
    for (const auto& t : all) {
      const ElementCounts c = count_elements(t);
      if (!within(c.springs, o.max_springs) || !within(c.dampers, o.max_dampers) ||
          !within(c.inerters, o.max_inerters))
        continue;
      const bool sp = static_path(t);
      if ((o.static_load == StaticLoad::Required && !sp) || (o.static_load == StaticLoad::Excluded && sp)) continue;
      layer.emplace_back(canonical_structure(t), to_string(renamed(t)));
    }
    std::sort(layer.begin(), layer.end());
    for (auto& [s, e] : layer) out.push_back(std::move(e));
  }
  return out;
}

}  // namespace inerta::network
