#include "cyclone/core/AtomicFile.hpp"

#include <cstdio>
#include <filesystem>
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

}  // namespace cyclone
