#pragma once
// A view of every n-th scan of another ScanSource (Config::scan_stride).
#include <stdexcept>

#include "slamroute/core/Scan.hpp"

namespace slamroute::evaluate {

class StridedScanSource : public ScanSource {
 public:
  StridedScanSource(const ScanSource& base, int stride) : base_(base), stride_(stride) {
    if (stride < 1) throw std::invalid_argument("evaluate.scan_stride must be >= 1");
  }
  std::size_t size() const override { return (base_.size() + stride_ - 1) / stride_; }
  double time(std::size_t i) const override { return base_.time(i * stride_); }
  Scan scan(std::size_t i) const override { return base_.scan(i * stride_); }
  LidarSpec spec() const override { return base_.spec(); }

 private:
  const ScanSource& base_;
  std::size_t stride_;
};

}  // namespace slamroute::evaluate
