#pragma once
// The pipeline library (pipeline/) as the commands use it: child steps carrying the global
// options of this invocation, and the library's names in this namespace.
#include <filesystem>
#include <string>
#include <vector>

#include "Commands.hpp"
#include "Subprocess.hpp"
#include "slamroute/pipeline/Memory.hpp"
#include "slamroute/pipeline/Steps.hpp"

namespace slamroute::cli {

using pipeline::availableMemoryGb;
using pipeline::makeRouteDrivable;
using pipeline::routeLength;
using pipeline::slamJobsForMemory;
using pipeline::slamJobsThatFit;
using pipeline::slamMemoryGb;

/// The global options of this invocation (seed, config file, log level) for child steps.
pipeline::ChildOptions childOptions(const Context& ctx);

/// A child step `slamroute [--seed S] [--config C] [--log-level L] ARGS…`; `seed` overrides the
/// context's seed when >= 0.
Step childStep(const Context& ctx, const std::string& label, std::vector<std::string> args,
               const std::filesystem::path& log, long long seed = -1);

}  // namespace slamroute::cli
