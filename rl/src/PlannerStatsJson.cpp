#include "PlannerStatsJson.hpp"

namespace slamroute::rl {
using nlohmann::json;

namespace {

json toJson(std::monostate) { return json::object(); }

json toJson(const RandomWalkStats& s) {
  return {{"shortest_path_segments", s.shortest_path_segments},
          {"shortest_path_length_m", s.shortest_path_length_m}};
}

json toJson(const QLearningStats& s) {
  return {{"episodes", s.episodes},
          {"episodes_reaching_goal", s.episodes_reaching_goal},
          {"training_steps", s.training_steps},
          {"q_table_entries", s.q_table_entries},
          {"u_ref_logdet_per_edge", s.u_ref_logdet_per_edge},
          {"shortest_path_segments", s.shortest_path_segments},
          {"shortest_path_length_m", s.shortest_path_length_m},
          {"learned_policy_share", s.learned_policy_share}};
}

json toJson(const TspStats& s) {
  return {{"method", s.method},
          {"tour_cost_m", s.tour_cost_m},
          {"matrix_tour_cost_m", s.matrix_tour_cost_m}};
}

json toJson(const PostmanStats& s) {
  return {{"turn_free_optimum_m", s.turn_free_optimum_m},
          {"legal_circulation_m", s.legal_circulation_m},
          {"trails_before_merge", s.trails_before_merge},
          {"free_merges", s.free_merges},
          {"forcing_rounds", s.forcing_rounds},
          {"one_way_detours", s.one_way_detours},
          {"closed_walk_detours", s.closed_walk_detours},
          {"detour_length_m", s.detour_length_m},
          {"excess_over_turn_free_pct", s.excess_over_turn_free_pct}};
}

json toJson(const CoverageStats& s) {
  json ga = nullptr;
  if (s.ga)
    ga = {{"generations", s.ga->generations},
          {"evaluations", s.ga->evaluations},
          {"improved_at_generation", s.ga->improved_at_generation},
          {"switching_length_m", s.ga->switching_length_m}};
  return {
      {"coverage_legs", s.coverage_legs},
      {"loop_closure_revisits", s.loop_closure_revisits},
      {"revisit_length_m", s.revisit_length_m},
      {"aco",
       {{"tour_cost_m", s.aco.tour_cost_m},
        {"nearest_neighbour_m", s.aco.nearest_neighbour_m},
        {"improved_at_iteration", s.aco.improved_at_iteration},
        {"cities", s.aco.cities}}},
      {"ga", ga},
      {"seconds",
       {{"distances", s.distances_seconds}, {"aco", s.aco_seconds}, {"total", s.total_seconds}}}};
}

}  // namespace

json plannerStatsJson(const PlannerStats& stats) {
  return std::visit([](const auto& s) { return toJson(s); }, stats);
}

}  // namespace slamroute::rl
