// LEMON Christofides / greedy + 2-opt (see LemonTsp.hpp for why this file is C++17).
#include "LemonTsp.hpp"

#include <lemon/christofides_tsp.h>
#include <lemon/full_graph.h>
#include <lemon/greedy_tsp.h>
#include <lemon/opt2_tsp.h>

namespace slamroute::rl::detail {

std::vector<int> lemonTour(const std::vector<std::vector<double>>& d, bool christofides) {
  const int n = static_cast<int>(d.size());
  lemon::FullGraph fg(n);
  using CostMap = lemon::FullGraph::EdgeMap<double>;
  CostMap cost(fg);
  for (lemon::FullGraph::EdgeIt e(fg); e != lemon::INVALID; ++e) {
    const auto a = static_cast<std::size_t>(fg.id(fg.u(e)));
    const auto b = static_cast<std::size_t>(fg.id(fg.v(e)));
    cost[e] = 0.5 * (d[a][b] + d[b][a]);
  }
  std::vector<lemon::FullGraph::Node> init;
  if (christofides) {
    lemon::ChristofidesTsp<CostMap> ch(fg, cost);
    ch.run();
    init = ch.tourNodes();
  } else {
    lemon::GreedyTsp<CostMap> gr(fg, cost);
    gr.run();
    init = gr.tourNodes();
  }
  lemon::Opt2Tsp<CostMap> opt(fg, cost);
  opt.run(init);
  std::vector<int> tour;
  for (const auto& v : opt.tourNodes()) tour.push_back(fg.id(v));
  return tour;
}

}  // namespace slamroute::rl::detail
