#include "Report.hpp"

#include "ReportSections.hpp"
#include "slamroute/core/AtomicFile.hpp"
#include "slamroute/core/SumoNet.hpp"
#include "slamroute/pipeline/JsonFile.hpp"
#include "slamroute/simulate/Drive.hpp"

namespace slamroute::cli {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

/// The world of the first drive of `in.planners` that wrote a world.yaml.
void loadFirstDriveWorld(const ReportInputs& in, std::optional<simulate::World>& world) {
  for (const auto& p : in.planners) {
    const fs::path drive = in.out / "drives" / p;
    if (!fs::exists(drive / "world.yaml")) continue;
    const simulate::DriveWorldFile wf = simulate::readDriveWorldFile(drive);
    world.emplace(simulate::World::build(SumoNet::read(wf.net), wf.world, wf.seed));
    return;
  }
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
        writeCoverageVsPostmanSection, writePlannerPicturesSection, writeWeightVsDriftSection, writeDriftByStreetKindSection,
        writeStepTimesSection})
    section(md, data);
  writeFileAtomic(in.out / "report.md", md.str());
}

}  // namespace slamroute::cli
