#pragma once
// Each planner family's own figures of a plan (what route.json's "extra" holds beside the
// planning graph and the route's checks), typed; plan() writes them into the route's JSON.
#include <optional>
#include <string>
#include <variant>

namespace slamroute::rl {

struct RandomWalkStats {
  long long shortest_path_segments = 0;  ///< times the walk was completed by a shortest path
  double shortest_path_length_m = 0;
};

struct QLearningStats {
  long long episodes = 0, episodes_reaching_goal = 0, training_steps = 0, q_table_entries = 0;
  double u_ref_logdet_per_edge = 0;      ///< the reward's uncertainty normaliser
  long long shortest_path_segments = 0;  ///< greedy roll-out stalls completed by shortest paths
  double shortest_path_length_m = 0;
  double learned_policy_share = 0;  ///< share of the route's length the learned policy chose
};

struct TspStats {
  std::string method;  ///< held-karp | christofides+2opt | greedy+2opt
  double tour_cost_m = 0, matrix_tour_cost_m = 0;
};

struct PostmanStats {
  double turn_free_optimum_m = 0, legal_circulation_m = 0;
  long long trails_before_merge = 0, free_merges = 0, forcing_rounds = 0;
  long long one_way_detours = 0, closed_walk_detours = 0;
  double detour_length_m = 0, excess_over_turn_free_pct = 0;
};

/// aco-ga, open-loop, exhaustive-revisit and switching (CoverageConfig.hpp).
struct CoverageStats {
  struct Aco {
    double tour_cost_m = 0, nearest_neighbour_m = 0;
    long long improved_at_iteration = 0, cities = 0;
  };
  struct Ga {
    long long generations = 0, evaluations = 0, improved_at_generation = 0;
    double switching_length_m = 0;  ///< the switching walk the GA started from
  };
  long long coverage_legs = 0, loop_closure_revisits = 0;
  double revisit_length_m = 0;
  Aco aco;
  std::optional<Ga> ga;  ///< aco-ga only
  double distances_seconds = 0, aco_seconds = 0, total_seconds = 0;
};

using PlannerStats = std::variant<std::monostate, RandomWalkStats, QLearningStats, TspStats,
                                  PostmanStats, CoverageStats>;

}  // namespace slamroute::rl
