// `slamroute drive`. Not built yet: the owning module's issue replaces this file.
#include "Commands.hpp"

namespace slamroute::cli {

void registerDrive(CLI::App& app, Context& ctx) {
  auto* sub = app.add_subcommand("drive", "Drive a route in SUMO with traffic and simulate the LiDAR");
  sub->allow_extras();
  sub->callback([&ctx] {
    ctx.load();
    throw NotImplemented("drive: not implemented yet");
  });
}

}  // namespace slamroute::cli
