// Links between close junctions from vehicles' drives (ShortLinks.cpp): where a street already
// joins the two nodes, a link is added only for a direction no vehicle drove along it.
#include <gtest/gtest.h>

#include "ShortLinks.hpp"
#include "Streets.hpp"

namespace slamroute::roadgraph::detail {
namespace {

/// Two junction nodes 22 m apart joined by street 0 (a separate eastbound lane, 0 -> 1).
struct TwoNodes {
  std::vector<Point3> nodes = {Point3(0, 0, 0), Point3(22, 0, 0)};
  std::vector<Street> streets;
  std::vector<Polyline> polys;
  GraphBuildStats st;
  TwoNodes() {
    Street s;
    s.u = 0;
    s.v = 1;
    s.comp = 0;
    s.centre = {Point3(5, -4, 0), Point3(17, -4, 0)};
    streets.push_back(s);
    polys.push_back({nodes[0], Point3(5, -4, 0), Point3(17, -4, 0), nodes[1]});
  }
};

TEST(ShortLinks, DirectionNoVehicleDroveAlongTheStreetBetweenGetsALink) {
  // Three vehicles drive east along the street; five drive west through the junction box,
  // past no street point: a one-way link 1 -> 0 beside the street.
  TwoNodes t;
  const Passages passages = {{{0, 1, 0}, 3}, {{1, 0, -1}, 5}};
  addShortLinks(passages, t.nodes, EdgeConfig{}, t.streets, t.polys, t.st);
  ASSERT_EQ(t.streets.size(), 2u);
  EXPECT_EQ(t.st.short_links, 1u);
  const Street& link = t.streets[1];
  EXPECT_EQ(link.comp, -1);
  EXPECT_EQ(link.u, 0);
  EXPECT_EQ(link.v, 1);
  EXPECT_EQ(link.link_fwd, 0);  // east is the street's
  EXPECT_EQ(link.link_bwd, 5);
  EXPECT_EQ(t.polys.size(), 2u);
}

TEST(ShortLinks, DirectionDrivenAlongTheStreetGetsNoLink) {
  // One vehicle drove west along the street too: that direction is the street's, and the
  // drives past no street point are not a second way between the nodes.
  TwoNodes t;
  const Passages passages = {{{0, 1, 0}, 3}, {{1, 0, 0}, 1}, {{1, 0, -1}, 5}, {{0, 1, -1}, 4}};
  addShortLinks(passages, t.nodes, EdgeConfig{}, t.streets, t.polys, t.st);
  EXPECT_EQ(t.streets.size(), 1u);
  EXPECT_EQ(t.st.short_links, 0u);
}

TEST(ShortLinks, NodesWithoutAStreetBetweenAreLinkedBothWays) {
  TwoNodes t;
  t.streets.clear();
  t.polys.clear();
  const Passages passages = {{{0, 1, -1}, 2}, {{1, 0, -1}, 3}};
  addShortLinks(passages, t.nodes, EdgeConfig{}, t.streets, t.polys, t.st);
  ASSERT_EQ(t.streets.size(), 1u);
  EXPECT_EQ(t.streets[0].link_fwd, 2);
  EXPECT_EQ(t.streets[0].link_bwd, 3);
}

TEST(ShortLinks, DriveOntoAStreetAtAnEndItDidNotPassLinksThatEnd) {
  // Node 2 lies 20 m west of node 0, the street's near end; two vehicles drive from node 2
  // along the street to node 1 without coming near node 0: a link 2 -> 0.
  TwoNodes t;
  t.nodes.push_back(Point3(-20, 0, 0));
  const Passages passages = {{{0, 1, 0}, 3}, {{2, 1, 0}, 2}};
  addShortLinks(passages, t.nodes, EdgeConfig{}, t.streets, t.polys, t.st);
  ASSERT_EQ(t.streets.size(), 2u);
  const Street& link = t.streets[1];
  EXPECT_EQ(link.u, 0);
  EXPECT_EQ(link.v, 2);
  EXPECT_EQ(link.link_fwd, 0);
  EXPECT_EQ(link.link_bwd, 2);  // 2 -> 0
  // One vehicle is no link (min_link_vehicles), nor is a far end 40 m off (link_max_m).
  TwoNodes one;
  one.nodes.push_back(Point3(-20, 0, 0));
  addShortLinks({{{2, 1, 0}, 1}}, one.nodes, EdgeConfig{}, one.streets, one.polys, one.st);
  EXPECT_EQ(one.streets.size(), 1u);
  TwoNodes far;
  far.nodes.push_back(Point3(-40, 0, 0));
  addShortLinks({{{2, 1, 0}, 4}}, far.nodes, EdgeConfig{}, far.streets, far.polys, far.st);
  EXPECT_EQ(far.streets.size(), 1u);
}

}  // namespace
}  // namespace slamroute::roadgraph::detail
