#pragma once
// PCL's generalized ICP on our clouds: the outside reference for our own ICP (PclCrossCheckTest,
// bench_pcl). Include only where PCL may be compiled in (tests_evaluate, bench_pcl).
#include <pcl/point_types.h>
#include <pcl/registration/gicp.h>

#include <memory>
#include <optional>

#include "slamroute/core/Scan.hpp"
#include "slamroute/core/Types.hpp"
#include "slamroute/evaluate/Features.hpp"

namespace slamroute::evaluate::test {

inline pcl::PointCloud<pcl::PointXYZ>::Ptr toPcl(const Cloud& c) {
  auto out = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  for (const auto& p : c) out->push_back({p.x(), p.y(), p.z()});
  return out;
}

inline Cloud cloudOf(const Scan& s) {
  Cloud c;
  for (const auto& p : s.points) c.emplace_back(p.x, p.y, p.z);
  return c;
}

/// T_target_source by PCL's generalized ICP from identity; nothing when it did not converge.
inline std::optional<Pose3> pclGicp(const Cloud& target, const Cloud& source, double max_corr_m,
                                    int iterations) {
  pcl::GeneralizedIterativeClosestPoint<pcl::PointXYZ, pcl::PointXYZ> gicp;
  gicp.setInputTarget(toPcl(target));
  gicp.setInputSource(toPcl(source));
  gicp.setMaxCorrespondenceDistance(max_corr_m);
  gicp.setMaximumIterations(iterations);
  pcl::PointCloud<pcl::PointXYZ> aligned;
  gicp.align(aligned);
  if (!gicp.hasConverged()) return std::nullopt;
  Pose3 T = Pose3::Identity();
  T.matrix() = gicp.getFinalTransformation().cast<double>();
  return T;
}

}  // namespace slamroute::evaluate::test
