#include "NetcdfHeaderCheck.hpp"

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include "cyclone/core/Error.hpp"

namespace cyclone::mesh::detail {

namespace {

// Big-endian reads (netCDF's byte order) with the bytes left known.
class HeaderReader {
public:
  explicit HeaderReader(const std::string& path)
      : path_(path), in_(path, std::ios::binary), size_(std::uintmax_t(std::filesystem::file_size(path))) {}
  std::uintmax_t left() const { return size_ - pos_; }
  std::uint64_t integer(int bytes, const char* what) {
    if (left() < std::uintmax_t(bytes)) fail(std::string("the header ends inside ") + what);
    std::uint64_t v = 0;
    for (int i = 0; i < bytes; ++i) v = (v << 8) | std::uint8_t(in_.get());
    pos_ += std::uintmax_t(bytes);
    return v;
  }
  void skip(std::uint64_t bytes, const char* what) {
    if (bytes > left()) fail(std::string(what) + " of " + std::to_string(bytes) + " bytes at byte " +
                             std::to_string(pos_) + ", beyond the file's end (" + std::to_string(size_) + " bytes)");
    in_.seekg(std::streamoff(bytes), std::ios::cur);
    pos_ += bytes;
  }
  // A count of items of at least `bytesEach` bytes each.
  std::string text(std::uint64_t bytes, const char* what) {
    if (bytes > left()) skip(bytes, what);  // fails, naming it
    std::string t(std::size_t(bytes), '\0');
    in_.read(t.data(), std::streamsize(bytes));
    pos_ += bytes;
    return t;
  }
  std::uint64_t count(int bytes, const char* what, std::uint64_t bytesEach) {
    const auto n = integer(bytes, what);
    if (bytesEach > 0 && n > left() / bytesEach)
      fail(std::string(what) + " " + std::to_string(n) + " at byte " + std::to_string(pos_ - std::uintmax_t(bytes)) +
           " cannot fit in the " + std::to_string(left()) + " bytes left");
    return n;
  }
  [[noreturn]] void fail(const std::string& why) const {
    throw InputError(path_, "damaged netCDF header: " + why + " (the file is damaged or truncated)");
  }

private:
  std::string path_;
  std::ifstream in_;
  std::uintmax_t size_ = 0, pos_ = 0;
};

std::uint64_t padded(std::uint64_t n) { return (n + 3) / 4 * 4; }

void name(HeaderReader& r) { r.skip(padded(r.count(4, "a name's length", 1)), "a name"); }

std::string nameText(HeaderReader& r) {
  const auto n = r.count(4, "a name's length", 1);
  std::string t = r.text(n, "a name");
  r.skip(padded(n) - n, "a name's padding");
  return t;
}

// Exodus' per-entity dimensions: num_node_sets = N names num_nod_ns1..N, and so on. One
// renamed by a damaged byte ("num_nodIns2") reached the Exodus library, whose message named
// its own call and "no entries defined" (issue 49 probe), not the set.
void checkExodusDimensions(HeaderReader& r, const std::map<std::string, std::uint64_t>& dims) {
  const struct {
    const char* count;
    const char* each;
    const char* what;
  } entities[] = {{"num_node_sets", "num_nod_ns", "node set"},
                  {"num_side_sets", "num_side_ss", "side set"},
                  {"num_el_blk", "num_el_in_blk", "element block"}};
  for (const auto& e : entities) {
    const auto n = dims.find(e.count);
    if (n == dims.end()) continue;
    for (std::uint64_t i = 1; i <= n->second && i <= 100000; ++i)
      if (!dims.count(e.each + std::to_string(i)))
        r.fail(std::string("Exodus ") + e.what + " " + std::to_string(i) + " of " + std::to_string(n->second) +
               " (" + e.count + ") has no dimension " + e.each + std::to_string(i));
  }
}

std::uint64_t typeSize(HeaderReader& r, std::uint64_t type) {
  switch (type) {
    case 1: case 2: return 1;  // byte, char
    case 3: return 2;          // short
    case 4: case 5: return 4;  // int, float
    case 6: return 8;          // double
    default: r.fail("an unknown value type " + std::to_string(type));
  }
}

// A list: its tag (or ABSENT: two zeros) and its element count.
std::uint64_t list(HeaderReader& r, std::uint64_t tag, const char* what, std::uint64_t bytesEach) {
  const auto t = r.integer(4, what);
  const auto n = r.count(4, what, bytesEach);
  if (t != 0 && t != tag) r.fail(std::string(what) + " has tag " + std::to_string(t));
  if (t == 0 && n != 0) r.fail(std::string(what) + " is absent but counts " + std::to_string(n));
  return n;
}

void attributes(HeaderReader& r) {
  const auto n = list(r, 12, "an attribute list", 12);
  for (std::uint64_t i = 0; i < n; ++i) {
    name(r);
    const auto size = typeSize(r, r.integer(4, "an attribute's type"));
    const auto values = r.count(4, "an attribute's number of values", size);
    r.skip(padded(values * size), "an attribute's values");
  }
}

}  // namespace

void checkNetcdfHeader(const std::string& path) {
  HeaderReader r(path);
  if (r.left() < 4) return;
  const auto magic = r.integer(4, "the magic number");
  const int version = int(magic & 0xff);
  if ((magic >> 8) != 0x434446 || (version != 1 && version != 2)) return;  // not classic netCDF
  r.integer(4, "the number of records");
  const auto dims = list(r, 10, "the dimension list", 12);
  std::map<std::string, std::uint64_t> lengths;
  for (std::uint64_t i = 0; i < dims; ++i) {
    const std::string dimension = nameText(r);
    lengths[dimension] = r.integer(4, "a dimension's length");
  }
  checkExodusDimensions(r, lengths);
  attributes(r);
  const auto vars = list(r, 11, "the variable list", 24);
  for (std::uint64_t i = 0; i < vars; ++i) {
    name(r);
    const auto ndims = r.count(4, "a variable's number of dimensions", 4);
    for (std::uint64_t d = 0; d < ndims; ++d)
      if (r.integer(4, "a variable's dimension") >= dims) r.fail("a variable names a dimension that is not there");
    attributes(r);
    typeSize(r, r.integer(4, "a variable's type"));
    r.integer(4, "a variable's size");
    r.integer(version == 2 ? 8 : 4, "a variable's offset");
  }
}

}  // namespace cyclone::mesh::detail
