#include "slamroute/core/AtomicFile.hpp"

#include <zlib.h>

#include <unistd.h>
#include <atomic>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace slamroute {
namespace fs = std::filesystem;
namespace {

fs::path tempBeside(const fs::path& path) {
  static std::atomic<unsigned> counter{0};
  const fs::path dir = path.has_parent_path() ? path.parent_path() : fs::path(".");
  return dir / ("." + path.filename().string() + ".tmp." + std::to_string(::getpid()) + "." +
                std::to_string(counter++));
}

void ensureParent(const fs::path& path) {
  if (path.has_parent_path() && !path.parent_path().empty()) {
    std::error_code ec;
    fs::create_directories(path.parent_path(), ec);
    if (ec)
      throw std::runtime_error(path.string() + ": cannot create folder (" + ec.message() + ")");
  }
}

}  // namespace

void writeFileAtomic(const fs::path& path, const std::string& content) {
  AtomicOutput out(path, true);
  out.stream().write(content.data(), static_cast<std::streamsize>(content.size()));
  out.commit();
}

void requireFileTarget(const fs::path& path) {
  std::error_code ec;
  if (fs::is_directory(path, ec))
    throw std::runtime_error(path.string() + ": is a folder; give a file name to write");
}

AtomicOutput::AtomicOutput(fs::path path, bool binary) : path_(std::move(path)) {
  requireFileTarget(path_);
  ensureParent(path_);
  tmp_ = tempBeside(path_);
  out_.open(tmp_, binary ? std::ios::binary | std::ios::out : std::ios::out);
  if (!out_) throw std::runtime_error(path_.string() + ": cannot open for writing");
}

AtomicOutput::~AtomicOutput() {
  if (!committed_) {
    out_.close();
    std::error_code ec;
    fs::remove(tmp_, ec);
  }
}

void AtomicOutput::commit() {
  out_.flush();
  if (!out_) throw std::runtime_error(path_.string() + ": write failed (disk full?)");
  out_.close();
  std::error_code ec;
  fs::rename(tmp_, path_, ec);
  if (ec) {
    fs::remove(tmp_, ec);
    throw std::runtime_error(path_.string() + ": cannot move into place (" + ec.message() + ")");
  }
  committed_ = true;
}

fs::path AtomicFileSet::staged(const fs::path& target) {
  requireFileTarget(target);
  ensureParent(target);
  static std::atomic<unsigned> counter{0};
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  const fs::path tmp = dir / (".tmp." + std::to_string(::getpid()) + "." +
                              std::to_string(counter++) + "." + target.filename().string());
  staged_.emplace_back(tmp, target);
  return tmp;
}

void AtomicFileSet::dropAtCommit(const fs::path& target) { dropped_.push_back(target); }

void AtomicFileSet::commit() {
  std::error_code ec;
  for (const auto& [tmp, target] : staged_)
    if (!fs::is_regular_file(tmp, ec))
      throw std::runtime_error(target.string() + ": was not written");
  for (const auto& [tmp, target] : staged_) {
    fs::rename(tmp, target, ec);
    if (ec)
      throw std::runtime_error(target.string() + ": cannot move into place (" + ec.message() + ")");
  }
  for (const auto& target : dropped_) fs::remove(target, ec);
  committed_ = true;
}

AtomicFileSet::~AtomicFileSet() {
  if (committed_) return;
  std::error_code ec;
  for (const auto& [tmp, target] : staged_) fs::remove(tmp, ec);
}

std::string readFile(const fs::path& path) {
  std::error_code ec;
  if (!fs::exists(path, ec)) throw std::runtime_error(path.string() + ": file not found");
  if (fs::is_directory(path, ec))
    throw std::runtime_error(path.string() + ": is a folder, not a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path.string() + ": cannot open for reading");
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

namespace {

bool startsWithGzipMagic(const unsigned char* p, size_t n) {
  return n >= 2 && p[0] == 0x1f && p[1] == 0x8b;
}

/// Inflates one gzip member starting at zs.next_in into `out`; on return zs.next_in points just
/// past the member.
void inflateMember(z_stream& zs, std::string& out, const fs::path& path) {
  char buf[1 << 16];
  int ret = Z_OK;
  while (ret != Z_STREAM_END) {
    zs.next_out = reinterpret_cast<Bytef*>(buf);
    zs.avail_out = sizeof(buf);
    ret = inflate(&zs, Z_NO_FLUSH);
    const bool inputEnded = zs.avail_in == 0 && zs.avail_out != 0;
    if ((ret == Z_OK && inputEnded) || (ret == Z_BUF_ERROR && zs.avail_in == 0))
      throw std::runtime_error(path.string() + ": truncated gzip file");
    if (ret != Z_OK && ret != Z_STREAM_END)
      throw std::runtime_error(path.string() + ": corrupt gzip data");
    out.append(buf, sizeof(buf) - zs.avail_out);
  }
}

/// gzip files may hold several members one after another (`cat a.gz b.gz`, archives written in
/// chunks); gzip, SUMO and Python read them all as one text, so every member is inflated.
/// Zero bytes after the last member are padding (tar-style blocks) and are ignored like gzip does.
std::string gunzipAllMembers(std::string& raw, const fs::path& path) {
  z_stream zs{};
  if (inflateInit2(&zs, 15 + 16) != Z_OK)
    throw std::runtime_error(path.string() + ": zlib init failed");
  zs.next_in = reinterpret_cast<Bytef*>(raw.data());
  zs.avail_in = static_cast<uInt>(raw.size());
  std::string out;
  try {
    inflateMember(zs, out, path);
    while (startsWithGzipMagic(zs.next_in, zs.avail_in)) {
      inflateReset(&zs);
      inflateMember(zs, out, path);
    }
    const auto* rest = zs.next_in;
    for (uInt i = 0; i < zs.avail_in; ++i)
      if (rest[i] != 0)
        throw std::runtime_error(path.string() + ": data after the end of the gzip stream");
  } catch (...) {
    inflateEnd(&zs);
    throw;
  }
  inflateEnd(&zs);
  return out;
}

}  // namespace

std::string readMaybeGzip(const fs::path& path) {
  std::string raw = readFile(path);
  if (!startsWithGzipMagic(reinterpret_cast<const unsigned char*>(raw.data()), raw.size())) {
    if (path.extension() == ".gz")
      throw std::runtime_error(path.string() + ": not a gzip file despite the .gz name");
    return raw;
  }
  if (raw.size() > std::numeric_limits<uInt>::max())
    throw std::runtime_error(path.string() + ": compressed file larger than 4 GB");
  return gunzipAllMembers(raw, path);
}

}  // namespace slamroute
