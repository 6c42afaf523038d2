// ExploreRun: K explorers in one SUMO session, sweeping the sparse LiDAR into the shared grid and
// choosing a turn whenever they enter a street.
#include "ExploreRun.hpp"

#include <algorithm>
#include <chrono>
#include <limits>
#include <stdexcept>

#include "slamroute/core/Log.hpp"
#include "slamroute/explore/KnownPaths.hpp"
#include "slamroute/explore/Measures.hpp"

namespace slamroute::explore {
namespace {

simulate::LidarConfig sparseLidar(const SensorConfig& s) {
  simulate::LidarConfig c;
  c.preset = s.preset;
  c.spec.horizontal_samples = s.horizontal_samples;
  c.range_sigma_m = 0.0;
  c.dropout_prob = 0.0;
  c.motion_distortion = false;
  return c;
}

OccupancyGrid gridFor(const RoadGraph& g, const GridConfig& c) {
  const auto [lo, hi] = streetBounds(g, c.margin_m);
  return OccupancyGrid(lo, hi, c.cell_m);
}

}  // namespace

std::pair<Point2, Point2> streetBounds(const RoadGraph& g, double margin_m) {
  const double inf = std::numeric_limits<double>::infinity();
  Point2 lo(inf, inf), hi(-inf, -inf);
  for (const RoadEdge& e : g.edges)
    for (const Point3& p : e.polyline) {
      lo = lo.cwiseMin(p.head<2>());
      hi = hi.cwiseMax(p.head<2>());
    }
  return {lo - Point2::Constant(margin_m), hi + Point2::Constant(margin_m)};
}

ExploreRun::ExploreRun(const ExploreOptions& opts, const Config& cfg,
                       const simulate::WorldConfig& world, const simulate::DriveConfig& drive)
    : opts_(opts),
      cfg_(cfg),
      drive_(drive),
      net_(SumoNet::read(opts.net)),
      graph_(RoadGraph::fromSumoNet(net_)),
      pg_(rl::PlanGraph::build(graph_, opts.net.string())),
      world_(simulate::World::build(net_, world, opts.seed)),
      lidar_(sparseLidar(cfg.sensor), opts.seed),
      grid_(gridFor(graph_, cfg.grid)),
      streets_(pg_, graph_, grid_),
      strategy_(makeStrategy(opts.strategy, cfg, opts.seed)) {
  if (opts.vehicles < 1 || opts.vehicles > 64)
    throw std::invalid_argument("explore: --vehicles must be in [1, 64]");
  for (int e = 0; e < pg_.m; ++e) {
    const RoadEdge& re =
        graph_.edges[static_cast<std::size_t>(pg_.edge_orig[static_cast<std::size_t>(e)])];
    for (const auto& s : re.sumo_edges) edge_of_[s] = e;
  }
  driven_.assign(static_cast<std::size_t>(pg_.m), false);
  drive_count_.assign(static_cast<std::size_t>(pg_.m), 0);
  targets_.assign(static_cast<std::size_t>(opts.vehicles), -1);
  result_.strategy = opts.strategy;
  result_.total_edges = pg_.m;
}

std::vector<int> ExploreRun::startEdges() const {
  std::vector<int> out;
  for (const auto& s : opts_.start_edges) {
    const auto it = edge_of_.find(s);
    if (it == edge_of_.end())
      throw std::invalid_argument(opts_.net.string() + ": start edge '" + s +
                                  "' is not in the net's largest legally drivable part");
    out.push_back(it->second);
  }
  if (out.empty()) out.push_back(0);
  while (static_cast<int>(out.size()) < opts_.vehicles) out.push_back(out.back());
  out.resize(static_cast<std::size_t>(opts_.vehicles));
  return out;
}

void ExploreRun::depart(simulate::OnlineVehicles& vehicles) {
  const std::vector<int> starts = startEdges();
  std::map<int, int> on_edge;  // vehicles already leaving from an edge
  for (int k = 0; k < opts_.vehicles; ++k) {
    Explorer x;
    x.id = "explorer" + std::to_string(k);
    x.result.id = x.id;
    const int e = starts[static_cast<std::size_t>(k)];
    x.result.depart_s = cfg_.depart_gap_s * on_edge[e]++;
    x.pos = streets_.midpoint(e);
    if (cfg_.map_poses == "slam")  // each vehicle's own odometry errors
      x.dead_reckoning.emplace(drive_, opts_.seed + 0x9e3779b97f4a7c15ULL * (k + 1));
    vehicles.add(x.id, sumoEdge(e), x.result.depart_s);
    explorers_.push_back(std::move(x));
  }
}

ExploreResult ExploreRun::run() {
  simulate::SumoSessionOptions so;
  so.net = net_.source;
  so.seed = opts_.seed;
  so.step_length_s = cfg_.step_length_s;
  so.time_to_teleport_s = -1.0;
  so.extra_args = {"--lanechange.duration", "2"};
  simulate::SumoSession session(so);
  simulate::OnlineVehicles vehicles(session, cfg_.speed_factor);
  depart(vehicles);
  Progress progress("explore", static_cast<std::size_t>(pg_.m));
  while (!finished()) {
    vehicles.step();
    result_.end_time_s = session.time();
    for (int k = 0; k < opts_.vehicles; ++k) follow(vehicles, k);
    progress.update(static_cast<std::size_t>(result_.edges_driven));
    if (result_.end_time_s > cfg_.max_time_s) {
      result_.time_limit_hit = true;
      logWarn("explore: time limit " + std::to_string(cfg_.max_time_s) + " s reached");
      break;
    }
  }
  progress.finish();
  session.close();
  for (auto& x : explorers_) {
    x.result.distance_m = x.odometer_m;
    result_.vehicles.push_back(x.result);
  }
  result_.grid_cells_known = static_cast<int>(grid_.size() - grid_.countOf(Cell::Unknown));
  result_.streets_known = streets_.numKnown();
  for (int i = 0; i < static_cast<int>(grid_.size()); ++i) result_.grid.push_back(grid_.at(i));
  return result_;
}

OfflineBound ExploreRun::offlineBound() const {
  return offlineFleetBound(graph_, pg_, startEdges(), opts_.seed);
}

void ExploreRun::follow(simulate::OnlineVehicles& vehicles, int k) {
  Explorer& x = explorers_[static_cast<std::size_t>(k)];
  const simulate::OnlineVehicleState s = vehicles.state(x.id);
  if (!s.in_net) return;
  if (t0_ < 0) t0_ = result_.end_time_s - cfg_.step_length_s;
  x.odometer_m = std::max(x.odometer_m, s.odometer_m);
  x.pos = s.pos.head<2>();
  const Pose3 sensor = simulate::vehicleBodyPose(s.pos.x(), s.pos.y(), s.pos.z(), s.angle_deg,
                                                 s.slope_deg, lidar_.spec().mount_height_m);
  if (x.dead_reckoning) x.dead_reckoning->step(result_.end_time_s, sensor);
  if (x.odometer_m - x.last_scan_m >= cfg_.sensor.scan_spacing_m) scan(k, s, sensor);
  // x.route's index of the street it is on or last left (-1 before its first route)
  const int at = static_cast<int>(x.route.size()) - 1 - s.route_edges_ahead;
  if (s.edge.empty()) {
    if (at > 0) passUnseen(vehicles, k, at, result_.end_time_s);
    return;
  }
  const auto it = edge_of_.find(s.edge);
  if (it == edge_of_.end())
    throw std::runtime_error(opts_.net.string() + ": explorer " + x.id +
                             " left the drivable part on '" + s.edge + "'");
  // at > 0 with the same street: it came round to it again, every street between unseen
  if (it->second != x.edge || at > 0) enterEdge(vehicles, k, at, it->second, result_.end_time_s);
}

// The sweep is taken at the true sensor pose and enters the grid at the pose the vehicle
// believes (the same with map_poses: truth); ground is judged against the road it stands on
// (height is not what dead reckoning loses).
void ExploreRun::scan(int k, const simulate::OnlineVehicleState& s, const Pose3& sensor) {
  Explorer& x = explorers_[static_cast<std::size_t>(k)];
  x.last_scan_m = x.odometer_m;
  const Pose3 T = x.dead_reckoning ? x.dead_reckoning->estimate(sensor) : sensor;
  const double road_z = world_.surfaceZ(s.pos.x(), s.pos.y(), s.pos.z() + 1.0).value_or(s.pos.z());
  const Scan sweep = lidar_.scan(world_, sensor, {}, scans_++);
  std::vector<Point3> pts;
  pts.reserve(sweep.points.size());
  for (const ScanPoint& p : sweep.points) pts.push_back(T * Point3(p.x, p.y, p.z));
  const std::vector<int> changed =
      grid_.addScan(pts, T.translation(), road_z, cfg_.grid.max_range_m, cfg_.grid.ground_tol_m,
                    cfg_.grid.ground_grade);
  streets_.update(changed);
}

const std::string& ExploreRun::sumoEdge(int e) const {
  return graph_.edges[static_cast<std::size_t>(pg_.edge_orig[static_cast<std::size_t>(e)])]
      .sumo_edges.front();
}

void ExploreRun::advance(int k, int edge, double t) {
  Explorer& x = explorers_[static_cast<std::size_t>(k)];
  if (x.edge >= 0) recordDriven(x.edge, t);
  x.settled = x.idle;
  x.edge = edge;
  if (!driven_[static_cast<std::size_t>(edge)]) ++entered_;
  driven_[static_cast<std::size_t>(edge)] = true;
  if (targets_[static_cast<std::size_t>(k)] == edge) targets_[static_cast<std::size_t>(k)] = -1;
  x.result.edges.push_back(sumoEdge(edge));
}

// The route becomes [edge, chosen turn, provisional turns for another kLookaheadM]: streets
// shorter than one step's travel (real nets have chains of sub-metre edges) may be passed
// between two looks, and the vehicle must never run out of route. Streets passed that way are
// counted as driven; their turns were the provisional ones. `at`: x.route's index of `edge`.
void ExploreRun::enterEdge(simulate::OnlineVehicles& vehicles, int k, int at, int edge, double t) {
  Explorer& x = explorers_[static_cast<std::size_t>(k)];
  if (at > 0 && x.route[static_cast<std::size_t>(at)] != edge)
    throw std::logic_error("explore: " + x.id + " is on " + sumoEdge(edge) +
                           ", not where its route says");
  for (int i = 1; i < at; ++i) advance(k, x.route[static_cast<std::size_t>(i)], t);
  advance(k, edge, t);
  for (int i = pg_.nextBegin(edge); i < pg_.nextEnd(edge); ++i)
    streets_.markOffered(pg_.next[static_cast<std::size_t>(i)]);
  x.route = {edge, chooseNext(k)};
  sendRoute(vehicles, k, t);
}

// Seen inside a junction after x.route[at]: it drove that street (and any before it) between
// two looks. Its route is renewed here, not only on a street: past sub-metre streets it may be
// seen inside junctions only, until the route runs out (a U-turn into a sub-metre street whose
// far end turns it round again). It keeps the turn it is taking; the provisional turns after it
// are chosen afresh.
void ExploreRun::passUnseen(simulate::OnlineVehicles& vehicles, int k, int at, double t) {
  Explorer& x = explorers_[static_cast<std::size_t>(k)];
  if (at + 1 >= static_cast<int>(x.route.size()))
    throw std::logic_error("explore: " + x.id + " is in a junction beyond its route");
  for (int i = 1; i <= at; ++i) advance(k, x.route[static_cast<std::size_t>(i)], t);
  x.route = {x.route[static_cast<std::size_t>(at)], x.route[static_cast<std::size_t>(at) + 1]};
  sendRoute(vehicles, k, t);
}

/// Extends x.route by the provisional turns and hands it to SUMO.
void ExploreRun::sendRoute(simulate::OnlineVehicles& vehicles, int k, double t) {
  constexpr double kLookaheadM = 80.0;
  constexpr std::size_t kMaxEdges = 256;  // sub-metre edges: a bound, not the usual end
  Explorer& x = explorers_[static_cast<std::size_t>(k)];
  for (double ahead = 0.0; ahead < kLookaheadM && x.route.size() < kMaxEdges;) {
    x.route.push_back(wander(x.route.back(), x.route));
    ahead += pg_.len[static_cast<std::size_t>(x.route.back())];
  }
  std::vector<std::string> sumo;
  for (int e : x.route) sumo.push_back(sumoEdge(e));
  logDebug("explore: " + x.id + " at t=" + std::to_string(t) + " s on " + sumo[0] + ", next " +
           sumo[1]);
  vehicles.setRoute(x.id, sumo);
}

// A vehicle keeps its target until it gets there or the target stops being open (another
// vehicle drove it): re-deciding at every street lets assignments flip back and forth while
// the vehicles circle. Only a new decision asks the strategy (and counts as one).
int ExploreRun::chooseNext(int k) {
  Explorer& x = explorers_[static_cast<std::size_t>(k)];
  const FleetView f = view();
  const int t = targets_[static_cast<std::size_t>(k)];
  if (t >= 0 && f.open(t, k)) {
    const KnownPaths paths(pg_, x.edge, [&](int e) { return streets_.known(e); });
    if (const auto p = paths.pathTo(t)) return p->edges.front();
  }
  const auto c0 = std::chrono::steady_clock::now();
  const Decision d = strategy_->decide(f, k);
  result_.decision_ms.push_back(
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - c0).count());
  ++result_.decisions;
  ++x.result.decisions;
  targets_[static_cast<std::size_t>(k)] = d.target;
  x.idle = d.path.empty();
  if (!x.idle) x.settled = false;
  return x.idle ? wander(x.edge, {x.edge}) : d.path.front();
}

/// With nothing to do, take the turn after `e` driven least often, a street already in `planned`
/// counting as driven once more (lowest id on ties): a provisional route does not go back and
/// forth between two streets nobody has finished yet.
int ExploreRun::wander(int e, const std::vector<int>& planned) const {
  auto times = [&](int n) {
    return drive_count_[static_cast<std::size_t>(n)] +
           static_cast<int>(std::count(planned.begin(), planned.end(), n));
  };
  int best = -1;
  for (int i = pg_.nextBegin(e); i < pg_.nextEnd(e); ++i) {
    const int n = pg_.next[static_cast<std::size_t>(i)];
    if (best < 0 || times(n) < times(best)) best = n;
  }
  if (best < 0) throw std::runtime_error(opts_.net.string() + ": no turn leaves a drivable street");
  return best;
}

void ExploreRun::recordDriven(int edge, double t) {
  if (drive_count_[static_cast<std::size_t>(edge)]++ > 0) return;
  ++result_.edges_driven;
  CoverageSample c;
  c.time_s = t - t0_;
  for (const auto& x : explorers_) {
    c.fleet_distance_m += x.odometer_m;
    c.vehicle_distance_m.push_back(x.odometer_m);
  }
  c.edges_driven = result_.edges_driven;
  result_.curve.push_back(c);
}

bool ExploreRun::finished() const {
  if (result_.edges_driven >= pg_.m) return true;
  // a street entered for the first time counts once it has been driven to its end
  if (explorers_.empty() || entered_ > result_.edges_driven) return false;
  return std::all_of(explorers_.begin(), explorers_.end(),
                     [](const Explorer& x) { return x.settled; });
}

FleetView ExploreRun::view() const {
  FleetView f{pg_, streets_, grid_, driven_, {}, targets_};
  for (const auto& x : explorers_) {
    VehicleView v;
    v.edge = x.edge;
    v.pos = x.pos;
    f.vehicles.push_back(v);
  }
  return f;
}

}  // namespace slamroute::explore
