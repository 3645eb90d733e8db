#include "cyclone/cyclic/ModeShapes.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <map>
#include <mutex>

#include "cyclone/core/Error.hpp"

namespace cyclone::cyclic {

// An open, already unlinked file: its blocks are freed when the descriptor is closed.
// Shared by every store of the process that moved to the same directory; each write
// claims its range at the end under the lock and then writes without it (pwrite).
struct ModeShapes::File {
  int fd = -1;
  std::string directory;
  std::mutex lock;
  std::size_t end = 0;  // bytes claimed so far
  std::size_t claim(std::size_t bytes) {
    const std::lock_guard<std::mutex> guard(lock);
    const std::size_t at = end;
    end += bytes;
    return at;
  }
  ~File() {
    if (fd >= 0) ::close(fd);
  }
};

namespace {

// The whole range through pwrite or pread, which may move fewer bytes than asked.
template <class Bytes, class Transfer>
void transferAll(Transfer transfer, int fd, Bytes* bytes, std::size_t count, std::size_t offset,
                 const char* what, const std::string& directory) {
  std::size_t left = count * sizeof(double), at = 0;
  while (left > 0) {
    const ssize_t n = transfer(fd, bytes + at, left, off_t(offset + at));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0)
      throw Error(std::string("cannot ") + what + " the mode shapes' scratch file in " + directory + ": " +
                  std::strerror(errno));
    left -= std::size_t(n), at += std::size_t(n);
  }
}

void writeAll(int fd, const double* data, std::size_t count, std::size_t offset, const std::string& directory) {
  transferAll(::pwrite, fd, reinterpret_cast<const char*>(data), count, offset, "write", directory);
}

void readAll(int fd, double* data, std::size_t count, std::size_t offset, const std::string& directory) {
  transferAll(::pread, fd, reinterpret_cast<char*>(data), count, offset, "read", directory);
}

}  // namespace

void ModeShapes::push_back(const ModeShape& shape) {
  if (count_ == 0) nodes_ = shape.real.size(), withImag_ = !shape.imag.empty();
  if (shape.real.size() != nodes_ || (!shape.imag.empty() && shape.imag.size() != nodes_) ||
      shape.imag.empty() == withImag_)
    throw Error("ModeShapes: every shape of a nodal diameter has its number of nodes and the same parts");
  std::vector<double> values;
  values.reserve(valuesPerShape());
  for (const auto& node : shape.real) values.insert(values.end(), node.begin(), node.end());
  for (const auto& node : shape.imag) values.insert(values.end(), node.begin(), node.end());
  if (file_) {
    const std::size_t at = file_->claim(values.size() * sizeof(double));
    writeAll(file_->fd, values.data(), values.size(), at, file_->directory);
    offsets_.push_back(at);
  } else {
    memory_.insert(memory_.end(), values.begin(), values.end());
  }
  ++count_;
}

ModeShape ModeShapes::operator[](std::size_t i) const {
  if (i >= count_) throw Error("ModeShapes: shape " + std::to_string(i) + " of " + std::to_string(count_));
  std::vector<double> read;
  const double* values = nullptr;
  if (file_) {
    read.resize(valuesPerShape());
    readAll(file_->fd, read.data(), read.size(), offsets_[i], file_->directory);
    values = read.data();
  } else {
    values = memory_.data() + i * valuesPerShape();
  }
  ModeShape s;
  s.real.resize(nodes_);
  s.imag.assign(nodes_, {0, 0, 0});
  for (std::size_t n = 0; n < nodes_; ++n)
    for (int d = 0; d < 3; ++d) s.real[n][std::size_t(d)] = values[3 * n + std::size_t(d)];
  if (withImag_)
    for (std::size_t n = 0; n < nodes_; ++n)
      for (int d = 0; d < 3; ++d) s.imag[n][std::size_t(d)] = values[3 * nodes_ + 3 * n + std::size_t(d)];
  return s;
}

namespace {

// The process's scratch file in a directory, made when no store holds one there.
std::shared_ptr<ModeShapes::File> scratchFileIn(const std::string& directory) {
  static std::mutex lock;
  static std::map<std::string, std::weak_ptr<ModeShapes::File>> files;
  const std::lock_guard<std::mutex> guard(lock);
  auto& slot = files[directory];
  if (auto file = slot.lock()) return file;
  auto file = std::make_shared<ModeShapes::File>();
  file->directory = directory;
  std::string path = directory + "/cyclone-mode-shapes-XXXXXX";
  file->fd = ::mkstemp(path.data());
  if (file->fd < 0)
    throw Error("cannot create a scratch file for mode shapes in " + directory + ": " + std::strerror(errno));
  ::unlink(path.c_str());  // nameless from now on: gone with the descriptor, also after a crash
  slot = file;
  return file;
}

}  // namespace

void ModeShapes::moveToScratchFile(const std::string& directory) {
  if (file_) return;
  auto file = scratchFileIn(directory.empty() ? std::string(".") : directory);
  const std::size_t bytes = valuesPerShape() * sizeof(double);
  std::vector<std::size_t> offsets;
  for (std::size_t i = 0; i < count_; ++i) {
    const std::size_t at = file->claim(bytes);
    writeAll(file->fd, memory_.data() + i * valuesPerShape(), valuesPerShape(), at, file->directory);
    offsets.push_back(at);
  }
  file_ = std::move(file);
  offsets_ = std::move(offsets);
  std::vector<double>().swap(memory_);
}

}  // namespace cyclone::cyclic
