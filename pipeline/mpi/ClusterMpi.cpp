// The ranks of a sweep as MPI processes (built when CMake finds MPI).
#include <mpi.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "slamroute/pipeline/Cluster.hpp"

namespace slamroute::pipeline {

namespace {

class MpiCluster : public Cluster {
 public:
  MpiCluster() {
    int provided = 0;
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_SINGLE, &provided);
    // A dead rank must not take the others down: errors come back as return codes.
    MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
  }
  ~MpiCluster() override {
    // Sends still pending go to a rank that died: cancelled, or MPI_Finalize would wait for them.
    for (auto& p : pending_) {
      MPI_Cancel(&p.req);
      MPI_Request_free(&p.req);
    }
    // MPI_Finalize synchronises with every rank and would wait for a dead one forever; the
    // launcher ends the job once this process exits.
    if (!peer_died_) MPI_Finalize();
  }
  void peerDied(int) override { peer_died_ = true; }
  int rank() const override { return rank_; }
  int size() const override { return size_; }

  void send(int to, Tag tag, const std::string& text) override {
    // Buffered: the message is copied out and the call returns at once, even when the
    // receiver is busy or gone.
    auto copy = std::make_unique<std::string>(text);  // the buffer must outlive the send
    MPI_Request req;
    if (MPI_Isend(copy->data(), static_cast<int>(copy->size()), MPI_CHAR, to, static_cast<int>(tag),
                  MPI_COMM_WORLD, &req) == MPI_SUCCESS)
      pending_.push_back({std::move(copy), req});
    reap();
  }

  std::optional<Message> poll() override {
    reap();
    int flag = 0;
    MPI_Status st;
    if (MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &st) != MPI_SUCCESS || !flag)
      return std::nullopt;
    int n = 0;
    MPI_Get_count(&st, MPI_CHAR, &n);
    std::string text(static_cast<std::size_t>(n), '\0');
    MPI_Recv(text.data(), n, MPI_CHAR, st.MPI_SOURCE, st.MPI_TAG, MPI_COMM_WORLD,
             MPI_STATUS_IGNORE);
    return Message{st.MPI_SOURCE, static_cast<Tag>(st.MPI_TAG), std::move(text)};
  }

 private:
  struct Pending {
    std::unique_ptr<std::string> text;  // kept alive until the send completes
    MPI_Request req;
  };

  /// Frees the sends that have completed.
  void reap() {
    for (std::size_t i = 0; i < pending_.size();) {
      int done = 0;
      if (MPI_Test(&pending_[i].req, &done, MPI_STATUS_IGNORE) != MPI_SUCCESS || done) {
        pending_.erase(pending_.begin() + static_cast<std::ptrdiff_t>(i));
      } else {
        ++i;
      }
    }
  }

  int rank_ = 0, size_ = 1;
  bool peer_died_ = false;
  std::vector<Pending> pending_;
};

}  // namespace

std::unique_ptr<Cluster> joinMpiCluster() { return std::make_unique<MpiCluster>(); }

}  // namespace slamroute::pipeline
