// Seeded mutation fuzzing of the traces readers (tests/FuzzMutate.hpp): traces.csv and SUMO FCD
// XML, each read and checked as build-graph does.
#include <gtest/gtest.h>

#include <sstream>

#include "FuzzMutate.hpp"
#include "TestTmp.hpp"
#include "slamroute/roadgraph/Traces.hpp"

namespace slamroute::roadgraph {
namespace {

void readAndCheck(const std::filesystem::path& p) {
  const Traces tr = readTraces(p);
  checkTraces(tr, p.string());
  byVehicleThenTime(tr);
}

TEST(FuzzTraces, Csv) {
  std::ostringstream os;
  os << "t,vehicle,x,y,z,heading_deg,speed\n";
  for (int i = 0; i < 30; ++i)
    os << 0.1 * i << ",car" << i % 3 << "," << 1.5 * i << "," << 0.5 * (i % 3) << ",0,90,12.5\n";
  test::fuzzReader(os.str(), test::testTmp() / "m.traces.csv", 11, 300, readAndCheck);
}

TEST(FuzzTraces, FcdXml) {
  std::ostringstream os;
  os << "<fcd-export>\n";
  for (int i = 0; i < 20; ++i)
    os << "<timestep time=\"" << 0.1 * i << "\"><vehicle id=\"v" << i % 2 << "\" x=\"" << 2.0 * i
       << "\" y=\"3.5\" angle=\"90\" speed=\"13\"/></timestep>\n";
  os << "</fcd-export>\n";
  test::fuzzReader(os.str(), test::testTmp() / "m.fcd.xml", 12, 300, readAndCheck);
}

}  // namespace
}  // namespace slamroute::roadgraph
