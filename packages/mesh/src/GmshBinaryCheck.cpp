#include "GmshBinaryCheck.hpp"

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "cyclone/core/Error.hpp"

namespace cyclone::mesh::detail {

namespace {

// Sequential reads with the bytes left always known.
class Reader {
public:
  explicit Reader(const std::string& path)
      : path_(path), in_(path, std::ios::binary), size_(std::uintmax_t(std::filesystem::file_size(path))) {}

  std::uintmax_t left() const { return size_ - pos_; }
  std::uintmax_t offset() const { return pos_; }

  std::string line() {
    std::string s;
    char c;
    while (pos_ < size_ && in_.get(c)) {
      ++pos_;
      if (c == '\n') break;
      s.push_back(c);
      if (s.size() > 4096) fail("a header line longer than 4096 bytes");
    }
    if (!s.empty() && s.back() == '\r') s.pop_back();
    return s;
  }
  template <class T>
  T value(const char* what) {
    if (left() < sizeof(T)) fail(std::string("the file ends inside ") + what);
    T v;
    in_.read(reinterpret_cast<char*>(&v), sizeof(T));
    pos_ += sizeof(T);
    return v;
  }
  // A count of records of at least `bytesEach` bytes: must fit in what is left.
  std::uint64_t count(const char* what, std::uintmax_t bytesEach) {
    const auto n = value<std::uint64_t>(what);
    if (bytesEach > 0 && n > left() / bytesEach) {
      std::ostringstream msg;
      msg << what << " at byte " << pos_ - 8 << " is " << n << ", which needs at least " << bytesEach
          << " bytes each, but the file has " << left()
          << " bytes left: the file is damaged (or not gmsh's binary format 4.1)";
      fail(msg.str());
    }
    return n;
  }
  void skip(std::uintmax_t bytes, const char* what) {
    if (bytes > left()) fail(std::string("the file ends inside ") + what);
    in_.seekg(std::streamoff(bytes), std::ios::cur);
    pos_ += bytes;
  }
  // Past the line "$End<name>", whatever the section holds.
  void skipSection(const std::string& name) {
    const std::string end = "$End" + name;
    std::string window;
    char c;
    while (pos_ < size_ && in_.get(c)) {
      ++pos_;
      window.push_back(c);
      if (window.size() > end.size()) window.erase(0, 1);
      if (window == end) return;
    }
    fail("section $" + name + " has no " + end);
  }
  [[noreturn]] void fail(const std::string& why) const { throw InputError(path_, "binary Gmsh file: " + why); }

private:
  std::string path_;
  std::ifstream in_;
  std::uintmax_t size_ = 0, pos_ = 0;
};

void checkEntities(Reader& r) {
  std::uint64_t counts[4];
  const char* names[] = {"the number of points", "the number of curves", "the number of surfaces",
                         "the number of volumes"};
  for (int d = 0; d < 4; ++d) counts[d] = r.count(names[d], 4 + 3 * 8 + 8);
  for (int d = 0; d < 4; ++d)
    for (std::uint64_t i = 0; i < counts[d]; ++i) {
      r.skip(4 + (d == 0 ? 3 : 6) * 8, "an entity");
      r.skip(4 * r.count("an entity's number of physical tags", 4), "physical tags");
      if (d > 0) r.skip(4 * r.count("an entity's number of bounding entities", 4), "bounding entities");
    }
}

void checkNodes(Reader& r) {
  const auto blocks = r.count("the number of node blocks", 3 * 4 + 8);
  r.count("the number of nodes", 8 + 3 * 8);
  r.skip(16, "the node tag range");
  for (std::uint64_t b = 0; b < blocks; ++b) {
    const auto dim = r.value<std::int32_t>("a node block");
    r.skip(4, "a node block");
    const auto parametric = r.value<std::int32_t>("a node block");
    if (dim < 0 || dim > 3) r.fail("a node block of dimension " + std::to_string(dim) + " at byte " + std::to_string(r.offset() - 12));
    const std::uintmax_t coords = 3 + (parametric ? std::uintmax_t(dim) : 0);
    const auto n = r.count("a node block's number of nodes", 8 + 8 * coords);
    r.skip(n * (8 + 8 * coords), "a node block");
  }
}

void checkElements(Reader& r, int (*nodesPerElement)(int)) {
  const auto blocks = r.count("the number of element blocks", 3 * 4 + 8);
  r.count("the number of elements", 2 * 8);
  r.skip(16, "the element tag range");
  for (std::uint64_t b = 0; b < blocks; ++b) {
    r.skip(8, "an element block");
    const auto type = r.value<std::int32_t>("an element block");
    int nodes = 0;
    try {
      nodes = nodesPerElement(type);
    } catch (...) {
      r.fail("an element block of unknown element type " + std::to_string(type) + " at byte " +
             std::to_string(r.offset() - 4));
    }
    const auto n = r.count("an element block's number of elements", 8 * (1 + std::uintmax_t(nodes)));
    r.skip(n * 8 * (1 + std::uintmax_t(nodes)), "an element block");
  }
}

}  // namespace

void checkBinaryMshCounts(const std::string& path, int (*nodesPerElement)(int)) {
  Reader r(path);
  if (r.line() != "$MeshFormat") return;  // not format 2/4 with a header: gmsh says what it is
  std::istringstream version(r.line());
  double v = 0;
  int binary = 0, dataSize = 0;
  version >> v >> binary >> dataSize;
  if (!binary) return;
  if (v < 4.1 || v >= 5) r.fail("version " + std::to_string(v) + " (binary files of version 4.1 are read)");
  if (dataSize != 8) r.fail("data size " + std::to_string(dataSize) + " (8 expected)");
  if (r.value<std::int32_t>("the byte-order mark") != 1) r.fail("byte order other than this machine's");
  r.skipSection("MeshFormat");
  while (r.left() > 0) {
    std::string header = r.line();
    if (header.empty()) continue;
    if (header[0] != '$') r.fail("'" + header.substr(0, 40) + "' where a section starts, at byte " + std::to_string(r.offset()));
    const std::string name = header.substr(1);
    if (name == "Entities") checkEntities(r);
    else if (name == "Nodes") checkNodes(r);
    else if (name == "Elements") checkElements(r, nodesPerElement);
    r.skipSection(name);
  }
}

}  // namespace cyclone::mesh::detail
