#include "slamroute/pipeline/SweepSpec.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <set>
#include <stdexcept>

namespace slamroute::pipeline {
namespace fs = std::filesystem;

namespace {

struct SpecError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// An existing file named relative to the spec's folder, as an absolute path.
std::string existingFile(const fs::path& base, const std::string& name, const char* what) {
  const fs::path p = fs::weakly_canonical(fs::absolute(base / name));
  if (!fs::is_regular_file(p)) throw SpecError(std::string(what) + " '" + name + "' not found");
  return p.string();
}

template <typename T>
std::vector<T> list(const YAML::Node& root, const char* key) {
  if (!root[key]) return {};
  if (!root[key].IsSequence()) throw SpecError(std::string("'") + key + "' must be a list");
  return root[key].as<std::vector<T>>();
}

std::vector<SweepVariant> readVariants(const YAML::Node& root, const fs::path& base) {
  std::vector<SweepVariant> out;
  if (!root["variants"]) return {SweepVariant{}};
  if (!root["variants"].IsSequence()) throw SpecError("'variants' must be a list");
  for (const auto& v : root["variants"]) {
    if (!v["name"]) throw SpecError("a variant without a name");
    SweepVariant sv{v["name"].as<std::string>(), ""};
    if (v["config"]) sv.config_file = existingFile(base, v["config"].as<std::string>(), "config");
    for (const auto& o : out)
      if (o.name == sv.name) throw SpecError("variant '" + sv.name + "' given twice");
    out.push_back(sv);
  }
  if (out.empty()) throw SpecError("'variants' is empty");
  return out;
}

SweepRow readRow(const YAML::Node& r, const fs::path& base) {
  if (!r["net"] || !r["planner"] || !r["seed"])
    throw SpecError("a row needs net, planner and seed");
  SweepRow row{existingFile(base, r["net"].as<std::string>(), "net"),
               r["planner"].as<std::string>(), r["seed"].as<std::uint64_t>(),
               r["variant"] ? r["variant"].as<std::string>() : "default"};
  return row;
}

void checkKeys(const YAML::Node& root) {
  static const std::set<std::string> known{"nets", "planners", "seeds", "variants", "rows"};
  if (!root.IsMap()) throw SpecError("not a YAML mapping");
  for (const auto& kv : root)
    if (!known.count(kv.first.as<std::string>()))
      throw SpecError("unknown key '" + kv.first.as<std::string>() + "'");
}

}  // namespace

SweepSpec SweepSpec::readYaml(const fs::path& file) {
  try {
    const YAML::Node root = YAML::LoadFile(file.string());
    checkKeys(root);
    const fs::path base = fs::absolute(file).parent_path();
    SweepSpec s;
    for (const auto& n : list<std::string>(root, "nets"))
      s.nets.push_back(existingFile(base, n, "net"));
    s.planners = list<std::string>(root, "planners");
    s.seeds = list<std::uint64_t>(root, "seeds");
    s.variants = readVariants(root, base);
    if (root["rows"])
      for (const auto& r : root["rows"]) s.rows.push_back(readRow(r, base));
    for (const auto& r : s.rows) s.variant(r.variant);  // throws on an unknown one
    if (s.expand().empty()) throw SpecError("no runs: give nets, planners and seeds, or rows");
    return s;
  } catch (const SpecError& e) {
    throw std::runtime_error(file.string() + ": " + e.what());
  } catch (const YAML::Exception& e) {
    throw std::runtime_error(file.string() + ": " + e.what());
  }
}

std::vector<SweepRow> SweepSpec::expand() const {
  std::vector<SweepRow> out;
  for (const auto& n : nets)
    for (const auto& v : variants)
      for (auto seed : seeds)
        for (const auto& p : planners) out.push_back({n, p, seed, v.name});
  for (const auto& r : rows)
    if (std::find(out.begin(), out.end(), r) == out.end()) out.push_back(r);
  return out;
}

const SweepVariant& SweepSpec::variant(const std::string& name) const {
  for (const auto& v : variants)
    if (v.name == name) return v;
  throw SpecError("unknown variant '" + name + "'");
}

std::string netStem(const std::string& net) {
  const std::string f = fs::path(net).filename().string();
  return f.substr(0, f.find('.'));
}

}  // namespace slamroute::pipeline
