#include "GmshCountsCheck.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <vector>

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
  template <class T>
  void values(T* to, std::size_t n, const char* what) {
    if (n * sizeof(T) > left()) fail(std::string("the file ends inside ") + what);
    in_.read(reinterpret_cast<char*>(to), std::streamsize(n * sizeof(T)));
    pos_ += n * sizeof(T);
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

struct TagRange {
  std::uint64_t min = 0, max = 0;
  bool known = false;
};

void checkNodes(Reader& r, TagRange& tags) {
  const auto blocks = r.count("the number of node blocks", 3 * 4 + 8);
  r.count("the number of nodes", 8 + 3 * 8);
  tags.min = r.value<std::uint64_t>("the node tag range");
  tags.max = r.value<std::uint64_t>("the node tag range");
  tags.known = true;
  // gmsh 4.8 keeps node tags as int: a larger one wraps around and reads as another node.
  if (tags.max > std::uint64_t(std::numeric_limits<std::int32_t>::max()))
    r.fail("node tags up to " + std::to_string(tags.max) + ": gmsh reads tags up to 2147483647");
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

void checkElements(Reader& r, int (*nodesPerElement)(int), const TagRange& tags) {
  const auto blocks = r.count("the number of element blocks", 3 * 4 + 8);
  r.count("the number of elements", 2 * 8);
  r.skip(16, "the element tag range");
  if (!tags.known) r.fail("$Elements before $Nodes");
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
    // Every node tag within the nodes' range: gmsh 4.8 does not check it, and crashed
    // (SIGSEGV) or took another node (found by fuzz_readers).
    std::vector<std::uint64_t> element(std::size_t(nodes) + 1);
    for (std::uint64_t e = 0; e < n; ++e) {
      r.values(element.data(), element.size(), "an element block");
      for (int k = 1; k <= nodes; ++k)
        if (element[std::size_t(k)] < tags.min || element[std::size_t(k)] > tags.max)
          r.fail("element " + std::to_string(element[0]) + " names node " + std::to_string(element[std::size_t(k)]) +
                 ", outside the nodes' tags " + std::to_string(tags.min) + ".." + std::to_string(tags.max) +
                 " (byte " + std::to_string(r.offset()) + "): the file is damaged");
    }
  }
}

// An ASCII file's counts: each must fit in the file's bytes at the fewest bytes a record
// can take in text (a node: its tag and three coordinates, "1\n0 0 0\n"; an element: its
// tag and one node, "1 1\n"). gmsh 4.8's ASCII reader reserves what a count says too:
// a 400-byte file whose node count read 4e9 took 15.6 GB, then read as the mesh it was.
void checkAsciiCounts(const std::string& path, double version) {
  const std::uintmax_t size = std::uintmax_t(std::filesystem::file_size(path));
  std::ifstream in(path);
  std::string line;
  std::uintmax_t lineNumber = 0;
  auto fail = [&](const std::string& what, std::uint64_t n, std::uintmax_t bytesEach) {
    std::ostringstream msg;
    msg << "ASCII Gmsh file: " << what << " on line " << lineNumber << " is " << n << ", which needs at least "
        << bytesEach << " bytes each, but the file has " << size << " bytes: the file is damaged";
    throw InputError(path, msg.str());
  };
  // The fields of the next line checked in order (a field not given: none is), each
  // count returned; empty where the line is not numbers (gmsh says what is wrong).
  auto counts = [&](std::initializer_list<std::pair<const char*, std::uintmax_t>> fields) {
    std::vector<std::uint64_t> read;
    if (!std::getline(in, line)) return read;
    ++lineNumber;
    std::istringstream values(line);
    for (const auto& [what, bytesEach] : fields) {
      double n = 0;  // as read, so that a negative or huge count is seen as it is
      if (!(values >> n)) return std::vector<std::uint64_t>();
      if (bytesEach > 0 && n > double(size / bytesEach)) fail(what, std::uint64_t(std::max(0.0, n)), bytesEach);
      read.push_back(std::uint64_t(std::max(0.0, n)));
    }
    return read;
  };
  auto skipLines = [&](std::uint64_t n) {
    for (std::uint64_t i = 0; i < n && std::getline(in, line); ++i) ++lineNumber;
  };
  const bool four = version >= 4;
  // Each section closed by its own $End line before the next one opens (a missing
  // $EndNodes read as "the gmsh model has no 3D elements"; issue 49 probe).
  std::string open;
  std::uintmax_t openedOn = 0;
  auto unclosed = [&](const std::string& where) {
    throw InputError(path, "ASCII Gmsh file: the section $" + open + " opened on line " + std::to_string(openedOn) +
                               " is not closed by $End" + open + " " + where + ": the file is damaged");
  };
  while (std::getline(in, line)) {
    ++lineNumber;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (!line.empty() && line[0] == '$') {
      if (line.rfind("$End", 0) == 0) {
        if (line.substr(4) != open) unclosed("(line " + std::to_string(lineNumber) + " says " + line + ")");
        open.clear();
      } else {
        if (!open.empty()) unclosed("before " + line + " on line " + std::to_string(lineNumber));
        open = line.substr(1), openedOn = lineNumber;
      }
    }
    if (line == "$Entities" && four) {
      counts({{"the number of points", 8}, {"the number of curves", 8}, {"the number of surfaces", 8},
              {"the number of volumes", 8}});
    } else if (line == "$Nodes" && four) {
      const auto header = counts({{"the number of node blocks", 8}, {"the number of nodes", 8}});
      for (std::uint64_t b = 0; header.size() == 2 && b < header[0]; ++b) {
        const auto block = counts({{"", 0}, {"", 0}, {"", 0}, {"a node block's number of nodes", 8}});
        if (block.size() != 4) break;
        skipLines(2 * block[3]);  // the tags, then the coordinates
      }
    } else if (line == "$Elements" && four) {
      const auto header = counts({{"the number of element blocks", 8}, {"the number of elements", 4}});
      for (std::uint64_t b = 0; header.size() == 2 && b < header[0]; ++b) {
        const auto block = counts({{"", 0}, {"", 0}, {"", 0}, {"an element block's number of elements", 4}});
        if (block.size() != 4) break;
        skipLines(block[3]);
      }
    } else if (line == "$Nodes") {
      counts({{"the number of nodes", 8}});
    } else if (line == "$Elements") {
      counts({{"the number of elements", 4}});
    }
  }
  if (!open.empty()) unclosed("before the file's end");
}

}  // namespace

void checkMshCounts(const std::string& path, int (*nodesPerElement)(int)) {
  Reader r(path);
  if (r.line() != "$MeshFormat") return;  // not format 2/4 with a header: gmsh says what it is
  std::istringstream version(r.line());
  double v = 0;
  int binary = 0, dataSize = 0;
  version >> v >> binary >> dataSize;
  if (!binary) return checkAsciiCounts(path, v);
  if (v < 4.1 || v >= 5) r.fail("version " + std::to_string(v) + " (binary files of version 4.1 are read)");
  if (dataSize != 8) r.fail("data size " + std::to_string(dataSize) + " (8 expected)");
  if (r.value<std::int32_t>("the byte-order mark") != 1) r.fail("byte order other than this machine's");
  r.skipSection("MeshFormat");
  TagRange tags;
  while (r.left() > 0) {
    std::string header = r.line();
    if (header.empty()) continue;
    if (header[0] != '$') r.fail("'" + header.substr(0, 40) + "' where a section starts, at byte " + std::to_string(r.offset()));
    const std::string name = header.substr(1);
    if (name == "Entities") checkEntities(r);
    else if (name == "Nodes") checkNodes(r, tags);
    else if (name == "Elements") checkElements(r, nodesPerElement, tags);
    r.skipSection(name);
  }
}

}  // namespace cyclone::mesh::detail
