#pragma once
// Paths of the SUMO nets the tests read. Every net a test needs is either in the repository
// (networks/: the generated default city and test nets, and the two real city nets under
// networks/real/) or installed by Debian's sumo-tools, which scripts/setup.sh installs, so a
// clone runs every test.
#include <cstdlib>
#include <filesystem>
#include <string>

namespace slamroute::test {

/// A net shipped under networks/, e.g. shippedNet("test/plus.net.xml").
inline std::filesystem::path shippedNet(const std::string& rel) {
  return std::filesystem::path(SLAMROUTE_SOURCE_DIR) / "networks" / rel;
}
inline std::filesystem::path defaultCityNet() {
  return shippedNet("default_city/default_city.net.xml");
}
/// Bologna, Andrea Costa quarter (DLR sumo-scenarios; networks/real/bologna_acosta/SOURCE.txt).
inline std::filesystem::path bolognaNet() {
  return shippedNet("real/bologna_acosta/acosta_buslanes.net.xml");
}
/// Ingolstadt, 21 junctions with traffic lights and their surroundings (InTAS via RESCO;
/// networks/real/ingolstadt21/SOURCE.txt).
inline std::filesystem::path ingolstadtNet() {
  return shippedNet("real/ingolstadt21/ingolstadt21.net.xml");
}
/// A net of Debian's sumo-tools below SUMO_HOME (default /usr/share/sumo), e.g.
/// sumoToolsNet("tools/game/DRT/osm.net.xml").
inline std::filesystem::path sumoToolsNet(const std::string& rel) {
  const char* home = std::getenv("SUMO_HOME");
  return std::filesystem::path(home && *home ? home : "/usr/share/sumo") / rel;
}

}  // namespace slamroute::test
