#include <gtest/gtest.h>
#include <zlib.h>

#include <cstring>
#include <tuple>
#include <vector>

#include "SumoToolsNets.hpp"
#include "TestUtil.hpp"
#include "slamroute/core/AtomicFile.hpp"
#include "slamroute/core/DriveGraph.hpp"
#include "slamroute/core/SumoNet.hpp"

namespace slamroute {
namespace {

// A tiny net written by hand: junctions A-B-C in a line, two-way A-B, one-way B->C, a bus-only
// edge C->A, mixed 2D/3D shapes, an unknown newer vehicle class and projection "!".
const char* kTinyNet = R"(<?xml version="1.0"?>
<net version="1.9">
  <location netOffset="0.00,0.00" convBoundary="0,0,200,0" origBoundary="0,0,200,0" projParameter="!"/>
  <edge id=":B_0" function="internal"><lane id=":B_0_0" index="0" speed="10" length="5" shape="99,0 101,0"/></edge>
  <edge id="AB" from="A" to="B" priority="1">
    <lane id="AB_0" index="0" speed="13.89" length="100" shape="0,-1.6,0 50,-1.6 100,-1.6,2.5"/>
  </edge>
  <edge id="BA" from="B" to="A" priority="1">
    <lane id="BA_0" index="0" speed="13.89" length="100" shape="100,1.6 0,1.6"/>
  </edge>
  <edge id="BC" from="B" to="C" priority="1">
    <lane id="BC_0" index="0" speed="13.89" length="100" disallow="pedestrian cable_car" shape="100,0 200,0"/>
  </edge>
  <edge id="CA" from="C" to="A" priority="1">
    <lane id="CA_0" index="0" speed="13.89" length="200" allow="bus cable_car" shape="200,5 0,5"/>
  </edge>
  <junction id="A" type="priority" x="0" y="0" incLanes="BA_0 CA_0" intLanes="" shape=""/>
  <junction id="B" type="priority" x="100" y="0" z="2.5" incLanes="AB_0" intLanes=":B_0_0" shape=""/>
  <junction id="C" type="dead_end" x="200" y="0" incLanes="BC_0" intLanes="" shape=""/>
  <junction id=":B_0_0" type="internal" x="100" y="0" incLanes="" intLanes=""/>
  <connection from="AB" to="BC" fromLane="0" toLane="0" via=":B_0_0" dir="s" state="M"/>
  <connection from="AB" to="BA" fromLane="0" toLane="0" dir="t" state="M"/>
  <connection from=":B_0" to="BC" fromLane="0" toLane="0" dir="s" state="M"/>
</net>
)";

TEST(SumoNet, ReadsJunctionsEdgesShapesAndTurns) {
  const auto dir = test::tempDir("sumonet_tiny");
  test::writeText(dir / "tiny.net.xml", kTinyNet);
  const SumoNet net = SumoNet::read(dir / "tiny.net.xml");
  EXPECT_EQ(net.junctions.size(), 3u);  // the internal junction is skipped
  EXPECT_EQ(net.edges.size(), 4u);      // the internal edge is skipped
  EXPECT_EQ(net.location.proj_parameter, "!");
  const SumoEdge* ab = net.findEdge("AB");
  ASSERT_NE(ab, nullptr);
  ASSERT_EQ(ab->lanes[0].shape.size(), 3u);
  EXPECT_DOUBLE_EQ(ab->lanes[0].shape[2].z(), 2.5);  // 3D point
  EXPECT_DOUBLE_EQ(ab->lanes[0].shape[1].z(), 0.0);  // 2D point in the same shape
  EXPECT_DOUBLE_EQ(net.findJunction("B")->pos.z(), 2.5);
  EXPECT_TRUE(net.findEdge("BC")->allowsPassenger());   // disallow list without passenger
  EXPECT_FALSE(net.findEdge("CA")->allowsPassenger());  // bus only (+ an unknown class)
  EXPECT_TRUE(net.turnAllowed("AB", "BC"));
  EXPECT_TRUE(net.turnAllowed("AB", "BA"));
  EXPECT_FALSE(net.turnAllowed("BA", "AB"));
}

TEST(SumoNet, DriveGraphAndStrongComponent) {
  const auto dir = test::tempDir("sumonet_tiny_dg");
  test::writeText(dir / "tiny.net.xml", kTinyNet);
  const SumoNet net = SumoNet::read(dir / "tiny.net.xml");
  const NetworkInfo info = networkInfo(net);
  EXPECT_EQ(info.junctions, 3u);
  EXPECT_EQ(info.passenger_edges, 3u);  // AB, BA, BC
  EXPECT_EQ(info.lscc_junctions, 2u);   // A <-> B; C is a one-way dead end
  EXPECT_EQ(info.lscc_edges, 2u);
  EXPECT_NEAR(info.total_length_m, 300.0, 1e-9);
}

TEST(SumoNet, ReadsGzip) {
  const auto dir = test::tempDir("sumonet_gz");
  const auto gz = dir / "tiny.net.xml.gz";
  gzFile f = gzopen(gz.c_str(), "wb");
  gzwrite(f, kTinyNet, static_cast<unsigned>(std::strlen(kTinyNet)));
  gzclose(f);
  EXPECT_EQ(SumoNet::read(gz).edges.size(), 4u);
  // Truncated gzip: a clear error naming the file.
  const std::string raw = readFile(gz);
  test::writeText(dir / "cut.net.xml.gz", raw.substr(0, raw.size() / 2));
  try {
    SumoNet::read(dir / "cut.net.xml.gz");
    FAIL() << "truncated gzip accepted";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("cut.net.xml.gz"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("gzip"), std::string::npos) << e.what();
  }
}

std::string gzipBytes(const std::filesystem::path& scratch, const std::string& text) {
  gzFile f = gzopen(scratch.c_str(), "wb");
  gzwrite(f, text.data(), static_cast<unsigned>(text.size()));
  gzclose(f);
  return readFile(scratch);
}

TEST(SumoNet, ReadsEveryMemberOfAMultiStreamGzip) {
  // `cat a.gz b.gz`: the net split in two gzip members, as SUMO scenario archives ship them.
  const auto dir = test::tempDir("sumonet_gz_multi");
  const std::string text = kTinyNet;
  const std::string a = gzipBytes(dir / "a.gz", text.substr(0, 200));
  const std::string b = gzipBytes(dir / "b.gz", text.substr(200));
  test::writeText(dir / "two.net.xml.gz", a + b);
  EXPECT_EQ(readMaybeGzip(dir / "two.net.xml.gz"), text);
  EXPECT_EQ(SumoNet::read(dir / "two.net.xml.gz").edges.size(), 4u);
  // Zero padding after the last member is ignored (gzip does the same); other bytes are not.
  test::writeText(dir / "padded.net.xml.gz", a + b + std::string(512, '\0'));
  EXPECT_EQ(readMaybeGzip(dir / "padded.net.xml.gz"), text);
  test::writeText(dir / "junk.net.xml.gz", a + b + "junk");
  EXPECT_THROW(readMaybeGzip(dir / "junk.net.xml.gz"), std::runtime_error);
  // A second member cut short is a truncated file, not a short net.
  test::writeText(dir / "cut2.net.xml.gz", a + b.substr(0, b.size() / 2));
  try {
    readMaybeGzip(dir / "cut2.net.xml.gz");
    FAIL() << "truncated second member accepted";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("cut2.net.xml.gz: truncated"), std::string::npos)
        << e.what();
  }
}

void expectError(const std::filesystem::path& p, const std::string& fragment) {
  try {
    const SumoNet net = SumoNet::read(p);
    networkInfo(net);
    FAIL() << p << " accepted";
  } catch (const std::exception& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(p.filename().string()), std::string::npos) << msg;
    EXPECT_NE(msg.find(fragment), std::string::npos) << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << "error must be one line: " << msg;
  }
}

TEST(SumoNet, BadInputsGiveOneLineErrors) {
  const auto dir = test::tempDir("sumonet_bad");
  expectError(dir / "missing.net.xml", "not found");
  test::writeText(dir / "text.net.xml", "this is not xml <<<");
  expectError(dir / "text.net.xml", "not valid XML");
  test::writeText(dir / "other.net.xml",
                  "<?xml version=\"1.0\"?><routes><vehicle id=\"a\"/></routes>");
  expectError(dir / "other.net.xml", "not a SUMO network");
  test::writeText(
      dir / "walk.net.xml",
      "<net><edge id=\"w\" from=\"a\" to=\"b\"><lane id=\"w_0\" index=\"0\" speed=\"2\" "
      "length=\"10\" allow=\"pedestrian\" shape=\"0,0 10,0\"/></edge>"
      "<junction id=\"a\" type=\"dead_end\" x=\"0\" y=\"0\"/>"
      "<junction id=\"b\" type=\"dead_end\" x=\"10\" y=\"0\"/></net>");
  expectError(dir / "walk.net.xml", "no edge open to passenger cars");
  test::writeText(
      dir / "shape.net.xml",
      "<net><edge id=\"e\" from=\"a\" to=\"b\"><lane id=\"e_0\" index=\"0\" speed=\"2\" "
      "length=\"10\" shape=\"0,0 ten,0\"/></edge></net>");
  expectError(dir / "shape.net.xml", "bad shape point");
}

/// kTinyNet with the first occurrence of `from` replaced by `to`.
std::string tinyNetWith(const std::string& from, const std::string& to) {
  std::string s = kTinyNet;
  const auto at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return s.replace(at, from.size(), to);
}

TEST(SumoNet, RejectsNonFiniteAndAbsurdNumbers) {
  const auto dir = test::tempDir("sumonet_absurd");
  const std::vector<std::tuple<std::string, std::string, std::string, std::string>> cases = {
      {"nan_x.net.xml", "x=\"100\"", "x=\"nan\"", "junction 'B'"},
      {"inf_y.net.xml", "y=\"0\" z=\"2.5\"", "y=\"inf\" z=\"2.5\"", "junction 'B'"},
      {"huge_x.net.xml", "x=\"200\"", "x=\"1e308\"", "within 10,000 km"},
      {"far_shape.net.xml", "100,0 200,0", "100,0 1e8,0", "bad shape point"},
      {"long_segment.net.xml", "100,0 200,0", "100,0 90000,0", "without a bend"},
      {"nan_length.net.xml", "length=\"200\"", "length=\"nan\"", "lane 'CA_0' has length"},
      {"neg_length.net.xml", "length=\"100\"", "length=\"-5\"", "lane 'AB_0' has length"},
      {"nan_speed.net.xml", "speed=\"13.89\"", "speed=\"NaN\"", "has speed"},
  };
  for (const auto& [file, from, to, fragment] : cases) {
    test::writeText(dir / file, tinyNetWith(from, to));
    expectError(dir / file, fragment);
  }
}

TEST(SumoNet, SumoToolsNetworksHaveTheKnownCounts) {
  const NetworkInfo bo = networkInfo(SumoNet::read(test::bolognaNet()));
  EXPECT_EQ(bo.junctions, 112u);
  EXPECT_EQ(bo.passenger_edges, 166u);
  EXPECT_EQ(bo.lscc_junctions, 81u);
  EXPECT_EQ(bo.lscc_edges, 135u);
  const NetworkInfo ad = networkInfo(SumoNet::read(test::adlershofNet()));
  EXPECT_EQ(ad.junctions, 1033u);
  EXPECT_EQ(ad.passenger_edges, 740u);
  EXPECT_EQ(ad.lscc_junctions, 365u);
  EXPECT_EQ(ad.lscc_edges, 702u);
}

}  // namespace
}  // namespace slamroute
