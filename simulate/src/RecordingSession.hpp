#pragma once
// The SUMO session of the recording commands (survey, drive).
#include <cstdint>
#include <filesystem>

#include "slamroute/simulate/SumoSession.hpp"

namespace slamroute::simulate {

/// Options for a session that records vehicles: lane changes take 2 s instead of one step, so
/// the recorded positions never jump sideways by a lane.
SumoSessionOptions recordingSessionOptions(const std::filesystem::path& net, std::uint64_t seed,
                                           double step_length_s, double time_to_teleport_s);

}  // namespace slamroute::simulate
