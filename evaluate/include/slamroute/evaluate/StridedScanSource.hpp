#pragma once
// A view of every n-th scan of another ScanSource (Config::scan_stride), optionally limited to a
// time window (Config::start_s / end_s), so a user can evaluate one stretch of a long drive.
#include <stdexcept>

#include "slamroute/core/Scan.hpp"

namespace slamroute::evaluate {

class StridedScanSource : public ScanSource {
 public:
  /// Scans with start_s <= time <= end_s (end_s <= 0: to the end), every `stride`-th of them.
  StridedScanSource(const ScanSource& base, int stride, double start_s = 0.0, double end_s = 0.0)
      : base_(base), stride_(static_cast<std::size_t>(stride)) {
    if (stride < 1) throw std::invalid_argument("evaluate.input.scan_stride must be >= 1");
    std::size_t first = 0, last = base.size();
    while (first < last && base.time(first) < start_s) ++first;
    if (end_s > 0)
      while (last > first && base.time(last - 1) > end_s) --last;
    first_ = first;
    count_ = last - first;
  }
  std::size_t size() const override { return (count_ + stride_ - 1) / stride_; }
  double time(std::size_t i) const override { return base_.time(first_ + i * stride_); }
  Scan scan(std::size_t i) const override { return base_.scan(first_ + i * stride_); }
  LidarSpec spec() const override { return base_.spec(); }

 private:
  const ScanSource& base_;
  std::size_t stride_;
  std::size_t first_ = 0, count_ = 0;
};

}  // namespace slamroute::evaluate
