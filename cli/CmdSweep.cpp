// `slamroute sweep SPEC.yaml --out DIR`: a study of nets x planners x seeds x config variants as
// one task graph (pipeline/Sweep.hpp). Under `mpirun -n N` or `srun -n N` rank 0 schedules and
// every rank runs tasks; started directly it runs them here, --jobs at once.
#include <cstring>
#include <filesystem>

#include "Commands.hpp"
#include "Pipeline.hpp"
#include "slamroute/core/Log.hpp"
#include "slamroute/pipeline/Subprocess.hpp"
#include "slamroute/pipeline/Sweep.hpp"
#include "slamroute/pipeline/SweepResults.hpp"

namespace slamroute::cli {
namespace fs = std::filesystem;

namespace {

struct SweepOpts {
  std::string spec, out;
  pipeline::SweepOptions run;
};

std::string commandLine(const Context& ctx, const SweepOpts& o, int ranks) {
  return (ranks > 1 ? "mpirun -n " + std::to_string(ranks) + " " : std::string()) +
         "slamroute --seed " + std::to_string(ctx.cfg.seed) +
         (ctx.config_file.empty() ? "" : " --config " + ctx.config_file) + " sweep " + o.spec +
         " --out " + o.out + " --jobs " + std::to_string(o.run.jobs_per_rank) +
         (o.run.resume ? " --resume" : "");
}

/// Rank 0: the study's tasks run to the end, then its results; throws when tasks failed.
void scheduleStudy(Context& ctx, const SweepOpts& o, pipeline::Cluster& cluster,
                   const fs::path& out) {
  const pipeline::SweepSpec spec = pipeline::SweepSpec::readYaml(o.spec);  // before DIR exists
  const auto rows = spec.expand();
  fs::create_directories(out);
  auto tasks = pipeline::sweepTasks(spec, rows, out, childOptions(ctx));
  logInfo("sweep: " + std::to_string(rows.size()) + " runs, " + std::to_string(tasks.size()) +
          " tasks on " + std::to_string(cluster.size()) + " rank(s), " +
          std::to_string(o.run.jobs_per_rank) + " at once each");
  const pipeline::SweepOutcome outcome = pipeline::scheduleSweep(cluster, std::move(tasks), o.run);
  pipeline::writeSweepResults(pipeline::collectResults(rows, outcome, out), outcome, out,
                              commandLine(ctx, o, cluster.size()));
  logInfo("results: " + (out / "results.csv").string() + ", " + (out / "summary.md").string());
  std::size_t failed = 0;
  for (const auto& s : outcome.status) failed += s.state != pipeline::TaskState::Done;
  if (outcome.interrupted_by != 0)
    throw pipeline::Interrupted(outcome.interrupted_by,
                                std::string("sweep interrupted by ") +
                                    strsignal(outcome.interrupted_by) + "; " +
                                    std::to_string(failed) +
                                    " task(s) not finished (--resume "
                                    "continues from the tasks that finished)");
  if (failed > 0)
    throw std::runtime_error("sweep: " + std::to_string(failed) + " task(s) failed or not run (" +
                             (out / "failed_tasks.txt").string() + ")");
}

void runSweep(Context& ctx, const SweepOpts& o) {
  ctx.load();
  const fs::path out = fs::weakly_canonical(fs::absolute(o.out));
  const auto cluster = pipeline::joinCluster();
  if (cluster->rank() > 0) return pipeline::serveSweep(*cluster, out, o.run);
  try {
    scheduleStudy(ctx, o, *cluster, out);
  } catch (...) {
    for (int r = 1; r < cluster->size(); ++r) cluster->send(r, pipeline::Tag::Stop, "");
    throw;
  }
}

}  // namespace

void registerSweep(CLI::App& app, Context& ctx) {
  auto o = std::make_shared<SweepOpts>();
  auto* sub = app.add_subcommand(
      "sweep", "A study (nets x planners x seeds x configs) over MPI ranks or --jobs");
  sub->add_option("spec", o->spec, "study spec (YAML: nets, planners, seeds, variants, rows)")
      ->required()
      ->check(CLI::ExistingFile);
  sub->add_option("--out", o->out, "output folder (shared by every rank)")->required();
  sub->add_option("--jobs", o->run.jobs_per_rank, "tasks each rank runs at once")
      ->capture_default_str()
      ->check(CLI::Range(1, 64));
  sub->add_flag("--resume", o->run.resume,
                "keep the tasks already done in --out from the same seed, config, net and inputs");
  sub->add_option("--worker-timeout", o->run.worker_timeout_s,
                  "seconds of silence after which a rank is taken for dead and its tasks re-queued")
      ->capture_default_str()
      ->check(CLI::Range(2.0, 86400.0));
  sub->callback([&ctx, o] { runSweep(ctx, *o); });
}

}  // namespace slamroute::cli
