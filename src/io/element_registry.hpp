#pragma once
// A table from an item type of a model file (the `type:` of a force element or a joint) to the
// keys that type accepts and the function that builds it. Each type is registered once, with one
// line (design.md: extension points registered once); the parser looks the type up here instead
// of branching over the types, and the unknown-type and unknown-key messages list exactly what is
// registered.
#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "model_reader.hpp"

namespace inerta::io::detail {

template <class Builder>
class ElementRegistry {
 public:
  struct Entry {
    std::string type;               ///< the `type:` value, e.g. "spring"
    std::vector<std::string> keys;  ///< accepted keys besides `name` and `type`, in the order messages list them
    Builder build;                  ///< never null
    std::string hint;               ///< appended to the unknown-key message (may be empty)
  };

  /// `kind` names the items in messages: "force element", "joint".
  explicit ElementRegistry(std::string kind) : kind_(std::move(kind)) {}

  /// Registers `type`. A type registered twice, an empty type, no builder, no keys, or a key
  /// `name`/`type`/given twice is a programming error (std::logic_error).
  ElementRegistry& add(std::string type, std::vector<std::string> keys, Builder build, std::string hint = {}) {
    auto bad = [&](const std::string& why) {
      throw std::logic_error(fmt::format("{} registry: type '{}': {}", kind_, type, why));
    };
    if (type.empty()) bad("empty type name");
    if (find(type)) bad("registered twice");
    if (!build) bad("no builder");
    if (keys.empty()) bad("no keys");
    for (std::size_t i = 0; i < keys.size(); ++i) {
      if (keys[i] == "name" || keys[i] == "type") bad("'name' and 'type' are implied");
      for (std::size_t j = 0; j < i; ++j)
        if (keys[j] == keys[i]) bad("key '" + keys[i] + "' listed twice");
    }
    entries_.push_back({std::move(type), std::move(keys), build, std::move(hint)});
    return *this;
  }

  /// The entry of `type`, nullptr if it is not registered.
  const Entry* find(const std::string& type) const {
    for (const Entry& e : entries_)
      if (e.type == type) return &e;
    return nullptr;
  }
  const std::vector<Entry>& entries() const { return entries_; }
  const std::string& kind() const { return kind_; }

  /// The registered types for messages, in registration order: "spring, damper or inerter".
  std::string type_list() const {
    std::string s;
    for (std::size_t i = 0; i < entries_.size(); ++i)
      s += (i == 0 ? "" : i + 1 == entries_.size() ? " or " : ", ") + entries_[i].type;
    return s;
  }

  /// The accepted keys of an entry: name, type, then its own.
  static std::vector<std::string> accepted_keys(const Entry& e) {
    std::vector<std::string> k{"name", "type"};
    k.insert(k.end(), e.keys.begin(), e.keys.end());
    return k;
  }

  /// The entry of item's `type`, after checking item's keys against it. ModelError at the line of
  /// `type` for an unknown type ("unknown <kind> type 'x'; expected <type_list>") and at the key's
  /// line for a key the type does not accept.
  const Entry& entry(const Reader& rd, const YAML::Node& item, const std::string& what) const {
    const std::string type = rd.text(item, "type", what);
    const Entry* e = find(type);
    if (!e) rd.fail(item["type"], "type", fmt::format("unknown {} type '{}'; expected {}", kind_, type, type_list()));
    rd.keys(item, what, accepted_keys(*e), e->hint);
    return *e;
  }

 private:
  std::string kind_;
  std::vector<Entry> entries_;
};

}  // namespace inerta::io::detail
