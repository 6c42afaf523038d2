#pragma once
// report.html as one self-contained file: the vendored Leaflet (CSS and JS), the page's own
// script and style (export/web/) and the report's data, all inlined, so that it opens offline
// from file:// with nothing fetched.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

namespace slamroute::cli {

/// Where the page's parts are: the vendored library (build/vendor/..., scripts/vendor_js.sh)
/// and the page's own files.
struct HtmlParts {
  std::filesystem::path vendor_dir;  ///< holds leaflet.js and leaflet.css
  std::filesystem::path web_dir;     ///< holds report.js and report.css
  static HtmlParts installed();      ///< the paths this build was configured with
  /// "" when every part is there, else which one is missing and how to get it.
  std::string missing() const;
};

/// The whole page. Throws std::runtime_error naming a missing part.
std::string selfContainedPage(const std::string& title, const nlohmann::json& data,
                              const HtmlParts& parts);

}  // namespace slamroute::cli
