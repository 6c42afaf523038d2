#pragma once
// The ranks of a sweep and the messages between them. Under `mpirun` or `srun` (and when
// slamroute is built with MPI) the ranks are MPI processes; otherwise there is one rank.
// Messages are short texts (JSON) with a tag, sent and polled without blocking.
#include <memory>
#include <optional>
#include <string>

namespace slamroute::pipeline {

enum class Tag : int { Hello = 1, Task = 2, Done = 3, Heartbeat = 4, Stop = 5 };

struct Message {
  int from = 0;
  Tag tag = Tag::Hello;
  std::string text;
};

class Cluster {
 public:
  virtual ~Cluster() = default;
  virtual int rank() const = 0;
  virtual int size() const = 0;
  /// Sends without waiting for the receiver; a dead receiver is not an error here (the
  /// scheduler notices it by its silence).
  virtual void send(int to, Tag tag, const std::string& text) = 0;
  /// A message that has arrived, if any (never waits).
  virtual std::optional<Message> poll() = 0;
  /// The scheduler took rank `r` for dead: the cluster does not wait for it when it shuts down.
  virtual void peerDied(int r) = 0;
};

/// Whether this process was started by an MPI launcher (mpirun, srun with PMI/PMIx).
bool launchedByMpi();

/// This process's place in the sweep: MPI (initialised here, finalised by the destructor) when
/// launched by an MPI launcher and built with MPI; else a single rank. Throws when launched
/// by an MPI launcher but built without MPI and the launcher started several ranks.
std::unique_ptr<Cluster> joinCluster();

}  // namespace slamroute::pipeline
