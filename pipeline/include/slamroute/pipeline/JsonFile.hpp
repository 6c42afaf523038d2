#pragma once
// Reading the JSON files earlier steps wrote.
#include <filesystem>

#include <nlohmann/json.hpp>

namespace slamroute::pipeline {

/// The JSON in `path`, or an empty object when the file does not exist (a step that did not run
/// or failed). A file that exists but cannot be read or parsed is an error: throws
/// std::runtime_error naming the file and the problem.
nlohmann::json readJsonIfPresent(const std::filesystem::path& path);

}  // namespace slamroute::pipeline
