// `slamroute survey`. Not built yet: the owning module's issue replaces this file.
#include "Commands.hpp"

namespace slamroute::cli {

void registerSurvey(CLI::App& app, Context& ctx) {
  auto* sub = app.add_subcommand("survey", "Drive vehicles over a net in SUMO, record traces and depth frames");
  sub->allow_extras();
  sub->callback([&ctx] {
    ctx.load();
    throw NotImplemented("survey: not implemented yet");
  });
}

}  // namespace slamroute::cli
