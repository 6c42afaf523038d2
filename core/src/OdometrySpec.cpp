// odometry.yaml: the noise figures of a drive's wheel odometry + gyro.
#include "slamroute/core/OdometrySpec.hpp"

#include <cmath>
#include <stdexcept>

#include "slamroute/core/AtomicFile.hpp"
#include "slamroute/core/ConfigIO.hpp"

namespace slamroute {
namespace {

struct NonNegativeCheck {
  const std::filesystem::path& path;
  template <class T>
  void field(const char* key, T& v, const char*) {
    if (!std::isfinite(v) || v < 0)
      throw std::runtime_error(path.string() + ": '" + key + "' must be a number >= 0");
  }
};

}  // namespace

void writeOdometrySpec(const std::filesystem::path& path, const OdometrySpec& spec) {
  writeFileAtomic(path, config::dumpYaml(spec));
}

std::optional<OdometrySpec> readOdometrySpec(const std::filesystem::path& path) {
  if (!std::filesystem::exists(path)) return std::nullopt;
  OdometrySpec spec;
  try {
    config::loadYaml(YAML::LoadFile(path.string()), spec, path.string());
  } catch (const YAML::Exception& e) {
    throw std::runtime_error(path.string() + ": not valid YAML (" + e.msg + ")");
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(e.what());
  }
  NonNegativeCheck check{path};
  visitFields(check, spec);
  return spec;
}

}  // namespace slamroute
