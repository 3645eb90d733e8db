#include "cyclone/core/AtomicFile.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "cyclone/core/Error.hpp"

namespace cyclone {

AtomicFile::AtomicFile(std::string finalPath) : final_(std::move(finalPath)) {
  namespace fs = std::filesystem;
  const fs::path p(final_);
  const fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
  if (!fs::is_directory(dir))
    throw InputError(final_, "output directory '" + dir.string() + "' does not exist");
  temp_ = (dir / ("." + p.filename().string() + ".tmp" + std::to_string(::getpid()))).string();
}

AtomicFile::~AtomicFile() {
  if (!committed_) std::remove(temp_.c_str());
}

void AtomicFile::commit() {
  std::error_code ec;
  std::filesystem::rename(temp_, final_, ec);
  if (ec) throw Error("cannot rename " + temp_ + " to " + final_ + ": " + ec.message());
  committed_ = true;
}

void AtomicFile::fail() const {
  const int error = errno;
  throw Error("cannot write " + final_ + ": " + (error ? std::strerror(error) : "the write failed"));
}

void AtomicFile::check(std::ofstream& out) const {
  if (out.is_open()) out.close();
  if (!out) fail();
}

void AtomicFile::write(const char* bytes, std::size_t size) const {
  std::FILE* f = std::fopen(temp_.c_str(), "wb");
  if (!f) fail();
  const bool written = std::fwrite(bytes, 1, size, f) == size;
  const int writeError = errno;
  // fclose flushes what the library still buffers: on a full disk that is where it fails.
  const bool closed = std::fclose(f) == 0;
  if (!written) errno = writeError;
  if (!written || !closed) fail();
}

}  // namespace cyclone
