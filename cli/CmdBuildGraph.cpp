// `slamroute build-graph`. Not built yet: the owning module's issue replaces this file.
#include "Commands.hpp"

namespace slamroute::cli {

void registerBuildGraph(CLI::App& app, Context& ctx) {
  auto* sub = app.add_subcommand("build-graph", "Build the road graph from a survey (paper 3.1)");
  sub->allow_extras();
  sub->callback([&ctx] {
    ctx.load();
    throw NotImplemented("build-graph: not implemented yet");
  });
}

}  // namespace slamroute::cli
