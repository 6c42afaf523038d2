// per_edge.csv: evaluate's drift per SUMO edge, written once and read back by the report and the
// EIF calibration, so the column order lives in one place.
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "slamroute/core/AtomicFile.hpp"
#include "slamroute/evaluate/Metrics.hpp"

namespace slamroute::evaluate {
namespace {

constexpr const char* kHeader =
    "sumo_edge,poses,visits,length_m,ate_mean_m,ate_max_m,drift_pct,rot_deg_per_m,"
    "window_drift_pct";

std::vector<std::string> fields(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  for (std::string f; std::getline(ss, f, ',');) out.push_back(f);
  return out;
}

double number(const std::string& cell) {
  std::size_t used = 0;
  double v = 0;
  try {
    v = std::stod(cell, &used);
  } catch (const std::exception&) {
  }
  if (used == 0 || used != cell.size()) throw std::runtime_error("bad number '" + cell + "'");
  return v;
}

/// A count (poses, visits): a whole number of at least 0, so a hand-edited 12.5 is an error, not
/// 12.
int count(const std::string& cell) {
  const double v = number(cell);
  if (!(v >= 0) || v != std::floor(v) || v > std::numeric_limits<int>::max())
    throw std::runtime_error("bad count '" + cell + "'");
  return static_cast<int>(v);
}

/// One row; files written before window_drift_pct have 8 columns and give NaN there.
EdgeError parseRow(const std::vector<std::string>& c) {
  if (c.size() != 8 && c.size() != 9)
    throw std::runtime_error(std::to_string(c.size()) + " columns, expected 8 or 9");
  EdgeError r;
  r.edge = c[0];
  r.poses = count(c[1]);
  r.visits = count(c[2]);
  r.length_m = number(c[3]);
  r.ate_mean_m = number(c[4]);
  r.ate_max_m = number(c[5]);
  r.drift_pct = number(c[6]);
  r.rot_deg_per_m = number(c[7]);
  r.window_drift_pct = c.size() > 8 ? number(c[8]) : std::numeric_limits<double>::quiet_NaN();
  return r;
}

}  // namespace

void writePerEdgeCsv(const std::filesystem::path& path, const std::vector<EdgeError>& rows) {
  std::ostringstream os;
  os.precision(6);
  os << kHeader << '\n';
  for (const auto& r : rows)
    os << r.edge << ',' << r.poses << ',' << r.visits << ',' << r.length_m << ',' << r.ate_mean_m
       << ',' << r.ate_max_m << ',' << r.drift_pct << ',' << r.rot_deg_per_m << ','
       << r.window_drift_pct << '\n';
  writeFileAtomic(path, os.str());
}

std::vector<EdgeError> readPerEdgeCsv(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path.string() + ": cannot open");
  std::string line;
  if (!std::getline(in, line) || line.rfind("sumo_edge,", 0) != 0)
    throw std::runtime_error(path.string() + ": not a per_edge.csv (header sumo_edge,...)");
  std::vector<EdgeError> out;
  for (int lineno = 2; std::getline(in, line); ++lineno) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    try {
      out.push_back(parseRow(fields(line)));
    } catch (const std::runtime_error& e) {
      throw std::runtime_error(path.string() + ":" + std::to_string(lineno) + ": " + e.what());
    }
  }
  return out;
}

}  // namespace slamroute::evaluate
