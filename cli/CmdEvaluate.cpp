// `slamroute evaluate`. Not built yet: the owning module's issue replaces this file.
#include "Commands.hpp"

namespace slamroute::cli {

void registerEvaluate(CLI::App& app, Context& ctx) {
  auto* sub = app.add_subcommand("evaluate", "Run LiDAR SLAM on a drive and measure the error (paper 3.3)");
  sub->allow_extras();
  sub->callback([&ctx] {
    ctx.load();
    throw NotImplemented("evaluate: not implemented yet");
  });
}

}  // namespace slamroute::cli
