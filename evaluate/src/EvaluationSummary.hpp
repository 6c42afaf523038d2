#pragma once
// Parts of EvaluationResult taken from a SLAM run (EvaluationSummary.cpp).
#include <vector>

#include "slamroute/evaluate/EvaluationResult.hpp"
#include "slamroute/evaluate/Slam.hpp"

namespace slamroute::evaluate {

std::vector<LoopRecord> loopRecords(const SlamResult& slam);
/// The stage times per scan of a run over `n` scans [ms].
TimingMsPerScan timingMsPerScan(const StageTimes& t, double n);

}  // namespace slamroute::evaluate
