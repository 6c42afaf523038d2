#pragma once
// The JSON form of the evaluation's typed results (metrics.json and `compare --json`), kept to
// the file boundary: nothing else in the libraries passes these objects around.
#include <nlohmann/json.hpp>

#include "slamroute/evaluate/EvaluationResult.hpp"

namespace slamroute::evaluate {

nlohmann::json toJson(const TrajectorySummary& t);
nlohmann::json toJson(const Reliability& r);
nlohmann::json toJson(const EvaluationResult& r);

/// The inverse of toJson(EvaluationResult); throws std::runtime_error on a missing key or a
/// value of the wrong type.
EvaluationResult evaluationFromJson(const nlohmann::json& j);

}  // namespace slamroute::evaluate
