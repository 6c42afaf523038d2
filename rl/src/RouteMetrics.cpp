// Route metrics (route.json): coverage, revisits, loop closures, weight, EIF log-det along it.
// The SUMO edge list concatenates the graph edges' SUMO chains; a graph edge without SUMO edges
// (a short link SUMO models inside a junction) adds nothing, and the drive's legalisation joins
// its neighbours (cli makeRouteDrivable).
#include <algorithm>
#include <nlohmann/json.hpp>

#include "Index.hpp"
#include "slamroute/rl/Eif.hpp"
#include "slamroute/rl/Planners.hpp"

namespace slamroute::rl {

int countIllegalTurns(const PlanGraph& pg, const std::vector<int>& edges) {
  int bad = 0;
  for (std::size_t k = 1; k < edges.size(); ++k) {
    const int e = edges[k - 1], f = edges[k];
    bool ok = false;
    for (int j = pg.nextBegin(e); j < pg.nextEnd(e) && !ok; ++j) ok = pg.next[sz(j)] == f;
    bad += ok ? 0 : 1;
  }
  return bad;
}

void fillRouteMetrics(const PlanGraph& pg, const RoadGraph& g, int start,
                      const std::vector<int>& edges, const EifConfig& eif, Route& r) {
  r.nodes.assign(1, pg.node_orig[sz(start)]);
  r.edges.clear();
  r.sumo_edges.clear();
  r.logdet_cov_along.clear();
  std::vector<char> node_seen(sz(pg.n), 0), street_seen(sz(pg.num_streets), 0);
  std::vector<double> last_travel(sz(pg.n), 0.0);
  std::vector<Info3> node_info(sz(pg.n));
  PoseEif filter(eif);
  node_seen[sz(start)] = 1;
  node_info[sz(start)] = filter.info();
  double length = 0.0, weighted = 0.0, covered = 0.0;
  int nodes_seen = 1;
  r.revisits = 0;
  r.loop_closures = 0;
  r.max_logdet_cov = r.final_logdet_cov = filter.logDetCov();
  for (int e : edges) {
    const RoadEdge& re = g.edges[sz(pg.edge_orig[sz(e)])];
    r.edges.push_back(re.id);
    r.nodes.push_back(pg.node_orig[sz(pg.v[sz(e)])]);
    for (const auto& s : re.sumo_edges)
      if (r.sumo_edges.empty() || r.sumo_edges.back() != s) r.sumo_edges.push_back(s);
    length += pg.len[sz(e)];
    weighted += pg.len[sz(e)] * re.weight;
    if (!street_seen[sz(pg.street[sz(e)])]) {
      street_seen[sz(pg.street[sz(e)])] = 1;
      covered += pg.street_len[sz(pg.street[sz(e)])];
    }
    filter.drive(edgeMotion(eif, pg.len[sz(e)], pg.heading[sz(e)], pg.weight[sz(e)]));
    const int w = pg.v[sz(e)];
    if (node_seen[sz(w)]) {
      ++r.revisits;
      if (length - last_travel[sz(w)] >= eif.loop_min_travel_m) {
        ++r.loop_closures;
        filter.closeLoop(node_info[sz(w)]);
      }
      if (filter.info().determinant() > node_info[sz(w)].determinant())
        node_info[sz(w)] = filter.info();
    } else {
      node_seen[sz(w)] = 1;
      ++nodes_seen;
      node_info[sz(w)] = filter.info();
    }
    last_travel[sz(w)] = length;
    const double ld = filter.logDetCov();
    r.logdet_cov_along.push_back(ld);
    r.max_logdet_cov = std::max(r.max_logdet_cov, ld);
    r.final_logdet_cov = ld;
  }
  r.length_m = length;
  r.node_coverage_pct = 100.0 * nodes_seen / pg.n;
  r.edge_coverage_pct = pg.total_street_len > 0 ? 100.0 * covered / pg.total_street_len : 100.0;
  r.mean_edge_weight = length > 0 ? weighted / length : 0.0;
}

}  // namespace slamroute::rl
