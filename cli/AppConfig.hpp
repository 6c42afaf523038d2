#pragma once
// The whole configuration of slamroute: one section per module. `slamroute config --dump`
// prints it; `--config FILE.yaml` overrides only the keys present.
#include <cstdint>
#include <string>

#include "slamroute/evaluate/Config.hpp"
#include "slamroute/explore/Config.hpp"
#include "slamroute/rl/Config.hpp"
#include "slamroute/roadgraph/Config.hpp"
#include "slamroute/simulate/Config.hpp"

namespace slamroute::cli {

struct AppConfig {
  std::uint64_t seed = 42;  ///< global seed; --seed overrides
  roadgraph::Config roadgraph;
  rl::Config rl;
  simulate::Config simulate;
  evaluate::Config evaluate;
  explore::Config explore;
};

template <class V>
void visitFields(V& v, AppConfig& c) {
  v.field("seed", c.seed, "global random seed (same seed, same output)");
  v.section("roadgraph", c.roadgraph);
  v.section("rl", c.rl);
  v.section("simulate", c.simulate);
  v.section("evaluate", c.evaluate);
  v.section("explore", c.explore);
}

}  // namespace slamroute::cli
