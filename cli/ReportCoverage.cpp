// report.md: aco-ga against postman, the two routes that cover every street, on the targets of
// complete coverage with an accurate map (docs/RESULTS.md): length in SUMO at most 1.2 x the
// postman's, ATE at least 30 % below it, every drivable directed edge driven.
#include <algorithm>

#include "ReportSections.hpp"
#include "slamroute/pipeline/JsonFile.hpp"

namespace slamroute::cli {
using nlohmann::json;

namespace {

/// a[field] / p[field] with 3 decimals; "–" when either is missing or p's is not positive.
std::string ratio(const json& a, const json& p, const std::string& field) {
  if (!a.contains(field) || !p.contains(field) || !a[field].is_number() || !p[field].is_number() ||
      p[field].get<double>() <= 0)
    return "–";
  return reportNumber(a[field].get<double>() / p[field].get<double>(), 3);
}

json member(const json& j, const std::string& key) { return j.value(key, json::object()); }

}  // namespace

void writeCoverageVsPostmanSection(std::ostringstream& md, const ReportData& data) {
  const auto& ps = data.in.planners;
  if (std::find(ps.begin(), ps.end(), "aco-ga") == ps.end() ||
      std::find(ps.begin(), ps.end(), "postman") == ps.end())
    return;
  const json ar = pipeline::readJsonIfPresent(data.in.out / "routes" / "aco-ga.json");
  const json pr = pipeline::readJsonIfPresent(data.in.out / "routes" / "postman.json");
  const json am = pipeline::readJsonIfPresent(data.in.out / "eval" / "aco-ga" / "metrics.json");
  const json pm = pipeline::readJsonIfPresent(data.in.out / "eval" / "postman" / "metrics.json");
  md << "aco-ga against postman (targets: length <= 1.2 x, ATE >= 30 % lower, every drivable "
        "directed edge):\n\n| length in SUMO / postman | ATE RMSE / postman | directed SUMO edges "
        "driven, aco-ga / postman [%] |\n|---|---|---|\n| "
     << ratio(member(ar, "sumo_length"), member(pr, "sumo_length"), "total_m") << " | "
     << ratio(am, pm, "ate_rmse_m") << " | "
     << reportNumber(member(am, "directed_coverage"), "edges_pct", 1) << " / "
     << reportNumber(member(pm, "directed_coverage"), "edges_pct", 1) << " |\n\n";
}

}  // namespace slamroute::cli
