#pragma once
// The resume stamps of pipeline steps (pipeline/Resume.hpp), under the names the commands use.
#include "Subprocess.hpp"
#include "slamroute/pipeline/Resume.hpp"

namespace slamroute::cli {
using pipeline::fileHash;
using pipeline::folderHash;
using pipeline::stepStamp;
using pipeline::stepsToRun;
}  // namespace slamroute::cli
