#pragma once
// A hand-written SUMO net for the coverage tests of core and rl.
#include <filesystem>
#include <fstream>

#include "TestTmp.hpp"
#include "slamroute/core/SumoNet.hpp"

namespace slamroute::test {

// One two-way street A-B (100 m each way) and a bus-only edge beside it. The turn at B (AB onto
// BA) passes two internal lanes (5 m + 2 m, an internal junction splits it), the one at A one
// (8 m).
inline const char* kStreetNet = R"(<?xml version="1.0"?>
<net version="1.9">
  <location netOffset="0.00,0.00" convBoundary="0,0,100,0" origBoundary="0,0,100,0" projParameter="!"/>
  <edge id=":A_0" function="internal"><lane id=":A_0_0" index="0" speed="5" length="8" shape="0,1.6 0,-1.6"/></edge>
  <edge id=":B_0" function="internal"><lane id=":B_0_0" index="0" speed="5" length="5" shape="100,-1.6 102,0"/></edge>
  <edge id=":B_1" function="internal"><lane id=":B_1_0" index="0" speed="5" length="2" shape="102,0 100,1.6"/></edge>
  <edge id="AB" from="A" to="B" priority="1">
    <lane id="AB_0" index="0" speed="13.89" length="100" shape="0,-1.6 100,-1.6"/>
  </edge>
  <edge id="BA" from="B" to="A" priority="1">
    <lane id="BA_0" index="0" speed="13.89" length="100" shape="100,1.6 0,1.6"/>
  </edge>
  <edge id="AB_bus" from="A" to="B" priority="1">
    <lane id="AB_bus_0" index="0" speed="13.89" length="100" allow="bus" shape="0,-5 100,-5"/>
  </edge>
  <junction id="A" type="priority" x="0" y="0" incLanes="BA_0" intLanes=":A_0_0" shape=""/>
  <junction id="B" type="priority" x="100" y="0" incLanes="AB_0" intLanes=":B_0_0 :B_1_0" shape=""/>
  <junction id=":B_1_0" type="internal" x="102" y="0" incLanes=":B_0_0" intLanes=""/>
  <connection from="AB" to="BA" fromLane="0" toLane="0" via=":B_0_0" dir="t" state="M"/>
  <connection from="BA" to="AB" fromLane="0" toLane="0" via=":A_0_0" dir="t" state="M"/>
  <connection from=":B_0" to="BA" fromLane="0" toLane="0" via=":B_1_0" dir="t" state="M"/>
  <connection from=":B_1" to="BA" fromLane="0" toLane="0" dir="t" state="M"/>
  <connection from=":A_0" to="AB" fromLane="0" toLane="0" dir="t" state="M"/>
</net>
)";

/// kStreetNet, written below the test's scratch folder and read.
inline SumoNet twoWayStreetNet() {
  const auto path = testTmp() / "street.net.xml";
  std::ofstream(path, std::ios::binary) << kStreetNet;
  return SumoNet::read(path);
}

}  // namespace slamroute::test
