// `qlearning`: tabular Q-learning on the road graph (paper §3.2, Fig. 4, eqs. 5-7).
//
// Choices the paper leaves open (all in rl.qlearning, documented here where they are made):
//  - State. The paper's state is the position on the graph. Because turn permissions depend on
//    where one came from, the position is the *arrival edge* (node state at the start). Coverage
//    is not Markov in the position alone, so the state also carries a small local coverage
//    signature: bit i = "action i reaches something not yet covered", for the first
//    signature_bits actions (0 gives the paper's position-only state). Where no action reaches
//    anything new (deep in driven streets, where every state would look alike), the signature
//    instead marks the action on the shortest legal path to the nearest uncovered part
//    (guide_to_uncovered, UncoveredGuide.hpp); taking it earns guide_reward (shaping toward
//    the nearest unvisited node). Without it the greedy roll-out stalls there and shortest paths
//    drive 40-65 % of the route on real nets. Table size is
//    sum over states of 2^bits * actions: flat float array, ~64 entries per edge.
//  - Update: Q(s,a) += alpha * (R + gamma * max_a' Q(s',a') - Q(s,a)) (eq. 5 with a learning rate
//    alpha; eq. 5 as printed is the alpha = 1 case). No bootstrap at the terminal step.
//  - Exploration: epsilon-greedy, epsilon decays linearly from epsilon_start to epsilon_end over
//    the first epsilon_decay_fraction of the episodes. Ties of the greedy choice go to the first
//    action. Episodes start at the start node; an episode ends when the goal is met (every node
//    visited, paper) or after max_steps_per_edge * edges steps. With explore_new_first an
//    exploring step draws among the actions reaching something new, and where there is none
//    takes the guided action half of the time (off-policy: the table still learns every action
//    it tries), so that exploring episodes reach the goal too.
//  - Reward (eqs. 6-7): R = w_C R_C + w_A R_A + w_U R_U with w = 1, 1, 20 (paper).
//      R_C = (new coverage) - step_length_cost * len/mean_len: +1 per newly visited node (goal
//            nodes) or + street length / mean edge length per newly driven street (goal edges),
//            minus the path length spent (our reading of eq. 6's l_path term).
//      R_A = normalised edge weight in [0, 1] (eq. 6: weight(S_t, S_t+1)).
//      R_U = change of log det L over the step / (20 * u_ref): the paper rewards det(L) (eq. 6);
//            we reward its change in log form (what the action did to the information; the level
//            itself would add an action-independent drift), normalised by u_ref = the mean
//            per-edge drop of log det L when driving n mean-length edges of weight 1, so that
//            the paper's weight 20 makes the term ~1 per edge like R_C and R_A (the paper chose
//            its weights so that the terms have similar magnitude). A loop closure can raise
//            log det L by many u_ref at once; the weighted term is clipped to
//            +-uncertainty_clip so that seeking closures never outweighs covering new nodes.
//    The training loop runs the EIF in covariance form (FastEif, algebraically the same filter).
//    reward = "accuracy" keeps only R_A (paper Table 2).
//  - Route: greedy roll-out of the table from the start node. The greedy policy is
//    deterministic, so returning to a state with no coverage progress since its last visit is a
//    stall (it would cycle forever; optionally also stall_steps steps without progress, where
//    taking the guided action counts as progress); then, if complete_with_shortest_paths, the
//    route drives the shortest legal path to the nearest uncovered part and the roll-out resumes
//    (route.json: completed_by_shortest_paths, and the segment count / length in extra).
// Cost: episodes * steps, steps <= cap = O(edges * ln edges); the guide searches only when the
// state leaves its kept path. Nothing is allocated inside the episode loop.
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include "Coverage.hpp"
#include "Index.hpp"
#include "UncoveredGuide.hpp"
#include "slamroute/core/Log.hpp"
#include "slamroute/rl/Eif.hpp"
#include "slamroute/rl/Planners.hpp"

namespace slamroute::rl {

namespace {

/// Action table over states: edge states 0..m-1, node states m..m+n-1.
struct Table {
  std::vector<int> act_off, act;  // CSR of target edges
  std::vector<int> bits;          // signature bits per state
  std::vector<std::size_t> qoff;  // Q offset per state
  std::vector<float> q;
  int deg(int s) const { return act_off[sz(s) + 1] - act_off[sz(s)]; }
};

Table buildTable(const PlanGraph& pg, int signature_bits) {
  Table t;
  const int ns = pg.m + pg.n;
  t.act_off.assign(sz(ns) + 1, 0);
  for (int s = 0; s < ns; ++s) {
    if (s < pg.m)
      for (int k = pg.nextBegin(s); k < pg.nextEnd(s); ++k) t.act.push_back(pg.next[sz(k)]);
    else
      for (int k = pg.outBegin(s - pg.m); k < pg.outEnd(s - pg.m); ++k)
        t.act.push_back(pg.out[sz(k)]);
    t.act_off[sz(s) + 1] = static_cast<int>(t.act.size());
  }
  t.bits.resize(sz(ns));
  t.qoff.resize(sz(ns) + 1, 0);
  for (int s = 0; s < ns; ++s) {
    t.bits[sz(s)] = std::min(t.deg(s), signature_bits);
    t.qoff[sz(s) + 1] = t.qoff[sz(s)] + (std::size_t{1} << t.bits[sz(s)]) * sz(t.deg(s));
  }
  t.q.assign(t.qoff.back(), 0.0f);
  return t;
}

/// Coverage of one episode, reset in O(1) by stamps.
struct EpisodeCoverage {
  const PlanGraph& pg;
  Goal goal;
  std::vector<int> node_stamp, street_stamp;
  int stamp = 0, remaining = 0;
  EpisodeCoverage(const PlanGraph& graph, Goal goal_kind)
      : pg(graph),
        goal(goal_kind),
        node_stamp(sz(graph.n), 0),
        street_stamp(sz(graph.num_streets), 0) {}
  void reset(int start) {
    ++stamp;
    remaining = goal == Goal::Nodes ? pg.n - 1 : pg.num_streets;
    node_stamp[sz(start)] = stamp;
  }
  bool isNew(int e) const {
    return goal == Goal::Nodes ? node_stamp[sz(pg.v[sz(e)])] != stamp
                               : street_stamp[sz(pg.street[sz(e)])] != stamp;
  }
  /// New coverage gained by driving e, in R_C units.
  double drive(int e) {
    if (goal == Goal::Nodes) {
      int& s = node_stamp[sz(pg.v[sz(e)])];
      if (s == stamp) return 0.0;
      s = stamp;
      --remaining;
      return 1.0;
    }
    node_stamp[sz(pg.v[sz(e)])] = stamp;
    int& s = street_stamp[sz(pg.street[sz(e)])];
    if (s == stamp) return 0.0;
    s = stamp;
    --remaining;
    return pg.street_len[sz(pg.street[sz(e)])] / pg.mean_len;
  }
};

/// The EIF of Eif.hpp in covariance form (S = L^-1), algebraically identical, cheaper per step
/// (no inversion when driving); used in the training loop only. Metrics use PoseEif.
struct FastEif {
  Eigen::Matrix3d S0, S, R_lc;
  explicit FastEif(const EifConfig& cfg) {
    const PoseEif ref(cfg);
    S0 = ref.info().inverse();
    R_lc = closureNoise(cfg);
    S = S0;
  }
  void reset() { S = S0; }
  void drive(const EdgeMotion& motion) { S = motion.F * S * motion.F.transpose() + motion.Q; }
  void closeLoop(const Eigen::Matrix3d& node_cov) {
    const Eigen::Matrix3d L = S.inverse() + (node_cov + R_lc).inverse();
    S = L.inverse();
  }
  double logDetCov() const { return std::log(S.determinant()); }
};

/// What the agent sees in state s besides the state itself: bit i of sig = "action i reaches
/// something new", for the first bits[s] actions. Where no action does and the guide is on, the
/// bit of the action on the shortest legal path to the nearest uncovered part instead (its index
/// in `toward`, -1 otherwise): without it every state deep in covered streets looks the same.
struct Observation {
  int sig = 0, toward = -1;
};

template <class Cov>
Observation observe(const Table& t, int s, const Cov& cov, detail::UncoveredGuide* guide) {
  Observation o;
  const int b = t.act_off[sz(s)], deg = t.deg(s);
  bool any_new = false;
  for (int i = 0; i < deg; ++i) {
    if (!cov.isNew(t.act[sz(b + i)])) continue;
    any_new = true;
    if (i < t.bits[sz(s)]) o.sig |= 1 << i;
  }
  if (any_new || guide == nullptr) return o;
  const int e = guide->toward(s, [&cov](int f) { return cov.isNew(f); });
  for (int i = 0; i < deg; ++i)
    if (t.act[sz(b + i)] == e) o.toward = i;
  if (o.toward >= 0 && o.toward < t.bits[sz(s)]) o.sig = 1 << o.toward;
  return o;
}

int greedy(const float* q, int deg) {
  int best = 0;
  for (int i = 1; i < deg; ++i)
    if (q[i] > q[best]) best = i;
  return best;
}

/// An exploration action: uniform over the actions (paper), or, with new_first, uniform over those
/// reaching something not yet covered when there are any, else the guided action (`toward`, -1:
/// none) half of the time.
int explore(const Table& t, int s, const std::vector<int>& act, const EpisodeCoverage& cov,
            bool new_first, int toward, std::mt19937_64& rng) {
  const int deg = t.deg(s), b = t.act_off[sz(s)];
  if (new_first && toward >= 0 && (rng() & 1)) return toward;
  if (new_first) {
    int fresh = 0;
    for (int i = 0; i < deg; ++i) fresh += cov.isNew(act[sz(b + i)]) ? 1 : 0;
    if (fresh > 0) {
      int k = static_cast<int>(rng() % static_cast<std::uint64_t>(fresh));
      for (int i = 0; i < deg; ++i)
        if (cov.isNew(act[sz(b + i)]) && k-- == 0) return i;
    }
  }
  return static_cast<int>(rng() % static_cast<std::uint64_t>(deg));
}

/// Share of the route's length the greedy policy chose (the rest are shortest-path completions).
double learnedShare(const PlanGraph& pg, const std::vector<int>& edges, double shortest_m) {
  double length = 0.0;
  for (int e : edges) length += pg.len[sz(e)];
  return length > 0.0 ? std::max(0.0, 1.0 - shortest_m / length) : 0.0;
}

/// Settings the planner cannot work with, also when called without a validated config.
void checkSettings(const QLearningConfig& qc) {
  if (qc.episodes < 0 || qc.signature_bits < 0 || qc.signature_bits > 6 || qc.alpha <= 0 ||
      qc.alpha > 1 || qc.gamma < 0 || qc.gamma >= 1)
    throw std::invalid_argument(
        "rl.qlearning: need episodes >= 0, 0 <= signature_bits <= 6, "
        "0 < alpha <= 1, 0 <= gamma < 1");
}

/// R_U normalisation u_ref (see the header comment): the mean per-edge drop of log det L over n
/// mean-length edges of weight 1.
double uncertaintyReference(const PlanGraph& pg, const EifConfig& eif) {
  PoseEif f(eif);
  const EdgeMotion motion = edgeMotion(eif, pg.mean_len, 0.0, 1.0);
  const double l0 = f.logDetInfo();
  for (int i = 0; i < pg.n; ++i) f.drive(motion);
  return std::max((l0 - f.logDetInfo()) / std::max(pg.n, 1), 1e-12);
}

/// The training environment: coverage of the episode, the EIF along it and the reward of a step
/// (eqs. 6-7).
class Environment {
 public:
  Environment(const PlanGraph& pg, const Config& cfg, Goal goal)
      : cov(pg, goal),
        pg_(pg),
        cfg_(cfg),
        qc_(cfg.qlearning),
        full_(cfg.reward == "full"),
        eif_(cfg.eif),
        node_cov_(sz(pg.n)),
        node_logdet_(sz(pg.n), 0.0),
        node_travel_(sz(pg.n), 0.0),
        node_stamp_(sz(pg.n), 0) {
    motion_.resize(sz(pg.m));
    for (int e = 0; e < pg.m; ++e)
      motion_[sz(e)] = edgeMotion(cfg.eif, pg.len[sz(e)], pg.heading[sz(e)], pg.weight[sz(e)]);
    u_ref = uncertaintyReference(pg, cfg.eif);
    u_scale_ = 1.0 / (20.0 * u_ref);
  }

  /// Starts episode `episode` (0-based) at node `from`.
  void reset(int from, int episode) {
    stamp_ = episode + 1;
    cov.reset(from);
    eif_.reset();
    node_cov_[sz(from)] = eif_.S;
    node_logdet_[sz(from)] = eif_.logDetCov();
    node_travel_[sz(from)] = 0.0;
    node_stamp_[sz(from)] = stamp_;
    travel_ = 0.0;
    logdet_cov_ = eif_.logDetCov();
  }

  /// Drives edge f; returns the reward R.
  double step(int f) {
    const double gained = cov.drive(f);
    double reward = qc_.weight_accuracy * pg_.weight[sz(f)];
    if (!full_) return reward;
    travel_ += pg_.len[sz(f)];
    eif_.drive(motion_[sz(f)]);
    const double logdet = arriveAt(pg_.v[sz(f)]);
    // R_U: gain of log det L = drop of log det covariance, clipped (see header).
    const double uncertainty =
        std::clamp((logdet_cov_ - logdet) * u_scale_ * qc_.weight_uncertainty,
                   -qc_.uncertainty_clip, qc_.uncertainty_clip);
    reward +=
        qc_.weight_coverage * (gained - qc_.step_length_cost * pg_.len[sz(f)] / pg_.mean_len) +
        uncertainty;
    logdet_cov_ = logdet;
    return reward;
  }

  EpisodeCoverage cov;
  double u_ref = 1.0;

 private:
  /// Closes a loop at a node seen this episode far enough back; keeps the best covariance seen
  /// at each node. Returns log det of the covariance after arriving at w.
  double arriveAt(int w) {
    double logdet = eif_.logDetCov();
    if (node_stamp_[sz(w)] == stamp_) {
      if (travel_ - node_travel_[sz(w)] >= cfg_.eif.loop_min_travel_m) {
        eif_.closeLoop(node_cov_[sz(w)]);
        logdet = eif_.logDetCov();
      }
      if (logdet < node_logdet_[sz(w)]) node_cov_[sz(w)] = eif_.S, node_logdet_[sz(w)] = logdet;
    } else {
      node_stamp_[sz(w)] = stamp_;
      node_cov_[sz(w)] = eif_.S;
      node_logdet_[sz(w)] = logdet;
    }
    node_travel_[sz(w)] = travel_;
    return logdet;
  }

  const PlanGraph& pg_;
  const Config& cfg_;
  const QLearningConfig& qc_;
  bool full_;
  std::vector<EdgeMotion> motion_;
  double u_scale_ = 1.0;
  FastEif eif_;
  std::vector<Eigen::Matrix3d> node_cov_;
  std::vector<double> node_logdet_, node_travel_;
  std::vector<int> node_stamp_;
  int stamp_ = 0;
  double travel_ = 0.0, logdet_cov_ = 0.0;
};

/// What training did, for route.json.
struct TrainingStats {
  long long steps = 0;
  int episodes_reaching_goal = 0;
};

/// The Q row of state s under coverage signature sig.
float* qRow(Table& t, int s, int sig) { return &t.q[t.qoff[sz(s)] + sz(sig) * sz(t.deg(s))]; }

/// One epsilon-greedy episode from node `from` with Q-learning updates (eq. 5); true when it met
/// the goal.
bool runEpisode(Table& t, Environment& env, const QLearningConfig& qc, int from, double eps,
                std::mt19937_64& rng, long long cap, long long& steps,
                detail::UncoveredGuide* guide) {
  auto uniform = [&rng] { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
  if (guide != nullptr) guide->reset();
  int s = env.cov.pg.m + from;
  Observation obs = observe(t, s, env.cov, guide);
  for (long long step = 0; step < cap; ++step) {
    float* qs = qRow(t, s, obs.sig);
    const int i = uniform() < eps
                      ? explore(t, s, t.act, env.cov, qc.explore_new_first, obs.toward, rng)
                      : greedy(qs, t.deg(s));
    const int f = t.act[sz(t.act_off[sz(s)] + i)];
    const double reward = env.step(f) + (i == obs.toward ? qc.guide_reward : 0.0);
    ++steps;
    const bool done = env.cov.remaining == 0;
    const Observation obs2 = observe(t, f, env.cov, guide);
    double target = reward;
    if (!done) {
      const float* q2 = qRow(t, f, obs2.sig);
      target += qc.gamma * q2[greedy(q2, t.deg(f))];
    }
    qs[i] += static_cast<float>(qc.alpha * (target - qs[i]));
    if (done) return true;
    s = f;
    obs = obs2;
  }
  return false;
}

/// Trains the table over qc.episodes episodes (exploration schedule in the header comment).
TrainingStats train(Table& t, Environment& env, const QLearningConfig& qc, int start,
                    std::uint64_t seed) {
  const PlanGraph& pg = env.cov.pg;
  std::mt19937_64 rng(seed);
  // A random walk needs about m ln m steps to drive every one of m edges (cover time), so a cap
  // linear in m cuts the walks of larger graphs short of the goal.
  const double cap_scale = qc.cap_scales_with_log_edges ? std::max(1.0, std::log(pg.m)) : 1.0;
  const long long cap =
      std::max<long long>(static_cast<long long>(qc.max_steps_per_edge * pg.m * cap_scale), 1);
  const int decay_eps = std::max(1, static_cast<int>(qc.epsilon_decay_fraction * qc.episodes));
  TrainingStats stats;
  detail::UncoveredGuide guide(pg);
  Progress progress("qlearning", sz(std::max(qc.episodes, 0)));
  for (int ep = 0; ep < qc.episodes; ++ep) {
    const double eps = qc.epsilon_start + (qc.epsilon_end - qc.epsilon_start) *
                                              std::min(1.0, static_cast<double>(ep) / decay_eps);
    const int from = qc.spread_starts && ep % 2 == 1
                         ? static_cast<int>(rng() % static_cast<std::uint64_t>(pg.n))
                         : start;
    env.reset(from, ep);
    if (runEpisode(t, env, qc, from, eps, rng, cap, stats.steps,
                   qc.guide_to_uncovered ? &guide : nullptr))
      ++stats.episodes_reaching_goal;
    progress.update(sz(ep + 1));
  }
  progress.finish();
  return stats;
}

/// The greedy roll-out's route and its shortest-path completions.
struct Rollout {
  std::vector<int> edges;
  bool completed_by_shortest_paths = false;
  int segments = 0;
  double shortest_len_m = 0.0;
};

/// Appends the shortest legal path from the current state to the nearest uncovered part; false
/// when there is none.
bool completeOnce(const PlanGraph& pg, const TurnPaths& paths, detail::Coverage& cov, int s,
                  int start, Rollout& r) {
  auto p = paths.toNearest(s < pg.m ? s : -1, start, [&cov](int e) { return cov.isNew(e); });
  if (!p) return false;
  for (int e : p->edges) {
    cov.drive(e);
    r.edges.push_back(e);
  }
  r.shortest_len_m += p->length_m;
  ++r.segments;
  r.completed_by_shortest_paths = true;
  return true;
}

/// Greedy roll-out of the table from the start node with stall detection (see header comment).
Rollout greedyRollout(const PlanGraph& pg, const TurnPaths& paths, const Table& t,
                      const QLearningConfig& qc, Goal goal, int start) {
  Rollout r;
  detail::Coverage cov(pg, goal, start);
  detail::UncoveredGuide guide(pg);
  std::vector<int> seen_epoch(sz(pg.m + pg.n), -1);
  int epoch = 0;
  int s = pg.m + start;
  const long long roll_cap = 10LL * pg.m + 10;
  long long progress_step = 0;
  for (long long step = 0; !cov.done() && step < roll_cap; ++step) {
    const bool stalled = seen_epoch[sz(s)] == epoch ||
                         (qc.stall_steps > 0 && step - progress_step >= qc.stall_steps);
    if (stalled) {  // back in a state without progress (or too long without any)
      if (!qc.complete_with_shortest_paths || !completeOnce(pg, paths, cov, s, start, r)) break;
      s = r.edges.back();
      ++epoch;
      progress_step = step;
      continue;
    }
    seen_epoch[sz(s)] = epoch;
    // The roll-out's own coverage; taking the guided action counts as progress too.
    const Observation obs = observe(t, s, cov, qc.guide_to_uncovered ? &guide : nullptr);
    const int deg = t.deg(s);
    const int i = greedy(&t.q[t.qoff[sz(s)] + sz(obs.sig) * sz(deg)], deg);
    const int f = t.act[sz(t.act_off[sz(s)] + i)];
    if (cov.drive(f))
      ++epoch, progress_step = step;
    else if (i == obs.toward)
      progress_step = step;
    r.edges.push_back(f);
    s = f;
  }
  if (!cov.done() && qc.complete_with_shortest_paths) {
    r.segments +=
        detail::completeByShortestPaths(pg, paths, cov, start, r.edges, &r.shortest_len_m);
    r.completed_by_shortest_paths = true;
  }
  return r;
}

}  // namespace

PlanOutput planQLearning(const PlanGraph& pg, const TurnPaths& paths, const Config& cfg, int start,
                         std::uint64_t seed) {
  const QLearningConfig& qc = cfg.qlearning;
  checkSettings(qc);
  const Goal goal = parseGoal(cfg.goal);
  Table t = buildTable(pg, qc.signature_bits);
  Environment env(pg, cfg, goal);
  const TrainingStats stats = train(t, env, qc, start, seed);
  Rollout rollout = greedyRollout(pg, paths, t, qc, goal, start);

  PlanOutput out;
  out.edges = std::move(rollout.edges);
  out.completed_by_shortest_paths = rollout.completed_by_shortest_paths;
  if (out.completed_by_shortest_paths)
    out.notes = "greedy roll-out stalled " + std::to_string(rollout.segments) +
                " time(s); completed by shortest paths to the nearest uncovered part";
  out.heuristic = true;
  out.stats = QLearningStats{qc.episodes,
                             stats.episodes_reaching_goal,
                             stats.steps,
                             static_cast<long long>(t.q.size()),
                             env.u_ref,
                             rollout.segments,
                             rollout.shortest_len_m,
                             learnedShare(pg, out.edges, rollout.shortest_len_m)};
  return out;
}

}  // namespace slamroute::rl
