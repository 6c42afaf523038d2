#include "slamroute/pipeline/JsonFile.hpp"

#include <stdexcept>

#include "slamroute/core/AtomicFile.hpp"

namespace slamroute::pipeline {

nlohmann::json readJsonIfPresent(const std::filesystem::path& path) {
  if (!std::filesystem::exists(path)) return nlohmann::json::object();
  try {
    return nlohmann::json::parse(readFile(path));
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(path.string() + ": not valid JSON (" + e.what() + ")");
  }
}

}  // namespace slamroute::pipeline
