#pragma once
// report.html in a real headless browser (Debian's chromium) for the CLI tests: the DOM after the
// page's scripts ran and the browser's log, with every network request sent to a dead proxy.
#include <cstdlib>
#include <filesystem>
#include <regex>
#include <string>

#include "slamroute/core/AtomicFile.hpp"

namespace slamroute::test {

inline bool haveChromium() { return std::system("command -v chromium > /dev/null 2>&1") == 0; }

struct Browser {
  std::string dom, log;
};

/// Opens `page` in headless Chromium with every network request sent to a dead proxy (so a page
/// that fetched anything would log the failure); returns the DOM after the scripts ran and the
/// browser's log. With `screenshot`, also writes a PNG of the page; `fragment` ("#fleet") is
/// appended to the page's URL.
inline Browser openInChromium(const std::filesystem::path& page, const std::filesystem::path& work,
                              const std::filesystem::path& screenshot = {},
                              const std::string& fragment = "") {
  const std::string common =
      "chromium --headless --disable-gpu --no-sandbox --no-first-run "
      "--proxy-server=127.0.0.1:9 --window-size=1400,1000 "
      "--virtual-time-budget=8000 --enable-logging=stderr --v=0 --user-data-dir=" +
      (work / "profile").string() + " ";
  const std::string url = "'file://" + std::filesystem::absolute(page).string() + fragment + "'";
  std::system((common + "--dump-dom " + url + " > " + (work / "dom.html").string() + " 2> " +
               (work / "chromium.log").string())
                  .c_str());
  if (!screenshot.empty())
    std::system((common + "--screenshot=" + screenshot.string() + " " + url + " > /dev/null 2>> " +
                 (work / "chromium.log").string())
                    .c_str());
  return {readFile(work / "dom.html"), readFile(work / "chromium.log")};
}

inline std::string bodyAttr(const std::string& dom, const std::string& name) {
  const std::regex re("<body[^>]*\\s" + name + "=\"([^\"]*)\"");
  std::smatch m;
  return std::regex_search(dom, m, re) ? m[1].str() : std::string("(absent)");
}

}  // namespace slamroute::test
