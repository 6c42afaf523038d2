#include "HtmlPage.hpp"

#include <stdexcept>

#include "slamroute/core/AtomicFile.hpp"
#include "slamroute/export/RouteFiles.hpp"

namespace slamroute::cli {
namespace fs = std::filesystem;

namespace {

/// Text inside a <script> or <style> element must not close it early.
std::string inlineSafe(std::string text, const std::string& closing) {
  for (auto at = text.find(closing); at != std::string::npos; at = text.find(closing, at + 2))
    text.replace(at, 2, "<\\/");
  return text;
}

/// A bundled library's trailing source-map comment: the map is not shipped, so drop the hint.
std::string withoutSourceMap(std::string js) {
  const auto at = js.rfind("//# sourceMappingURL=");
  if (at != std::string::npos) js.erase(at);
  return js;
}

}  // namespace

HtmlParts HtmlParts::installed() { return {SLAMROUTE_VENDOR_DIR, SLAMROUTE_WEB_DIR}; }

std::string HtmlParts::missing() const {
  for (const fs::path& p : {vendor_dir / "leaflet.js", vendor_dir / "leaflet.css"})
    if (!fs::exists(p))
      return p.string() +
             " is missing: the build vendors it with scripts/vendor_js.sh (needs npm, "
             "which scripts/setup.sh installs)";
  for (const fs::path& p : {web_dir / "report.js", web_dir / "report.css"})
    if (!fs::exists(p)) return p.string() + " is missing";
  return "";
}

std::string selfContainedPage(const std::string& title, const nlohmann::json& data,
                              const HtmlParts& parts) {
  if (const std::string m = parts.missing(); !m.empty()) throw std::runtime_error(m);
  std::string page;
  page +=
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>" +
      exports::xmlEscape(title) + "</title>\n<style>\n" +
      inlineSafe(readFile(parts.vendor_dir / "leaflet.css"), "</") + "\n" +
      inlineSafe(readFile(parts.web_dir / "report.css"), "</") + "\n</style>\n</head>\n";
  page +=
      "<body data-status=\"loading\">\n<noscript>This report needs JavaScript.</noscript>\n"
      "<script type=\"application/json\" id=\"report-data\">" +
      inlineSafe(data.dump(), "</") + "</script>\n<script>\n" +
      inlineSafe(withoutSourceMap(readFile(parts.vendor_dir / "leaflet.js")), "</") +
      "\n</script>\n<script>\n" + inlineSafe(readFile(parts.web_dir / "report.js"), "</") +
      "\n</script>\n</body>\n</html>\n";
  return page;
}

}  // namespace slamroute::cli
