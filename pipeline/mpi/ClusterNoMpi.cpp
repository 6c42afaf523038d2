// Built without MPI: a sweep always runs as a single rank.
#include <memory>

#include "slamroute/pipeline/Cluster.hpp"

namespace slamroute::pipeline {

std::unique_ptr<Cluster> joinMpiCluster() { return nullptr; }

}  // namespace slamroute::pipeline
