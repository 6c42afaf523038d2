#include "slamroute/pipeline/Resume.hpp"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <stdexcept>

#include "slamroute/core/AtomicFile.hpp"
#include "slamroute/core/Log.hpp"

namespace slamroute::pipeline {
namespace fs = std::filesystem;

namespace {

constexpr std::uint64_t kMul = 0x9E3779B97F4A7C15ull;

std::uint64_t mix(std::uint64_t h, std::uint64_t w) {
  h ^= w;
  h *= kMul;
  return h ^ (h >> 29);
}

std::uint64_t mixString(std::uint64_t h, const std::string& s) {
  for (unsigned char c : s) h = mix(h, c);
  return mix(h, s.size());
}

std::string hex(std::uint64_t h) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

}  // namespace

std::uint64_t fileHash(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error(file.string() + ": cannot be read");
  std::uint64_t h = 0x243F6A8885A308D3ull;
  std::vector<char> buf(1 << 20);
  std::uint64_t total = 0;
  while (in.read(buf.data(), static_cast<std::streamsize>(buf.size())) || in.gcount() > 0) {
    const std::size_t n = static_cast<std::size_t>(in.gcount());
    std::size_t i = 0;
    for (; i + 8 <= n; i += 8) {
      std::uint64_t w;
      std::memcpy(&w, buf.data() + i, 8);
      h = mix(h, w);
    }
    for (; i < n; ++i) h = mix(h, static_cast<unsigned char>(buf[i]));
    total += n;
  }
  if (in.bad()) throw std::runtime_error(file.string() + ": read error");
  return mix(h, total);
}

std::uint64_t folderHash(const fs::path& dir) {
  std::vector<fs::path> files;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  std::uint64_t h = 0x13198A2E03707344ull;
  for (const auto& f : files) {
    h = mixString(h, fs::relative(f, dir).generic_string());
    h = mix(h, fileHash(f));
  }
  return mix(h, files.size());
}

std::string stepStamp(const Step& s) {
  // The running program's own bytes: a rebuilt or upgraded slamroute may make other results.
  static const std::string program = hex(fileHash("/proc/self/exe"));
  std::string out = std::string("slamroute ") + SLAMROUTE_VERSION + "\nprogram " + program + "\n";
  for (std::size_t i = 0; i < s.args.size(); ++i) {
    const std::string& a = s.args[i];
    if ((a == "--log-level" || a == "--out") && i + 1 < s.args.size()) {
      ++i;  // how much a step prints, and where its output goes, do not change what it makes
      out += "arg " + a + "\n";
      continue;
    }
    // An input is known by its content, not its path: a run folder copied or moved elsewhere
    // (with its logs/) can still be resumed. Run and experiment pass absolute paths.
    std::error_code ec;
    const auto st = a.empty() || a[0] != '/' ? fs::file_status{} : fs::status(a, ec);
    if (!ec && fs::is_regular_file(st))
      out += "file " + hex(fileHash(a)) + "\n";
    else if (!ec && fs::is_directory(st))
      out += "folder " + hex(folderHash(a)) + "\n";
    else
      out += "arg " + a + "\n";
  }
  return out;
}

std::vector<Step> stepsToRun(std::vector<Step> steps, bool resume) {
  std::vector<Step> left;
  for (auto& st : steps) {
    st.stamp = stepStamp(st);
    if (resume && !st.output.empty() && fs::exists(st.output)) {
      const fs::path stamp = stampPath(st);
      if (!fs::exists(stamp)) {
        // A step stopped while running (its stamp is removed when it starts) or an orphan that
        // finished after its run was killed: what it was made from is unknown.
        logInfo("  again    " + st.label + ": no record of what " + st.output.string() +
                " was made from (" + stamp.string() + ")");
      } else if (readFile(stamp) == st.stamp) {
        logInfo("  kept     " + st.label + " (" + st.output.string() + ")");
        continue;
      } else {
        logInfo("  again    " + st.label + ": its settings or inputs changed since " +
                stamp.string());
      }
    }
    left.push_back(std::move(st));
  }
  return left;
}

}  // namespace slamroute::pipeline
