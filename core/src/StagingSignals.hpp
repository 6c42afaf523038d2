#pragma once
// Internal to StagingDir: staging folders removed when the process is stopped by SIGINT, SIGTERM
// or SIGHUP (Ctrl-C, a job scheduler, a closed terminal, a pipeline parent that died), so a
// stopped drive does not leave tens of MB in a hidden folder until its --out is used again.
#include <string>

namespace slamroute::detail {

/// Removes `dir` (recursively) if one of those signals arrives before unwatchOnSignal(dir); then
/// the signal takes its default action. Installs the handlers on first use, only for signals
/// whose handling nobody else has set. At most 16 folders at once; more are not watched.
void removeOnSignal(const std::string& dir);
void unwatchOnSignal(const std::string& dir);

}  // namespace slamroute::detail
