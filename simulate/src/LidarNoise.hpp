#pragma once
// Internal: counter-based random numbers for sensor noise — a pure function of (seed, scan,
// ray), so results never depend on thread scheduling.
#include <cmath>
#include <cstdint>

namespace slamroute::simulate::detail {

inline std::uint64_t splitmix(std::uint64_t z) {
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

struct RayRandom {
  std::uint64_t state;
  /// Per-scan key, computed once per scan: the stream of ray r starts at key ^ r.
  static std::uint64_t scanKey(std::uint64_t seed, std::uint64_t scan) {
    return splitmix(splitmix(seed ^ 0x5eed1da7ULL) ^ splitmix(scan * 0x100000001b3ULL + 17));
  }
  RayRandom(std::uint64_t key, std::uint64_t ray) : state(key ^ ray) {}
  RayRandom(std::uint64_t seed, std::uint64_t scan, std::uint64_t ray)
      : RayRandom(scanKey(seed, scan), ray) {}
  double uniform() {  // (0, 1)
    state = splitmix(state);
    return (static_cast<double>(state >> 11) + 0.5) * (1.0 / 9007199254740992.0);
  }
  /// Standard normal by inverting the CDF (Acklam's rational approximation, |rel err| < 1.2e-9):
  /// one uniform, and no log/sqrt for the central 95 % — cheaper than Box-Muller per ray.
  double normal() { return inverseNormalCdf(uniform()); }

  static double inverseNormalCdf(double p) {
    static constexpr double a[] = {-3.969683028665376e+01, 2.209460984245205e+02,
                                   -2.759285104469687e+02, 1.383577518672690e+02,
                                   -3.066479806614716e+01, 2.506628277459239e+00};
    static constexpr double b[] = {-5.447609879822406e+01, 1.615858368580409e+02,
                                   -1.556989798598866e+02, 6.680131188771972e+01,
                                   -1.328068155288572e+01};
    static constexpr double c[] = {-7.784894002430293e-03, -3.223964580411365e-01,
                                   -2.400758277161838e+00, -2.549732539343734e+00,
                                   4.374664141464968e+00,  2.938163982698783e+00};
    static constexpr double d[] = {7.784695709041462e-03, 3.224671290700398e-01,
                                   2.445134137142996e+00, 3.754408661907416e+00};
    constexpr double lo = 0.02425, hi = 1.0 - 0.02425;
    if (p < lo) {
      const double q = std::sqrt(-2 * std::log(p));
      return (((((c[0] * q + c[1]) * q + c[2]) * q + c[3]) * q + c[4]) * q + c[5]) /
             ((((d[0] * q + d[1]) * q + d[2]) * q + d[3]) * q + 1);
    }
    if (p > hi) {
      const double q = std::sqrt(-2 * std::log(1 - p));
      return -(((((c[0] * q + c[1]) * q + c[2]) * q + c[3]) * q + c[4]) * q + c[5]) /
             ((((d[0] * q + d[1]) * q + d[2]) * q + d[3]) * q + 1);
    }
    const double q = p - 0.5, r = q * q;
    return (((((a[0] * r + a[1]) * r + a[2]) * r + a[3]) * r + a[4]) * r + a[5]) * q /
           (((((b[0] * r + b[1]) * r + b[2]) * r + b[3]) * r + b[4]) * r + 1);
  }
};

}  // namespace slamroute::simulate::detail
