// `slamroute compare`. Not built yet: the owning module's issue replaces this file.
#include "Commands.hpp"

namespace slamroute::cli {

void registerCompare(CLI::App& app, Context& ctx) {
  auto* sub = app.add_subcommand("compare", "Trajectory metrics (ATE/RPE) between an estimate and ground truth");
  sub->allow_extras();
  sub->callback([&ctx] {
    ctx.load();
    throw NotImplemented("compare: not implemented yet");
  });
}

}  // namespace slamroute::cli
