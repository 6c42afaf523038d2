#pragma once
// Real city nets the tests run on. Debian's sumo-tools package (scripts/setup.sh installs it)
// ships them with SUMO's scenarios and games, so a clone finds them without any folder beside it.
// A missing one fails the test that asks for it instead of skipping it.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace slamroute::test {

/// `rel` below $SUMO_HOME/tools (Debian: /usr/share/sumo/tools).
inline std::filesystem::path sumoToolsNet(const std::string& rel) {
  const char* home = std::getenv("SUMO_HOME");
  const std::filesystem::path p =
      std::filesystem::path(home && *home ? home : "/usr/share/sumo") / "tools" / rel;
  EXPECT_TRUE(std::filesystem::exists(p)) << p << " missing: scripts/setup.sh installs sumo-tools";
  return p;
}

/// Bologna, Via Andrea Costa (EPL-2.0, OpenStreetMap data): 112 junctions, one-way streets,
/// forbidden U-turns and one two-lane roundabout.
inline std::filesystem::path bolognaNet() {
  return sumoToolsNet("sumolib/scenario/scenarios/RealWorld/acosta/acosta_buslanes.net.xml");
}

/// Berlin-Adlershof (OpenStreetMap, junctions joined by netconvert): 1,033 junctions, 365 on the
/// largest strongly connected part.
inline std::filesystem::path adlershofNet() { return sumoToolsNet("game/DRT/osm.net.xml"); }

/// Braunschweig's city centre (SUMO's 3D game).
inline std::filesystem::path braunschweigNet() { return sumoToolsNet("game/bs3d/bs.net.xml"); }

}  // namespace slamroute::test
