#include "slamroute/core/AtomicFile.hpp"

#include <zlib.h>

#include <atomic>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

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
    if (ec) throw std::runtime_error(path.string() + ": cannot create folder (" + ec.message() + ")");
  }
}

}  // namespace

void writeFileAtomic(const fs::path& path, const std::string& content) {
  AtomicOutput out(path, true);
  out.stream().write(content.data(), static_cast<std::streamsize>(content.size()));
  out.commit();
}

AtomicOutput::AtomicOutput(fs::path path, bool binary) : path_(std::move(path)) {
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

std::string readFile(const fs::path& path) {
  std::error_code ec;
  if (!fs::exists(path, ec)) throw std::runtime_error(path.string() + ": file not found");
  if (fs::is_directory(path, ec)) throw std::runtime_error(path.string() + ": is a folder, not a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path.string() + ": cannot open for reading");
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string readMaybeGzip(const fs::path& path) {
  std::string raw = readFile(path);
  const bool gz = raw.size() >= 2 && static_cast<unsigned char>(raw[0]) == 0x1f &&
                  static_cast<unsigned char>(raw[1]) == 0x8b;
  if (!gz) {
    if (path.extension() == ".gz")
      throw std::runtime_error(path.string() + ": not a gzip file despite the .gz name");
    return raw;
  }
  z_stream zs{};
  if (inflateInit2(&zs, 15 + 32) != Z_OK) throw std::runtime_error(path.string() + ": zlib init failed");
  zs.next_in = reinterpret_cast<Bytef*>(raw.data());
  zs.avail_in = static_cast<uInt>(raw.size());
  std::string out;
  char buf[1 << 16];
  int ret = Z_OK;
  while (ret != Z_STREAM_END) {
    zs.next_out = reinterpret_cast<Bytef*>(buf);
    zs.avail_out = sizeof(buf);
    ret = inflate(&zs, Z_NO_FLUSH);
    if (ret != Z_OK && ret != Z_STREAM_END) {
      inflateEnd(&zs);
      throw std::runtime_error(path.string() + ": corrupt gzip data");
    }
    out.append(buf, sizeof(buf) - zs.avail_out);
    if (ret == Z_OK && zs.avail_in == 0 && zs.avail_out != 0) {
      inflateEnd(&zs);
      throw std::runtime_error(path.string() + ": truncated gzip file");
    }
  }
  inflateEnd(&zs);
  return out;
}

}  // namespace slamroute
