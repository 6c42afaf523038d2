#pragma once
// Internal: a JSON file parsed whole, for the readers of graph.json and route.json.
#include <nlohmann/json.hpp>

#include <filesystem>
#include <stdexcept>
#include <string>

#include "slamroute/core/AtomicFile.hpp"

namespace slamroute::detail {

/// Throws std::invalid_argument "PATH: not valid JSON (...)" (readFile's errors name the file too).
inline nlohmann::json readJsonFile(const std::filesystem::path& path) {
  try {
    return nlohmann::json::parse(readFile(path));
  } catch (const nlohmann::json::parse_error& e) {
    throw std::invalid_argument(path.string() + ": not valid JSON (" + std::string(e.what()) + ")");
  }
}

}  // namespace slamroute::detail
