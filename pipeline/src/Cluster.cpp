#include "slamroute/pipeline/Cluster.hpp"

#include <cstdlib>
#include <stdexcept>

namespace slamroute::pipeline {

namespace {

/// The one rank of a sweep run without MPI.
class SingleRank : public Cluster {
 public:
  int rank() const override { return 0; }
  int size() const override { return 1; }
  void send(int, Tag, const std::string&) override {
    throw std::logic_error("sweep: a single rank has no one to send to");
  }
  std::optional<Message> poll() override { return std::nullopt; }
  void peerDied(int) override {}
};

const char* envOf(const char* name) { return std::getenv(name); }

}  // namespace

bool launchedByMpi() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE", "PMI_RANK"})
    if (envOf(v)) return true;
  return false;
}

std::unique_ptr<Cluster> joinMpiCluster();  // ClusterMpi.cpp, or ClusterNoMpi.cpp

std::unique_ptr<Cluster> joinCluster() {
  if (!launchedByMpi()) return std::make_unique<SingleRank>();
  if (auto c = joinMpiCluster()) return c;
  const char* n = envOf("OMPI_COMM_WORLD_SIZE") ? envOf("OMPI_COMM_WORLD_SIZE") : envOf("PMI_SIZE");
  if (n && std::atoi(n) > 1)
    throw std::runtime_error("sweep: started by an MPI launcher with " + std::string(n) +
                             " ranks, but this slamroute was built without MPI");
  return std::make_unique<SingleRank>();
}

}  // namespace slamroute::pipeline
