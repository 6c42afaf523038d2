// Keyframe descriptors, searched by ring key (nanoflann's dynamic k-d tree) and compared under
// every rotation (PlaceDatabase.hpp).
#include "slamroute/evaluate/PlaceDatabase.hpp"

#include <algorithm>
#include <nanoflann.hpp>
#include <stdexcept>
#include <string>

#include "slamroute/core/ConfigCheck.hpp"

namespace slamroute::evaluate {
namespace {

struct Entry {
  int keyframe = -1;
  PlaceDescriptor descriptor;
  Vec3 position = Vec3::Zero();
};

/// nanoflann's dataset interface over the entries' ring keys.
struct RingKeys {
  const std::vector<Entry>* entries = nullptr;
  std::size_t kdtree_get_point_count() const { return entries->size(); }
  float kdtree_get_pt(std::size_t i, std::size_t dim) const {
    return (*entries)[i].descriptor.ring_key[dim];
  }
  template <class BBox>
  bool kdtree_get_bbox(BBox& /*bb*/) const {
    return false;
  }
};

using RingKeyTree =
    nanoflann::KDTreeSingleIndexDynamicAdaptor<nanoflann::L2_Simple_Adaptor<float, RingKeys>,
                                               RingKeys, -1, std::uint32_t>;

/// The k nearest entries that pass the query's filters (keyframe age, position gate): a
/// nanoflann result set that ignores the others, so the search goes on until it has k of them.
class FilteredNearest {
 public:
  using DistanceType = float;
  using IndexType = std::uint32_t;
  FilteredNearest(const std::vector<Entry>& entries, const PlaceQuery& q, std::size_t k)
      : entries_(entries), q_(q), k_(k) {}
  std::size_t size() const { return found_.size(); }
  bool full() const { return found_.size() == k_; }
  float worstDist() const {
    return full() ? found_.back().first : std::numeric_limits<float>::max();
  }
  bool addPoint(float dist, std::uint32_t index) {
    if (!accepted(entries_[index])) return true;
    const std::pair<float, std::uint32_t> item(dist, index);
    found_.insert(std::upper_bound(found_.begin(), found_.end(), item), item);
    if (found_.size() > k_) found_.pop_back();
    return true;
  }
  const std::vector<std::pair<float, std::uint32_t>>& found() const { return found_; }

 private:
  bool accepted(const Entry& e) const {
    if (e.keyframe > q_.newest_keyframe) return false;
    return !q_.gate_centre || (e.position - *q_.gate_centre).norm() <= q_.gate_radius_m;
  }
  const std::vector<Entry>& entries_;
  const PlaceQuery& q_;
  std::size_t k_;
  std::vector<std::pair<float, std::uint32_t>> found_;  ///< (squared distance, entry), ascending
};

}  // namespace

struct PlaceDatabase::Impl {
  PlaceRecognitionConfig cfg;
  std::vector<Entry> entries;
  RingKeys adaptor{&entries};
  std::unique_ptr<RingKeyTree> tree;
};

PlaceDatabase::PlaceDatabase(PlaceRecognitionConfig cfg) : impl_(std::make_unique<Impl>()) {
  config::validateSubsection("place.", cfg);
  impl_->cfg = cfg;
  impl_->tree = std::make_unique<RingKeyTree>(cfg.rings, impl_->adaptor);
}

PlaceDatabase::~PlaceDatabase() = default;

std::size_t PlaceDatabase::size() const { return impl_->entries.size(); }

void PlaceDatabase::add(int keyframe, PlaceDescriptor descriptor, const Vec3& position) {
  if (descriptor.rings != impl_->cfg.rings || descriptor.sectors != impl_->cfg.sectors)
    throw std::invalid_argument("place descriptor of keyframe " + std::to_string(keyframe) +
                                " is not " + std::to_string(impl_->cfg.rings) + "x" +
                                std::to_string(impl_->cfg.sectors));
  impl_->entries.push_back({keyframe, std::move(descriptor), position});
  const auto i = static_cast<std::uint32_t>(impl_->entries.size() - 1);
  impl_->tree->addPoints(i, i);
}

std::vector<PlaceCandidate> PlaceDatabase::query(const PlaceDescriptor& descriptor,
                                                 const PlaceQuery& q) const {
  const auto k = static_cast<std::size_t>(impl_->cfg.ring_key_candidates);
  FilteredNearest nearest(impl_->entries, q, k);
  if (descriptor.ring_key.size() != static_cast<std::size_t>(impl_->cfg.rings))
    throw std::invalid_argument("place descriptor with " +
                                std::to_string(descriptor.ring_key.size()) + " rings, not " +
                                std::to_string(impl_->cfg.rings));
  if (!impl_->entries.empty())
    impl_->tree->findNeighbors(nearest, descriptor.ring_key.data(), nanoflann::SearchParams());
  std::vector<PlaceCandidate> out;
  for (const auto& [sq_dist, index] : nearest.found()) {
    const Entry& e = impl_->entries[index];
    const PlaceMatch m = placeDistance(descriptor, e.descriptor);
    if (m.distance < impl_->cfg.max_distance) out.push_back({e.keyframe, m.distance, m.yaw_rad});
  }
  std::sort(out.begin(), out.end(), [](const PlaceCandidate& a, const PlaceCandidate& b) {
    return a.distance != b.distance ? a.distance < b.distance : a.keyframe < b.keyframe;
  });
  return out;
}

}  // namespace slamroute::evaluate
