#pragma once
// Internal: a JSON file parsed whole, for the readers of graph.json and route.json.
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "slamroute/core/AtomicFile.hpp"

namespace slamroute::detail {

/// The library's message without its "[json.exception.type_error.302] " tag, for a person.
inline std::string jsonErrorText(const nlohmann::json::exception& e) {
  const std::string what = e.what();
  const auto close = what.find("] ");
  return what.rfind("[json.exception.", 0) == 0 && close != std::string::npos
             ? what.substr(close + 2)
             : what;
}

/// Throws std::invalid_argument "PATH: not valid JSON (...)" (readFile's errors name the file too),
/// also for numbers out of double's range (1e400).
inline nlohmann::json readJsonFile(const std::filesystem::path& path) {
  try {
    return nlohmann::json::parse(readFile(path));
  } catch (const nlohmann::json::exception& e) {
    throw std::invalid_argument(path.string() + ": not valid JSON (" + jsonErrorText(e) + ")");
  }
}

/// Throws std::invalid_argument "WHERE: KEY is not a finite number; not written" for the first
/// NaN or infinity in `j`: JSON has no such numbers (nlohmann writes null), so the file could
/// not be read back.
inline void requireFiniteNumbers(const nlohmann::json& j, const std::string& where,
                                 const std::string& key = "") {
  if (j.is_number_float() && !std::isfinite(j.get<double>()))
    throw std::invalid_argument(where + ": " + (key.empty() ? "a value" : key) +
                                " is not a finite number; not written");
  if (j.is_object())
    for (const auto& [k, v] : j.items())
      requireFiniteNumbers(v, where, key.empty() ? k : key + "." + k);
  if (j.is_array())
    for (std::size_t i = 0; i < j.size(); ++i)
      requireFiniteNumbers(j[i], where, key + "[" + std::to_string(i) + "]");
}

}  // namespace slamroute::detail
