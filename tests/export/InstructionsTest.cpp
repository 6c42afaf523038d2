// Turn-by-turn on nets with known answers: a plus (left, right, straight, U-turns at the dead
// ends, why a street is driven again) and a roundabout (exit n).
#include <gtest/gtest.h>

#include "TestNets.hpp"
#include "TestTmp.hpp"
#include "slamroute/export/Instructions.hpp"

namespace slamroute::exports {
namespace {

std::vector<std::string> manoeuvres(const std::vector<Instruction>& steps) {
  std::vector<std::string> out;
  for (const auto& s : steps) out.push_back(manoeuvreName(s.manoeuvre));
  return out;
}

TEST(Instructions, PlusNetLeftRightStraightAndUTurns) {
  const SumoNet net = SumoNet::read(test::geoPlusNet(test::testTmp()));
  // North up: from the south arm right is east; back west from E, right is north; from N down
  // to S is straight on; from S up, left is west.
  const std::vector<std::string> route = {"S_C", "C_E", "E_C", "C_N", "N_C", "C_S", "S_C", "C_W"};
  const auto steps = turnByTurn(net, route);
  ASSERT_EQ(steps.size(), 8u);
  EXPECT_EQ(manoeuvres(steps), (std::vector<std::string>{"depart", "right", "U-turn", "right",
                                                         "U-turn", "straight", "U-turn", "left"}));
  EXPECT_EQ(steps[0].street, "South Street");
  EXPECT_EQ(steps[1].street, "East Street");
  EXPECT_EQ(steps[3].street, "North Street");
  EXPECT_EQ(steps[7].street, "West Street");
  EXPECT_EQ(instructionText(steps[1]), "Turn right onto East Street");
  EXPECT_EQ(instructionText(steps[7]), "Turn left onto West Street");
  EXPECT_EQ(instructionText(steps[5]), "Continue straight onto South Street");
  // Distances add up: each step starts where the one before ended.
  for (std::size_t i = 1; i < steps.size(); ++i)
    EXPECT_NEAR(steps[i].at_m, steps[i - 1].at_m + steps[i - 1].drive_m, 1e-9);
  // The manoeuvres happen at the junctions: C for the turns, the arm ends for the U-turns.
  EXPECT_LT((steps[1].at_xy - net.findJunction("C")->pos.head<2>()).norm(), 1e-9);
  EXPECT_LT((steps[2].at_xy - net.findJunction("E")->pos.head<2>()).norm(), 1e-9);
}

TEST(Instructions, SaysWhyAStreetIsDrivenAgain) {
  const SumoNet net = SumoNet::read(test::geoPlusNet(test::testTmp()));
  const std::vector<std::string> route = {"S_C", "C_E", "E_C", "C_N", "N_C", "C_S", "S_C", "C_W"};
  const auto steps = turnByTurn(net, route, {.loop_min_travel_m = 50.0});
  EXPECT_EQ(steps[0].revisit, Revisit::None);
  EXPECT_EQ(steps[1].revisit, Revisit::None);
  // Back out of the dead end E: new streets (north, west) follow.
  EXPECT_EQ(steps[2].revisit, Revisit::Connection);
  EXPECT_EQ(steps[3].revisit, Revisit::None);
  // South Street again from C, last left ~330 m before (C_N + N_C): a loop closure at C.
  EXPECT_EQ(steps[5].revisit, Revisit::LoopClosure);
  EXPECT_NE(steps[5].revisit_detail.find("junction C"), std::string::npos)
      << steps[5].revisit_detail;
  EXPECT_EQ(steps[7].revisit, Revisit::None);
  // With a loop needing more driving than that, the same stretch is only a connection.
  const auto strict = turnByTurn(net, route, {.loop_min_travel_m = 5000.0});
  EXPECT_EQ(strict[5].revisit, Revisit::Connection);
  // Nothing new after driving back: the way to the end.
  const auto back = turnByTurn(net, {"W_C", "C_E", "E_C", "C_W"}, {.loop_min_travel_m = 5000.0});
  EXPECT_EQ(back.back().revisit, Revisit::Return);
}

TEST(Instructions, RoundaboutExitIsCountedFromTheEntry) {
  const SumoNet net = SumoNet::read(test::roundaboutNet(test::testTmp()));
  ASSERT_EQ(net.roundabouts.size(), 1u);
  // In from the south arm (A3), round past the east exit (A0), out at the north (A1): exit 2.
  const auto steps = turnByTurn(net, {"A3_R3", "R3_R0", "R0_R1", "R1_A1"});
  ASSERT_EQ(steps.size(), 2u);
  EXPECT_EQ(steps[1].manoeuvre, Manoeuvre::Roundabout);
  EXPECT_EQ(steps[1].roundabout_exit, 2);
  EXPECT_EQ(steps[1].street, "Arm A1 Road");
  EXPECT_EQ(instructionText(steps[1]), "At the roundabout take exit 2 onto Arm A1 Road");
  // The first exit is the east arm.
  const auto first = turnByTurn(net, {"A3_R3", "R3_R0", "R0_A0"});
  EXPECT_EQ(first.back().roundabout_exit, 1);
}

TEST(Instructions, UnknownEdgeNamesTheNet) {
  const SumoNet net =
      SumoNet::read(std::string(SLAMROUTE_SOURCE_DIR) + "/networks/test/plus.net.xml");
  try {
    turnByTurn(net, {"S_C", "nosuchedge"});
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("nosuchedge"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("plus.net.xml"), std::string::npos);
  }
}

}  // namespace
}  // namespace slamroute::exports
