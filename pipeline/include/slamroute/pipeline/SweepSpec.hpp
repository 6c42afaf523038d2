#pragma once
// What a sweep compares: nets x planners x seeds x config variants (a grid), and/or explicit
// rows. Read from a YAML file:
//
//   nets: [networks/test/plus.net.xml, networks/test/ring.net.xml]  # relative to the spec file
//   planners: [qlearning, random]
//   seeds: [1, 2]
//   variants:                      # optional; default: one variant "default" with no config
//     - {name: fast, config: fast.yaml}
//   rows:                          # optional: runs beyond the grid
//     - {net: networks/test/grid3x3.net.xml, planner: postman, seed: 7, variant: fast}
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace slamroute::pipeline {

struct SweepVariant {
  std::string name = "default";
  std::string config_file;  ///< absolute; empty: built-in defaults
};

/// One pipeline run of the study: a route planned, driven and evaluated.
struct SweepRow {
  std::string net;  ///< absolute path of the SUMO net
  std::string planner;
  std::uint64_t seed = 0;
  std::string variant = "default";

  bool operator==(const SweepRow&) const = default;
};

struct SweepSpec {
  std::vector<std::string> nets, planners;  ///< nets as absolute paths
  std::vector<std::uint64_t> seeds;
  std::vector<SweepVariant> variants;  ///< at least one
  std::vector<SweepRow> rows;          ///< explicit rows beyond the grid

  /// Reads and validates a spec; throws std::runtime_error with one line naming the file and the
  /// problem (unknown key, missing net or config file, unknown variant, empty study, ...).
  static SweepSpec readYaml(const std::filesystem::path& file);

  /// The grid's rows (net, variant, seed, planner order) then the explicit ones not in it.
  std::vector<SweepRow> expand() const;

  const SweepVariant& variant(const std::string& name) const;
};

/// The net's name: its file name up to the first dot.
std::string netStem(const std::string& net);

}  // namespace slamroute::pipeline
