#pragma once
// Parameters of the rl module (paper §3.2 and the baseline planners), with the paper's defaults
// and units. YAML section "rl:".
#include <cstdint>
#include <string>

#include "slamroute/rl/CoverageConfig.hpp"
#include "slamroute/rl/FleetConfig.hpp"

namespace slamroute::rl {

/// Extended information filter over the vehicle pose (x, y, heading): the R_U model (eq. 6).
/// The motion noise (the *_var_per_m and poor_weight_gain) is fitted to the SLAM's measured drift
/// per street: bench/bench_eif_calibration.cpp reads evaluate's per_edge.csv of `run` /
/// `experiment` drives, estimates the noise per metre of each street piece from its drift and
/// fits it as a line in (1 - edge weight); bench/RESULTS.md has the fit and how well C_k then
/// ranks the measured error along each drive.
struct EifConfig {
  void validate() const;  ///< values that cannot work: std::invalid_argument (ConfigValidate.cpp)
  double init_sigma_xy_m = 0.1;          ///< initial position std-dev [m]
  double init_sigma_heading_rad = 0.01;  ///< initial heading std-dev [rad]
  double long_var_per_m = 3.05e-3;       ///< along-track variance added per metre driven [m^2/m]
  double lat_var_per_m = 1.53e-3;        ///< cross-track variance added per metre [m^2/m]
  double heading_var_per_m = 1.3e-7;     ///< heading variance added per metre [rad^2/m]
  double poor_weight_gain = 3.06;   ///< noise x (1 + gain * (1 - weight)): poor streets drift more
  double closure_sigma_xy_m = 0.2;  ///< loop-closure registration std-dev, position [m]
  double closure_sigma_heading_rad = 0.01;  ///< loop-closure registration std-dev, heading [rad]
  double loop_min_travel_m = 50.0;  ///< a revisit is a loop closure after this much driving [m]
};

template <class V>
void visitFields(V& v, EifConfig& c) {
  v.field("init_sigma_xy_m", c.init_sigma_xy_m, "initial position std-dev [m]");
  v.field("init_sigma_heading_rad", c.init_sigma_heading_rad, "initial heading std-dev [rad]");
  v.field("long_var_per_m", c.long_var_per_m, "along-track variance added per metre [m^2/m]");
  v.field("lat_var_per_m", c.lat_var_per_m, "cross-track variance added per metre [m^2/m]");
  v.field("heading_var_per_m", c.heading_var_per_m, "heading variance added per metre [rad^2/m]");
  v.field("poor_weight_gain", c.poor_weight_gain,
          "motion noise is scaled by 1 + gain*(1 - edge weight) (weights normalised to [0,1])");
  v.field("closure_sigma_xy_m", c.closure_sigma_xy_m, "loop-closure registration std-dev [m]");
  v.field("closure_sigma_heading_rad", c.closure_sigma_heading_rad,
          "loop-closure registration heading std-dev [rad]");
  v.field("loop_min_travel_m", c.loop_min_travel_m,
          "a revisit counts as a loop closure after this much driving since the last visit [m]");
}

/// Tabular Q-learning (paper §3.2, eqs. 5-7).
struct QLearningConfig {
  void validate() const;  ///< values that cannot work: std::invalid_argument (ConfigValidate.cpp)
  int episodes = 1000;    ///< training episodes (paper: 1000)
  double gamma = 0.25;    ///< discount (paper: best of 0.25/0.5/0.75/0.9)
  double alpha = 0.3;     ///< learning rate (paper: unspecified)
  double epsilon_start = 1.0;  ///< epsilon-greedy exploration at the first episode
  double epsilon_end = 0.05;   ///< ... reached linearly at epsilon_decay_fraction of the episodes
  double epsilon_decay_fraction = 0.8;  ///< share of episodes over which epsilon decays
  double max_steps_per_edge = 4.0;      ///< episode step cap = this * edges (* ln edges, below)
  int signature_bits =
      4;  ///< state = arrival edge + "is new" bit of the first k actions (0 = position only)
  double weight_coverage = 1.0;      ///< eq. 7 weight of R_C
  double weight_accuracy = 1.0;      ///< eq. 7 weight of R_A
  double weight_uncertainty = 20.0;  ///< eq. 7 weight of R_U (paper: 20)
  double step_length_cost = 0.1;     ///< R_C: cost per mean edge length driven (eq. 6 l_path)
  double uncertainty_clip =
      1.0;              ///< |w_U * R_U| is clipped to this (one closure != many new nodes)
  int stall_steps = 0;  ///< roll-out: also a stall after this many steps without progress (0 = off)
  bool complete_with_shortest_paths = true;  ///< finish a stalled greedy roll-out by shortest paths
  bool explore_new_first =
      true;                   ///< exploration prefers actions reaching new coverage (paper: false)
  bool spread_starts = true;  ///< every other episode starts at a random node (paper: false)
  bool cap_scales_with_log_edges = true;  ///< step cap also x ln(edges) (paper setting: false)
  /// state: with nothing new at hand, which action leads to the nearest uncovered part (paper:
  /// false)
  bool guide_to_uncovered = true;
  double guide_reward = 2.0;  ///< reward for taking that action (shaping; 0 = none)
};

template <class V>
void visitFields(V& v, QLearningConfig& c) {
  v.field("episodes", c.episodes, "training episodes (paper: 1000)");
  v.field("gamma", c.gamma, "discount factor (paper: 0.25)");
  v.field("alpha", c.alpha, "learning rate");
  v.field("epsilon_start", c.epsilon_start, "epsilon-greedy exploration at episode 0");
  v.field("epsilon_end", c.epsilon_end, "final exploration rate");
  v.field("epsilon_decay_fraction", c.epsilon_decay_fraction,
          "epsilon decays linearly over this share of the episodes");
  v.field("max_steps_per_edge", c.max_steps_per_edge, "episode step cap = this * edge count");
  v.field("signature_bits", c.signature_bits,
          "state = arrival edge + 'target is new' bits of its first k actions (0..6; 0 = position "
          "only)");
  v.field("weight_coverage", c.weight_coverage, "eq. 7 weight of R_C");
  v.field("weight_accuracy", c.weight_accuracy, "eq. 7 weight of R_A");
  v.field("weight_uncertainty", c.weight_uncertainty, "eq. 7 weight of R_U (paper: 20)");
  v.field("step_length_cost", c.step_length_cost,
          "R_C cost per mean-edge-length driven (the l_path term of eq. 6)");
  v.field("uncertainty_clip", c.uncertainty_clip,
          "clip of the weighted uncertainty term |w_U * R_U| per step");
  v.field("stall_steps", c.stall_steps,
          "roll-out: a stall also after this many steps without new coverage (0 = only on a "
          "repeated state)");
  v.field("complete_with_shortest_paths", c.complete_with_shortest_paths,
          "finish a stalled greedy roll-out with shortest paths to the nearest uncovered part");
  v.field("explore_new_first", c.explore_new_first,
          "exploration draws among actions reaching new coverage when there are any (paper: "
          "false, uniform)");
  v.field("spread_starts", c.spread_starts,
          "every other training episode starts at a random node instead of the start (paper: "
          "false)");
  v.field("cap_scales_with_log_edges", c.cap_scales_with_log_edges,
          "episode step cap = max_steps_per_edge * edges * ln(edges), a random walk's cover time "
          "(false: max_steps_per_edge * edges)");
  v.field("guide_to_uncovered", c.guide_to_uncovered,
          "where no action reaches anything new, the state's signature marks the action on the "
          "shortest legal path to the nearest uncovered part (paper: false, position only)");
  v.field("guide_reward", c.guide_reward,
          "reward for taking the marked action (shaping toward the nearest uncovered part)");
}

struct RandomConfig {
  void validate() const;  ///< values that cannot work: std::invalid_argument (ConfigValidate.cpp)
  double max_steps_per_edge =
      1000.0;  ///< random walk step cap = this * edge count, then shortest paths
  double budget_m =
      0.0;  ///< stop the walk at this driven length, goal met or not (0: no budget) [m]
};

template <class V>
void visitFields(V& v, RandomConfig& c) {
  v.field("max_steps_per_edge", c.max_steps_per_edge,
          "random walk step cap = this * edge count (then finished by shortest paths)");
  v.field("budget_m", c.budget_m,
          "stop at this driven length even if the goal is not met; 0 = no budget [m] (Table 1 "
          "compares routes of equal length)");
}

struct TspConfig {
  void validate() const;  ///< values that cannot work: std::invalid_argument (ConfigValidate.cpp)
  int exact_max_nodes = 18;  ///< Held-Karp (exact) up to this many nodes (memory 2^(n-1)*n*8 B)
  int christofides_max_nodes = 400;  ///< above: greedy tour + 2-opt instead of Christofides
  int max_nodes = 3000;              ///< refuse above this (the distance matrix is n^2)
  bool closed_tour = true;           ///< return to the start node (classic TSP tour)
};

template <class V>
void visitFields(V& v, TspConfig& c) {
  v.field(
      "exact_max_nodes", c.exact_max_nodes,
      "exact Held-Karp up to this many nodes; above, a heuristic tour (labelled in route.json)");
  v.field(
      "christofides_max_nodes", c.christofides_max_nodes,
      "Christofides + 2-opt up to this many nodes; above, greedy tour + 2-opt (O(n^3) matching)");
  v.field("max_nodes", c.max_nodes, "refuse graphs with more nodes (n^2 distance matrix)");
  v.field("closed_tour", c.closed_tour, "return to the start node at the end");
}

struct PostmanConfig {
  void validate() const;  ///< values that cannot work: std::invalid_argument (ConfigValidate.cpp)
  bool closed = true;     ///< the circuit returns to its start (Euler circuit)
  int max_forcing_rounds =
      12;  ///< re-solves forcing a turn into a separate trail (0 = detours only)
};

template <class V>
void visitFields(V& v, PostmanConfig& c) {
  v.field("closed", c.closed,
          "route returns to the start node (otherwise the last return leg "
          "after full coverage is cut)");
  v.field("max_forcing_rounds", c.max_forcing_rounds,
          "connectivity repair: re-solve the circulation forcing a turn into a separate trail, at "
          "most this many rounds (0 = merge by detours only)");
}

struct Config {
  /// qlearning | random | tsp | postman | aco-ga | open-loop | exhaustive-revisit | switching
  std::string planner = "qlearning";
  std::string goal = "nodes";   ///< episode/coverage goal: nodes (paper) | edges (streets)
  std::string reward = "full";  ///< full (eq. 7) | accuracy (R_A only, paper Table 2)
  int start_node = -1;          ///< start node id (-1: the first node of the planning graph)
  EifConfig eif;
  QLearningConfig qlearning;
  RandomConfig random;
  TspConfig tsp;
  PostmanConfig postman;
  CoverageConfig coverage;  ///< aco-ga and its baselines
  FleetConfig fleet;        ///< several vehicles (Fleet.hpp)
};

template <class V>
void visitFields(V& v, Config& c) {
  v.field(
      "planner", c.planner,
      "qlearning | random | tsp | postman | aco-ga | open-loop | exhaustive-revisit | switching");
  v.field("goal", c.goal,
          "coverage goal: nodes (paper: every node visited) | edges (every street)");
  v.field("reward", c.reward, "qlearning reward: full (eq. 7) | accuracy (R_A only, Table 2)");
  v.field("start_node", c.start_node, "start node id (-1: first node of the planning graph)");
  v.section("eif", c.eif);
  v.section("qlearning", c.qlearning);
  v.section("random", c.random);
  v.section("tsp", c.tsp);
  v.section("postman", c.postman);
  v.section("coverage", c.coverage);
  v.section("fleet", c.fleet);
}

}  // namespace slamroute::rl
