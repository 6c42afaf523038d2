// `slamroute plan`. Not built yet: the owning module's issue replaces this file.
#include "Commands.hpp"

namespace slamroute::cli {

void registerPlan(CLI::App& app, Context& ctx) {
  auto* sub = app.add_subcommand("plan", "Plan a mapping route on a graph or net (paper 3.2)");
  sub->allow_extras();
  sub->callback([&ctx] {
    ctx.load();
    throw NotImplemented("plan: not implemented yet");
  });
}

}  // namespace slamroute::cli
