// `slamroute run`. Not built yet: the owning module's issue replaces this file.
#include "Commands.hpp"

namespace slamroute::cli {

void registerRun(CLI::App& app, Context& ctx) {
  auto* sub = app.add_subcommand("run", "The whole pipeline on a net (default: the shipped city)");
  sub->allow_extras();
  sub->callback([&ctx] {
    ctx.load();
    throw NotImplemented("run: not implemented yet");
  });
}

}  // namespace slamroute::cli
