// Trace readers: traces.csv and SUMO FCD XML, and their error messages.
#include "TestTmp.hpp"
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

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
  EXPECT_EQ(tr.points[2].vehicle, 0);
  EXPECT_DOUBLE_EQ(tr.points[1].pos.z(), 1.0);
  EXPECT_DOUBLE_EQ(tr.points[0].heading_deg, 90.0);
}

TEST(Traces, ReadsFcdXmlAndConvertsTheAngle) {
  const auto p = tmpFile("fcd.xml",
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
  EXPECT_DOUBLE_EQ(tr.points[0].heading_deg, 90.0);  // north
  EXPECT_DOUBLE_EQ(tr.points[1].heading_deg, 0.0);   // east
  EXPECT_DOUBLE_EQ(tr.points[2].t, 0.1);
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
  const auto nan = tmpFile("nan.csv", "t,vehicle,x,y,z,heading_deg,speed\n0,a,nan,1,0,0,0\n1,a,1,1,0,0,0\n");
  const Traces tr = readTraces(nan);
  EXPECT_THROW(checkTraces(tr, "nan.csv"), std::invalid_argument);
}

}  // namespace
}  // namespace slamroute::roadgraph
