#pragma once
// Names of the files in a drive folder (written by `slamroute drive`, read by `evaluate`).
namespace slamroute::drive_files {
inline constexpr const char* kGroundTruth = "groundtruth.tum";  ///< TUM, 10 Hz, sensor poses
inline constexpr const char* kPoseEdges = "pose_edges.csv";     ///< index,t,sumo_edge,lane_pos_m
inline constexpr const char* kSensor = "sensor.yaml";           ///< LidarSpec + noise settings
inline constexpr const char* kWorld = "world.yaml";             ///< net path, world config, seed
inline constexpr const char* kWorldMesh = "world.ply";          ///< static world triangle mesh
inline constexpr const char* kDriveInfo = "drive.json";         ///< route, length, teleports, …
inline constexpr const char* kScanDir = "scans";                ///< NNNNNN.bin + times.txt
inline constexpr const char* kOdometry = "odometry.csv";  ///< optional: t,speed_mps,yaw_rate_rad_s
inline constexpr const char* kOdometrySpec = "odometry.yaml";  ///< optional: its noise figures
}  // namespace slamroute::drive_files
