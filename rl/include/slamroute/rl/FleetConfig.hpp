#pragma once
// Parameters of the fleet planner (several vehicles share the streets). YAML section "rl.fleet".
#include <string>

namespace slamroute::rl {

struct FleetConfig {
  void validate() const;  ///< values that cannot work: std::invalid_argument (FleetPlan.cpp)
  int vehicles = 1;                     ///< K; 1 = the single-vehicle planners
  std::string strategy = "partition";   ///< partition | postman (see Fleet.hpp)
  int balance_moves = 200;              ///< partition: at most this many street moves
  int candidates_per_move = 12;         ///< partition: boundary streets tried per move
  int kmeans_iterations = 100;          ///< partition: Lloyd iterations at most
};

template <class V>
void visitFields(V& v, FleetConfig& c) {
  v.field("vehicles", c.vehicles, "number of mapping vehicles K (1: one route, the planners)");
  v.field("strategy", c.strategy,
          "partition (K-means parts, Hungarian assignment, rural postman per part, balancing "
          "moves) | postman (the single postman circuit split into K legs)");
  v.field("balance_moves", c.balance_moves,
          "partition: at most this many boundary-street moves to shorten the longest route");
  v.field("candidates_per_move", c.candidates_per_move,
          "partition: boundary streets of the longest route tried before giving up");
  v.field("kmeans_iterations", c.kmeans_iterations, "partition: Lloyd iterations at most");
}

}  // namespace slamroute::rl
