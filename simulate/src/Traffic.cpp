#include "slamroute/simulate/Traffic.hpp"

#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "slamroute/core/AtomicFile.hpp"

namespace slamroute::simulate {

void writeTrafficCsv(const std::filesystem::path& path, const TrafficFrames& frames,
                     const std::vector<double>& times) {
  if (times.size() != frames.size())
    throw std::invalid_argument("writeTrafficCsv " + path.string() + ": " +
                                std::to_string(frames.size()) + " frames but " +
                                std::to_string(times.size()) + " times");
  std::string out = "frame,t,id,x,y,z,heading_deg,length,width,height\n";
  char line[512];
  for (std::size_t f = 0; f < frames.size(); ++f)
    for (const auto& b : frames[f]) {
      if (b.id.find_first_of(",\n") != std::string::npos)
        throw std::invalid_argument("writeTrafficCsv: vehicle id '" + b.id + "' contains a comma");
      std::snprintf(line, sizeof line, "%zu,%.3f,%s,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f\n", f,
                    times[f], b.id.c_str(), b.x, b.y, b.z, b.heading_deg, b.length, b.width,
                    b.height);
      out += line;
    }
  writeFileAtomic(path, out);
}

TrafficFrames readTrafficCsv(const std::filesystem::path& path, std::size_t min_frames) {
  const std::string text = readFile(path);
  std::istringstream in(text);
  std::string line;
  TrafficFrames frames(min_frames);
  std::size_t lineno = 0;
  while (std::getline(in, line)) {
    ++lineno;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line[0] == '#' || (lineno == 1 && line.rfind("frame", 0) == 0)) continue;
    std::vector<std::string> f;
    std::stringstream ss(line);
    std::string tok;
    while (std::getline(ss, tok, ',')) f.push_back(tok);
    auto bad = [&](const std::string& why) {
      throw std::runtime_error(path.string() + ":" + std::to_string(lineno) + ": " + why);
    };
    if (f.size() != 10)
      bad("expected 10 columns (frame,t,id,x,y,z,heading_deg,length,width,height)");
    VehicleBox b;
    std::size_t frame = 0;
    try {
      const long fr = std::stol(f[0]);
      if (fr < 0) bad("negative frame");
      frame = static_cast<std::size_t>(fr);
      b.id = f[2];
      b.x = std::stod(f[3]);
      b.y = std::stod(f[4]);
      b.z = std::stod(f[5]);
      b.heading_deg = std::stod(f[6]);
      b.length = std::stod(f[7]);
      b.width = std::stod(f[8]);
      b.height = std::stod(f[9]);
    } catch (const std::logic_error&) {
      bad("not a number");
    }
    if (frame > 10000000) bad("frame index too large");
    if (frames.size() <= frame) frames.resize(frame + 1);
    frames[frame].push_back(b);
  }
  return frames;
}

}  // namespace slamroute::simulate
