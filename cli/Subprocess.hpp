#pragma once
// The pipeline's child-process runner (pipeline/Subprocess.hpp), under the names the commands use.
#include "slamroute/pipeline/Subprocess.hpp"

namespace slamroute::cli {
using pipeline::Interrupted;
using pipeline::lastLogLine;
using pipeline::runSteps;
using pipeline::selfExe;
using pipeline::stampPath;
using pipeline::Step;
using pipeline::StepResult;
using pipeline::stopWithParent;
}  // namespace slamroute::cli
