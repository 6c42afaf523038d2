// Trace readers: traces.csv and SUMO FCD XML, and their error messages.
#include <gtest/gtest.h>
#include "TestTmp.hpp"

#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "SyntheticTraces.hpp"
#include "slamroute/roadgraph/GraphBuilder.hpp"
#include "slamroute/roadgraph/Traces.hpp"

namespace slamroute::roadgraph {
namespace {

namespace fs = std::filesystem;

fs::path tmpFile(const std::string& name, const std::string& content) {
  const fs::path dir = slamroute::test::testTmp() / "roadgraph";
  fs::create_directories(dir);
  std::ofstream(dir / name) << content;
  return dir / name;
}

TEST(Traces, ReadsCsvByHeaderName) {
  const auto p = tmpFile("t.csv",
                         "t,vehicle,x,y,z,heading_deg,speed\n"
                         "0.0,car0,1.5,2.5,0.0,90,10\n"
                         "0.1,car1,3,4,1,0,5\n"
                         "0.2,car0,1.5,3.5,0.0,90,10\n");
  const Traces tr = readTraces(p);
  ASSERT_EQ(tr.points.size(), 3u);
  EXPECT_EQ(tr.vehicles.size(), 2u);
  // Points come in (vehicle name, time) order whatever the file's row order.
  EXPECT_EQ(tr.points[1].vehicle, 0);
  EXPECT_DOUBLE_EQ(tr.points[1].t, 0.2);
  EXPECT_EQ(tr.vehicles[static_cast<std::size_t>(tr.points[2].vehicle)], "car1");
  EXPECT_DOUBLE_EQ(tr.points[2].pos.z(), 1.0);
  EXPECT_DOUBLE_EQ(tr.points[0].heading_deg, 90.0);
}

TEST(Traces, TheGraphDoesNotDependOnTheRowOrder) {
  // The same rows shuffled: the same traces, so the same graph (ties on time within a vehicle
  // broken by position, vehicles numbered by name).
  const Traces synthetic = testing::makeTraces(testing::gridRoads(3, 100, 0), 0.5);
  std::vector<std::string> rows;
  for (const auto& p : synthetic.points) {
    std::ostringstream row;
    row.precision(10);
    row << p.t << "," << synthetic.vehicles[static_cast<std::size_t>(p.vehicle)] << "," << p.pos.x()
        << "," << p.pos.y() << ",0," << p.heading_deg << "," << p.speed << "\n";
    rows.push_back(row.str());
  }
  rows.push_back(rows[7]);  // a duplicated row: a tie on every key
  const std::string header = "t,vehicle,x,y,z,heading_deg,speed\n";
  std::string ordered = header, shuffled = header;
  for (const auto& r : rows) ordered += r;
  std::mt19937 rng(5);
  std::shuffle(rows.begin(), rows.end(), rng);
  for (const auto& r : rows) shuffled += r;
  const Traces a = readTraces(tmpFile("ordered.csv", ordered));
  const Traces b = readTraces(tmpFile("shuffled.csv", shuffled));
  ASSERT_EQ(a.points.size(), b.points.size());
  EXPECT_EQ(a.vehicles, b.vehicles);
  for (std::size_t i = 0; i < a.points.size(); ++i) {
    EXPECT_EQ(a.points[i].vehicle, b.points[i].vehicle) << i;
    EXPECT_EQ(a.points[i].t, b.points[i].t) << i;
    EXPECT_EQ(a.points[i].pos, b.points[i].pos) << i;
  }
  const auto ga = graphFromTraces(a, Config{}).graph, gb = graphFromTraces(b, Config{}).graph;
  EXPECT_EQ(ga.nodes.size(), gb.nodes.size());
  EXPECT_EQ(ga.edges.size(), gb.edges.size());
  EXPECT_DOUBLE_EQ(ga.totalLength(), gb.totalLength());
}

TEST(Traces, ReadsFcdXmlAndConvertsTheAngle) {
  const auto p =
      tmpFile("fcd.xml",
              "<fcd-export>\n"
              " <timestep time=\"0.00\">\n"
              "  <vehicle id=\"v0\" x=\"10\" y=\"20\" z=\"3\" angle=\"0\" speed=\"5\"/>\n"
              "  <vehicle id=\"v1\" x=\"11\" y=\"21\" angle=\"90\" speed=\"6\"/>\n"
              " </timestep>\n"
              " <timestep time=\"0.10\">\n"
              "  <vehicle id=\"v0\" x=\"10\" y=\"20.5\" z=\"3\" angle=\"0\" speed=\"5\"/>\n"
              " </timestep>\n"
              "</fcd-export>\n");
  const Traces tr = readTraces(p);
  ASSERT_EQ(tr.points.size(), 3u);
  // In (vehicle, time) order: v0 at 0.0 and 0.1, then v1.
  EXPECT_DOUBLE_EQ(tr.points[0].heading_deg, 90.0);  // north
  EXPECT_DOUBLE_EQ(tr.points[2].heading_deg, 0.0);   // east
  EXPECT_DOUBLE_EQ(tr.points[1].t, 0.1);
  EXPECT_DOUBLE_EQ(tr.points[0].pos.z(), 3.0);
  EXPECT_EQ(tr.vehicles.size(), 2u);
}

TEST(Traces, BadFilesGiveMessagesNamingTheFile) {
  EXPECT_THROW(readTraces("/nonexistent/traces.csv"), std::runtime_error);
  const auto nocol = tmpFile("nocol.csv", "t,vehicle,x,z\n0,a,1,2\n");
  try {
    readTraces(nocol);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("missing column 'y'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("nocol.csv"), std::string::npos);
  }
  const auto bad = tmpFile("bad.csv", "t,vehicle,x,y,z,heading_deg,speed\n0,a,1,oops,0,0,0\n");
  try {
    readTraces(bad);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("bad.csv:2"), std::string::npos) << e.what();
  }
  const auto badxml = tmpFile("bad.xml", "<fcd-export><timestep time=\"0\"><vehicle");
  EXPECT_THROW(readTraces(badxml), std::invalid_argument);
  const auto empty = tmpFile("empty.csv", "");
  EXPECT_THROW(readTraces(empty), std::invalid_argument);
  const auto nan =
      tmpFile("nan.csv", "t,vehicle,x,y,z,heading_deg,speed\n0,a,nan,1,0,0,0\n1,a,1,1,0,0,0\n");
  const Traces tr = readTraces(nan);
  EXPECT_THROW(checkTraces(tr, "nan.csv"), std::invalid_argument);
}

}  // namespace
}  // namespace slamroute::roadgraph
