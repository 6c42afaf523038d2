#include "Pipeline.hpp"

namespace slamroute::cli {
namespace fs = std::filesystem;

pipeline::ChildOptions childOptions(const Context& ctx) {
  pipeline::ChildOptions o;
  o.seed = ctx.cfg.seed;
  o.debug_log = ctx.log_level == "debug";
  if (!ctx.config_file.empty())
    o.config_file = fs::weakly_canonical(fs::absolute(ctx.config_file)).string();
  return o;
}

Step childStep(const Context& ctx, const std::string& label, std::vector<std::string> args,
               const fs::path& log, long long seed) {
  return pipeline::childStep(childOptions(ctx), label, std::move(args), log, seed);
}

}  // namespace slamroute::cli
