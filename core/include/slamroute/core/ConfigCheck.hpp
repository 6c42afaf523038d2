#pragma once
// Checks for config validate() functions: each throws std::invalid_argument "KEY must be ...
// (got VALUE)"; the loader puts the file and section in front (config::validateSection).
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace slamroute::config {

template <class T>
[[noreturn]] void rejectValue(const char* key, T value, const std::string& rule) {
  std::ostringstream os;
  os.precision(10);
  os << key << " must be " << rule << " (got " << value << ")";
  throw std::invalid_argument(os.str());
}

/// lo <= value <= hi, finite.
template <class T>
void requireRange(const char* key, T value, T lo, T hi) {
  if (!(value >= lo && value <= hi)) {  // also false for NaN
    std::ostringstream rule;
    rule.precision(10);
    rule << "in [" << lo << ", " << hi << "]";
    rejectValue(key, value, rule.str());
  }
}

/// value > 0 and value <= hi.
inline void requirePositive(const char* key, double value, double hi = 1e9) {
  if (!(value > 0 && value <= hi)) {
    std::ostringstream rule;
    rule << "> 0 and <= " << hi;
    rejectValue(key, value, rule.str());
  }
}

/// 0 <= value <= hi (sigmas, shares, optional lengths where 0 means off).
inline void requireNonNegative(const char* key, double value, double hi = 1e9) {
  requireRange(key, value, 0.0, hi);
}

/// Runs `sub.validate()` and puts `prefix` ("section." or "FILE: section.") before the key its
/// error names.
template <class S>
void validateSubsection(const std::string& prefix, const S& sub) {
  try {
    sub.validate();
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(prefix + e.what());
  }
}

}  // namespace slamroute::config
