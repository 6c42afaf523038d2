#pragma once
// Turn-by-turn instructions of a route over a SUMO net: one step per manoeuvre (the SUMO
// <connection>'s direction, or roundabout exit n), the street (the edge's `name`), how far to
// drive on it, and, where the route drives a street again, why.
#include <string>
#include <vector>

#include "slamroute/core/SumoNet.hpp"
#include "slamroute/core/Types.hpp"

namespace slamroute::exports {

enum class Manoeuvre { Depart, Straight, SlightLeft, Left, SlightRight, Right, UTurn, Roundabout };

/// "depart", "straight", "slight left", "left", "slight right", "right", "U-turn", "roundabout".
std::string manoeuvreName(Manoeuvre m);

/// Why a street is driven again.
enum class Revisit {
  None,         ///< first time on this street
  LoopClosure,  ///< comes back to a junction after a loop long enough for a SLAM loop closure
  Connection,   ///< crosses driven streets to reach streets not yet driven
  Return,       ///< no street after it is new: the way to the end of the route
};

std::string revisitReason(Revisit r);

struct InstructionConfig {
  /// A return to a junction after at least this much driving is a loop closure [m] (the
  /// planner's rl.eif.loop_min_travel_m).
  double loop_min_travel_m = 50.0;
};

struct Instruction {
  int step = 0;  ///< 1-based
  Manoeuvre manoeuvre = Manoeuvre::Depart;
  int roundabout_exit = 0;              ///< for Roundabout: the exit taken, counted from the entry
  std::string street;                   ///< edge name of the street driven after the manoeuvre
  std::vector<std::string> sumo_edges;  ///< the edges driven until the next step
  double at_m = 0.0;                    ///< distance from the start to the manoeuvre [m]
  double drive_m = 0.0;                 ///< distance to the next step (or the end) [m]
  Point2 at_xy = Point2::Zero();        ///< where the manoeuvre is (net x/y) [m]
  Revisit revisit = Revisit::None;
  std::string revisit_detail;  ///< e.g. "back at junction J after 640 m"
};

/// Throws std::invalid_argument naming the net when an edge is not in it.
std::vector<Instruction> turnByTurn(const SumoNet& net, const std::vector<std::string>& sumo_edges,
                                    const InstructionConfig& cfg = {});

/// "Turn left onto Main Street", "At the roundabout take exit 2 onto B Road", ...
std::string instructionText(const Instruction& in);

}  // namespace slamroute::exports
