#include "Report.hpp"

#include "ReportFleet.hpp"
#include "ReportSections.hpp"
#include "slamroute/core/AtomicFile.hpp"
#include "slamroute/core/FleetDrive.hpp"
#include "slamroute/core/SumoNet.hpp"
#include "slamroute/pipeline/JsonFile.hpp"
#include "slamroute/simulate/Drive.hpp"

namespace slamroute::cli {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

/// The world `drive` was driven in, when it wrote a world.yaml.
bool loadDriveWorld(const fs::path& drive, std::optional<simulate::World>& world) {
  if (!fs::exists(drive / "world.yaml")) return false;
  const simulate::DriveWorldFile wf = simulate::readDriveWorldFile(drive);
  world.emplace(simulate::World::build(SumoNet::read(wf.net), wf.world, wf.seed));
  return true;
}

/// The world of the first drive of `in.planners` that wrote a world.yaml, else the fleet's
/// first vehicle's (all drives of a run share the net, world config and seed).
void loadFirstDriveWorld(const ReportInputs& in, std::optional<simulate::World>& world) {
  for (const auto& p : in.planners)
    if (loadDriveWorld(in.out / "drives" / p, world)) return;
  if (!in.fleet.empty())
    loadDriveWorld(in.out / "drives" / in.fleet / FleetDriveInfo::folderName(0), world);
}

}  // namespace

ReportData::ReportData(const ReportInputs& inputs)
    : in(inputs), pictures(inputs.out / "report"), graph(RoadGraph::readJson(inputs.graph_json)) {
  fs::create_directories(pictures);
  graph_meta = json::parse(graph.metadata_json.empty() ? "{}" : graph.metadata_json);
  survey = pipeline::readJsonIfPresent(in.survey_dir / "survey.json");
  loadFirstDriveWorld(in, world);
  drift = pooledDrift(in.out, in.planners);
}

void writeReport(const ReportInputs& in) {
  const ReportData data(in);
  std::ostringstream md;
  for (const SectionWriter section :
       {writeHeaderSection, writeRoadGraphSection, writeResultsSection, writeUncertaintySection,
        writeCoverageVsPostmanSection, writePlannerPicturesSection, writeFleetPlanSection,
        writeFleetResultsSection, writeWeightVsDriftSection, writeDriftByStreetKindSection,
        writeMapCompletenessSection, writeStepTimesSection})
    section(md, data);
  writeFileAtomic(in.out / "report.md", md.str());
}

}  // namespace slamroute::cli
