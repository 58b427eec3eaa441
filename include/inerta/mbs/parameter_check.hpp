#pragma once
// Checks of physical parameters, shared by the constructors of bodies, force elements and time
// functions (and so, through them, by the model-file reader). Each check returns the value it was
// given, so that it can sit in a member initialiser, or throws inerta::InvalidArgument naming the
// element, the parameter and the value: "spring 'k1': k: must be >= 0 (N/m), got -5".
#include <Eigen/Core>
#include <string>
#include <string_view>

namespace inerta::mbs::check {

/// The element a parameter belongs to, for messages: kind "spring", name "k1" → "spring 'k1'";
/// without a name just the kind ("sine function").
struct Element {
  std::string_view kind;
  std::string_view name;
  std::string describe() const;
};

/// Throws InvalidArgument(who, parameter, problem).
[[noreturn]] void fail(const Element& who, const std::string& parameter, const std::string& problem);

/// v is a finite number (not NaN, not ±∞). `unit` (SI, may be empty) is shown in the message.
double finite(const Element& who, const std::string& parameter, double v, std::string_view unit = {});
/// v is finite and >= 0 (stiffness, damping, inertance, mass, length).
double nonnegative(const Element& who, const std::string& parameter, double v, std::string_view unit = {});
/// v is finite and > 0.
double positive(const Element& who, const std::string& parameter, double v, std::string_view unit = {});

/// Every coefficient of v is finite.
template <class V>
const V& finite_vector(const Element& who, const std::string& parameter, const V& v) {
  if (!v.allFinite()) fail(who, parameter, "must be finite (got a NaN or infinite component)");
  return v;
}
/// v is finite and not zero (a direction or an axis, normalised by the caller).
template <class V>
const V& direction(const Element& who, const std::string& parameter, const V& v) {
  finite_vector(who, parameter, v);
  if (!(v.norm() > 0)) fail(who, parameter, "must be a non-zero vector");
  return v;
}

}  // namespace inerta::mbs::check
