// Context (global options + config loading) and shared CLI helpers.
#include <filesystem>

#include "Commands.hpp"
#include "slamroute/core/AtomicFile.hpp"
#include "slamroute/core/ConfigIO.hpp"
#include "slamroute/core/Log.hpp"

namespace slamroute::cli {

void loadConfigFile(const std::string& file, AppConfig& cfg) {
  if (!std::filesystem::exists(file)) throw std::runtime_error(file + ": config file not found");
  const std::string text = readFile(file);  // names a folder as such
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw std::runtime_error(file + ": not valid YAML (" + e.msg + ")");
  }
  config::loadYaml(root, cfg, file);
}

void Context::load() {
  setLogLevel(parseLogLevel(log_level));
  if (!config_file.empty()) loadConfigFile(config_file, cfg);
  if (seed) cfg.seed = *seed;
  try {
    cfg.rl.coverage.validate();
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error((config_file.empty() ? std::string("config") : config_file) + ": " +
                             e.what());
  }
}

std::string defaultNetPath() {
  namespace fs = std::filesystem;
  const fs::path rel = fs::path("networks") / "default_city" / "default_city.net.xml";
  // Prefer a checkout-relative path, then the source tree the binary was built from.
  for (const fs::path& base : {fs::current_path(), fs::path(SLAMROUTE_SOURCE_DIR)}) {
    if (fs::exists(base / rel)) return (base / rel).string();
  }
  return (fs::path(SLAMROUTE_SOURCE_DIR) / rel).string();
}

}  // namespace slamroute::cli
