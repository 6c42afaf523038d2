#pragma once
// Parameters of the fleet planner (several vehicles share the streets). YAML section "rl.fleet".
#include <string>

namespace slamroute::rl {

struct FleetConfig {
  void validate() const;  ///< values that cannot work: std::invalid_argument (FleetConfig.cpp)
  int vehicles = 1;       ///< K; 1 = the single-vehicle planners
  /// partition | postman (Fleet.hpp); the command line takes it from --planner, so it is no
  /// YAML key (one place to choose the planner)
  std::string strategy = "partition";
  int balance_moves = 200;       ///< partition: at most this many edge moves
  int candidates_per_move = 12;  ///< partition: boundary edges tried per move
  int kmeans_iterations = 100;   ///< partition: Lloyd iterations at most
  /// partition: the merge-splits (two neighbouring parts as one tour, cut in two) of a descent
  /// stop once they have solved this many min-cost circulations (a count: same seed, same routes)
  int merge_budget = 100;
  int kick_rounds = 30;  ///< partition: rounds of random kicks of the parts, each re-balanced
  /// partition: the kicks stop once their re-plans' work (sum of the re-planned parts' squared
  /// directed-edge counts) reaches this
  int kick_budget = 30000000;
};

template <class V>
void visitFields(V& v, FleetConfig& c) {
  v.field("vehicles", c.vehicles, "number of mapping vehicles K (1: one route, the planners)");
  v.field("balance_moves", c.balance_moves,
          "partition: at most this many boundary-edge moves to shorten the longest route");
  v.field("candidates_per_move", c.candidates_per_move,
          "partition: boundary edges of the longest route tried per move before giving up");
  v.field("kmeans_iterations", c.kmeans_iterations, "partition: Lloyd iterations at most");
  v.field("merge_budget", c.merge_budget,
          "partition: the merge-splits (two neighbouring parts driven as one tour, cut again in "
          "two) of a descent stop once they have solved this many min-cost circulations (0: none)");
  v.field("kick_rounds", c.kick_rounds,
          "partition: rounds of random boundary-street moves, each followed by the balancing "
          "moves and kept when the makespan is shorter (0: none)");
  v.field("kick_budget", c.kick_budget,
          "partition: the kicks stop once the re-planned parts' squared directed-edge counts "
          "sum to this (a count, not a time: same seed, same routes)");
}

}  // namespace slamroute::rl
