#pragma once
// Statistics of study results: rank correlation and mean +- sample standard deviation.
#include <cstddef>
#include <string>
#include <vector>

namespace slamroute::pipeline {

/// Ranks 1..n of a sample, ties getting the mean of the ranks they share.
std::vector<double> ranks(const std::vector<double>& x);

/// Spearman rank correlation of two equally long samples (ties get mean ranks). NaN when n < 3
/// or a sample is constant.
double spearman(const std::vector<double>& a, const std::vector<double>& b);

struct MeanSd {
  double mean = 0.0;
  double sd = 0.0;  ///< sample standard deviation (n - 1); 0 for a single value
  std::size_t n = 0;
};

/// Mean and sample standard deviation; n = 0 (mean and sd NaN) for an empty sample.
MeanSd meanSd(const std::vector<double>& v);

/// "m ± s" with `decimals` digits after the point; "–" for an empty sample.
std::string formatMeanSd(const MeanSd& s, int decimals);

}  // namespace slamroute::pipeline
