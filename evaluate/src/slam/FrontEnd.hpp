#pragma once
// The SLAM's front end (LeGO-LOAM "imageProjection" + "featureAssociation", paper §3.3): motion
// compensation of the sweep, range image, ground, clusters, edge and planar features, and the
// feature clouds the keyframe and the scan-to-map take from them.
#include "slamroute/core/Scan.hpp"
#include "slamroute/evaluate/Config.hpp"
#include "slamroute/evaluate/Features.hpp"
#include "slamroute/evaluate/Registration.hpp"
#include "slamroute/evaluate/Slam.hpp"

namespace slamroute::evaluate::slam {

struct PreparedScan {
  FrameStatus status = FrameStatus::Ok;  ///< Empty / Invalid: nothing else is set
  FeatureSet features;
  Cloud kf_edges, kf_planes;    ///< voxel-filtered features a keyframe keeps (the local map)
  Cloud src_edges, src_planes;  ///< the scan-to-map source, thinned to a fixed budget
};

/// The scan with each point moved from its firing time to the sweep's start (Scan::t):
/// p_start = M(dt) p, with M(dt) the share dt / sweep_s of `sweep_motion`, the body's motion over
/// sweep_s seconds (constant turn rate and speed within one sweep). Scans without point times are
/// returned as they are.
Scan deskewed(const Scan& scan, const Pose3& sweep_motion, double sweep_s);

/// The motion over a sweep of sweep_s seconds at the constant velocity of the step from
/// `T_from` to `T_to` (dt_s seconds apart, world poses): the step's share sweep_s / dt_s.
Pose3 sweepMotionOfStep(const Pose3& T_from, const Pose3& T_to, double dt_s, double sweep_s);

/// Whether a registration matched enough edge and planar features to be believed
/// (MappingConfig::min_edge_features, min_plane_features).
bool enoughMatches(const AlignResult& r, const MappingConfig& c);

/// Steps 1-2 of the pipeline on one scan; accumulates the stage times.
PreparedScan prepareScan(const Scan& scan, const LidarSpec& spec, const Config& cfg,
                         StageTimes& times);

/// At most `max_n` points of `c`, evenly strided (voxel-sorted input: thins space uniformly).
Cloud capped(Cloud c, int max_n);

}  // namespace slamroute::evaluate::slam
