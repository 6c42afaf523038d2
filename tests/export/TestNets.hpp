#pragma once
// Small SUMO nets made by netconvert for the export tests: a plus on the globe (nodes given in
// longitude / latitude, projected to UTM by netconvert) with named streets, and a named
// roundabout.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

namespace slamroute::test {

/// Longitude / latitude of the geo plus net's junctions (C centre, N/E/S/W arm ends).
struct GeoNode {
  const char* id;
  double lon, lat;
};
inline constexpr GeoNode kGeoPlus[] = {{"C", 13.400000, 52.500000},
                                       {"N", 13.400000, 52.501500},
                                       {"E", 13.402500, 52.500000},
                                       {"S", 13.400000, 52.498500},
                                       {"W", 13.397500, 52.500000}};

inline void writeFile(const std::filesystem::path& p, const std::string& s) {
  std::ofstream(p, std::ios::binary) << s;
}

inline std::filesystem::path netconvert(const std::filesystem::path& dir, const std::string& stem,
                                        const std::string& extra) {
  const auto net = dir / (stem + ".net.xml");
  const std::string cmd = "netconvert -n " + (dir / (stem + ".nod.xml")).string() + " -e " +
                          (dir / (stem + ".edg.xml")).string() + " " + extra + " -o " +
                          net.string() + " > " + (dir / (stem + ".log")).string() + " 2>&1";
  if (std::system(cmd.c_str()) != 0) throw std::runtime_error("netconvert failed: " + cmd);
  return net;
}

/// Two-way streets "North/East/South/West Street" from C to each arm end.
inline std::string plusEdges() {
  std::string e = "<edges>\n";
  for (const char* arm : {"N", "E", "S", "W"}) {
    const std::string a(arm);
    const std::string name = a == "N" ? "North" : a == "E" ? "East" : a == "S" ? "South" : "West";
    for (const std::string& id : {"C_" + a, a + "_C"})
      e += "  <edge id=\"" + id + "\" from=\"" + id.substr(0, 1) + "\" to=\"" + id.substr(2) +
           "\" name=\"" + name + " Street\" numLanes=\"1\" speed=\"13.89\"/>\n";
  }
  return e + "</edges>\n";
}

/// The plus with its junctions at kGeoPlus, UTM zone 33 chosen by netconvert.
inline std::filesystem::path geoPlusNet(const std::filesystem::path& dir) {
  std::string n = "<nodes>\n";
  for (const auto& g : kGeoPlus)
    n += "  <node id=\"" + std::string(g.id) + "\" x=\"" + std::to_string(g.lon) + "\" y=\"" +
         std::to_string(g.lat) + "\"" + (std::string(g.id) == "C" ? " type=\"priority\"" : "") +
         "/>\n";
  writeFile(dir / "geoplus.nod.xml", n + "</nodes>\n");
  writeFile(dir / "geoplus.edg.xml", plusEdges());
  return netconvert(dir, "geoplus", "--proj.utm");
}

/// A one-way counter-clockwise ring R0 (east) R1 (north) R2 (west) R3 (south) of radius 30 m
/// around (500, 500) with a two-way arm of 150 m at each: "Arm A<k> Road" to A<k>; the ring is
/// declared a <roundabout>.
inline std::filesystem::path roundaboutNet(const std::filesystem::path& dir) {
  const double dx[4] = {1, 0, -1, 0}, dy[4] = {0, 1, 0, -1};
  std::string n = "<nodes>\n", e = "<edges>\n", ring_nodes, ring_edges;
  for (int k = 0; k < 4; ++k) {
    const std::string r = "R" + std::to_string(k), a = "A" + std::to_string(k);
    const std::string next = "R" + std::to_string((k + 1) % 4);
    n += "  <node id=\"" + r + "\" x=\"" + std::to_string(500 + 30 * dx[k]) + "\" y=\"" +
         std::to_string(500 + 30 * dy[k]) + "\" type=\"priority\"/>\n";
    n += "  <node id=\"" + a + "\" x=\"" + std::to_string(500 + 180 * dx[k]) + "\" y=\"" +
         std::to_string(500 + 180 * dy[k]) + "\"/>\n";
    e += "  <edge id=\"" + r + "_" + next + "\" from=\"" + r + "\" to=\"" + next +
         "\" name=\"Ring\" numLanes=\"1\" speed=\"8.33\"/>\n";
    for (const auto& [f, t] : {std::pair{a, r}, std::pair{r, a}})
      e += "  <edge id=\"" + f + "_" + t + "\" from=\"" + f + "\" to=\"" + t + "\" name=\"Arm " +
           a + " Road\" numLanes=\"1\" speed=\"13.89\"/>\n";
    ring_nodes += (k ? " " : "") + r;
    ring_edges += (k ? " " : "") + r + "_" + next;
  }
  e += "  <roundabout nodes=\"" + ring_nodes + "\" edges=\"" + ring_edges + "\"/>\n";
  writeFile(dir / "ring.nod.xml", n + "</nodes>\n");
  writeFile(dir / "ring.edg.xml", e + "</edges>\n");
  return netconvert(dir, "ring", "--offset.disable-normalization");
}

}  // namespace slamroute::test
