#pragma once
// YAML dump/load for plain config structs, without repeating field lists.
//
// A config struct opts in with a free function found by ADL, listing every field once:
//
//   template <class V> void visitFields(V& v, MyConfig& c) {
//     v.field("inner_radius_m", c.inner_radius_m, "hollow cylinder inner radius [m]");
//     v.section("lidar", c.lidar);   // nested struct with its own visitFields
//     v.moved("old_key", "lidar.new_key");  // a key that moved: loading it is an error naming
//   }                                        // where it lives now
//
// dumpYaml() writes every field with its default and comment; loadYaml() overrides only the keys
// present and rejects unknown keys (a typo in a config file is an error, not a silent default).
// A struct with a `void validate() const` (throwing std::invalid_argument "key must be ...") is
// checked as soon as its section is loaded (validateSection).
#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "slamroute/core/ConfigCheck.hpp"

namespace slamroute::config {

class Dumper {
 public:
  explicit Dumper(std::ostringstream& os, int indent = 0) : os_(os), indent_(indent) {}

  template <class T>
  void field(const char* key, T& value, const char* comment) {
    pad();
    os_ << key << ": " << format(value);
    if (comment && *comment) os_ << "  # " << comment;
    os_ << "\n";
  }
  template <class S>
  void section(const char* key, S& sub) {
    pad();
    os_ << key << ":\n";
    Dumper inner(os_, indent_ + 2);
    visitFields(inner, sub);
  }
  void moved(const char*, const char*) {}

 private:
  void pad() { os_ << std::string(static_cast<std::size_t>(indent_), ' '); }
  static std::string format(bool b) { return b ? "true" : "false"; }
  static std::string format(const std::string& s) { return "\"" + s + "\""; }
  template <class T>
  static std::string format(const std::vector<T>& v) {
    std::ostringstream o;
    o << "[";
    for (std::size_t i = 0; i < v.size(); ++i) o << (i ? ", " : "") << format(v[i]);
    o << "]";
    return o.str();
  }
  template <class T>
  static std::string format(const T& v) {
    std::ostringstream o;
    o.precision(10);
    o << v;
    return o.str();
  }
  std::ostringstream& os_;
  int indent_;
};

/// Runs a section's validate() (when it has one) right after the section is loaded, so a value
/// that cannot work fails before any work with "FILE: section.sub.key ..." instead of after a run.
template <class S>
void validateSection(const S& sub, const std::string& file, const std::string& path) {
  if constexpr (requires { sub.validate(); }) validateSubsection(file + ": " + path, sub);
}

class Loader {
 public:
  Loader(const YAML::Node& node, std::string where)
      : node_(node), where_(where), file_(std::move(where)) {}

  template <class T>
  void field(const char* key, T& value, const char*) {
    seen_.push_back(key);
    const YAML::Node n = node_[key];
    if (!n) return;
    try {
      value = n.as<T>();
    } catch (const YAML::Exception&) {
      throw std::invalid_argument(where_ + ": key '" + key + "' has a value of the wrong type");
    }
  }
  template <class S>
  void section(const char* key, S& sub) {
    seen_.push_back(key);
    const YAML::Node n = node_[key];
    if (!n) return;
    if (!n.IsMap()) throw std::invalid_argument(where_ + ": '" + key + "' must be a mapping");
    Loader inner(n, where_ + ":" + key, file_, path_ + key + ".");
    visitFields(inner, sub);
    inner.checkUnknown();
    validateSection(sub, file_, inner.path_);
  }
  void moved(const char* old_key, const char* new_key) { moved_.emplace_back(old_key, new_key); }
  void checkUnknown() const {
    for (const auto& kv : node_) {
      if (!kv.first.IsScalar()) throw std::invalid_argument(where_ + ": a key is not a plain name");
      const auto k = kv.first.as<std::string>();
      bool known = false;
      for (const auto& s : seen_) known = known || s == k;
      if (known) continue;
      for (const auto& [old_key, new_key] : moved_)
        if (old_key == k)
          throw std::invalid_argument(where_ + ": key '" + k + "' is now '" + new_key + "'");
      throw std::invalid_argument(where_ + ": unknown key '" + k + "'");
    }
  }

 private:
  Loader(const YAML::Node& node, std::string where, std::string file, std::string path)
      : node_(node), where_(std::move(where)), file_(std::move(file)), path_(std::move(path)) {}
  YAML::Node node_;
  std::string where_;
  std::string file_;  ///< the config file, for validate()'s messages
  std::string path_;  ///< "section.sub." of this loader's keys
  std::vector<std::string> seen_;
  std::vector<std::pair<std::string, std::string>> moved_;
};

/// Full YAML text of a config struct with its current values and comments.
template <class C>
std::string dumpYaml(C cfg) {
  std::ostringstream os;
  Dumper d(os);
  visitFields(d, cfg);
  return os.str();
}

/// Overrides the fields present in `node`. `where` names the source (file) for error messages.
template <class C>
void loadYaml(const YAML::Node& node, C& cfg, const std::string& where) {
  if (!node || node.IsNull()) return;
  if (!node.IsMap()) throw std::invalid_argument(where + ": expected a YAML mapping");
  Loader l(node, where);
  visitFields(l, cfg);
  l.checkUnknown();
  validateSection(cfg, where, "");
}

}  // namespace slamroute::config
