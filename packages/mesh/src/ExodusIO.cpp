#include "cyclone/mesh/ExodusIO.hpp"

#include <exodusII.h>
#include <netcdf.h>

#include <algorithm>
#include <cstring>

#include "NetcdfHeaderCheck.hpp"
#include <filesystem>
#include <limits>
#include <set>

#include "cyclone/core/AtomicFile.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/mesh/MeshGeometryCheck.hpp"

namespace cyclone::mesh {
namespace {

// Longest name written; Exodus' default of 32 is too short for descriptive set names.
constexpr int kMaxNameLength = 80;

// The library's last message, for our exceptions. Errors are reported through those,
// so the library is told (once) neither to print them nor to exit on them.
std::string exodusMessage() {
  const char *msg = nullptr, *func = nullptr;
  int code = 0;
  ex_get_err(&msg, &func, &code);
  std::string text = msg ? msg : "";
  if (func && *func) text = std::string(func) + ": " + text;
  return text;
}

void quietExodus() {
  static const bool done = (ex_opts(EX_DEFAULT), true);
  (void)done;
}

// Throws unless rc >= 0 (positive codes are the library's warnings, e.g. "no names stored").
void check(int rc, const char* call, const std::string& path) {
  if (rc < 0) throw Error(path + ": Exodus call " + call + " failed (" + exodusMessage() + ")");
}

// Closes the file on every exit path.
class ExodusFile {
public:
  ExodusFile(int id, std::string path) : id_(id), path_(std::move(path)) {}
  ~ExodusFile() {
    if (id_ >= 0) ex_close(id_);
  }
  ExodusFile(ExodusFile&& other) noexcept : id_(other.id_), path_(std::move(other.path_)) { other.id_ = -1; }
  ExodusFile(const ExodusFile&) = delete;
  ExodusFile& operator=(const ExodusFile&) = delete;
  int id() const { return id_; }
  void close() {
    const int id = id_;
    id_ = -1;
    check(ex_close(id), "ex_close", path_);
  }

private:
  int id_;
  std::string path_;
};

// A classic or 64-bit-offset netCDF file is its header (dimensions, attributes and
// variable descriptions, serialized with every name and value padded to 4 bytes) and
// then every variable's data, records last, so it is at least as long as both
// together. netCDF reads a file cut short as zeros past its end (issue 20), so the
// length is checked first; the sum is a lower bound (netCDF may leave room after the
// header and align variables). A netCDF-4 file is HDF5, whose reader sees the cut.
void checkNotTruncated(int ncid, const std::string& path) {
  int format = 0;
  if (nc_inq_format(ncid, &format) != NC_NOERR || (format != NC_FORMAT_CLASSIC && format != NC_FORMAT_64BIT_OFFSET))
    return;
  int ndims = 0, nvars = 0, natts = 0, unlimited = -1;
  if (nc_inq(ncid, &ndims, &nvars, &natts, &unlimited) != NC_NOERR) return;
  auto padded = [](std::uintmax_t bytes) { return (bytes + 3) / 4 * 4; };
  char name[NC_MAX_NAME + 1];
  auto nameBytes = [&](const char* n) { return 4 + padded(std::strlen(n)); };
  auto typeBytes = [&](nc_type type) {
    std::size_t bytes = 0;
    nc_inq_type(ncid, type, nullptr, &bytes);
    return std::uintmax_t(bytes);
  };
  auto attributeBytes = [&](int varid, int count) {
    std::uintmax_t bytes = 8;  // the list's tag and length
    for (int a = 0; a < count; ++a) {
      nc_type type;
      std::size_t len = 0;
      if (nc_inq_attname(ncid, varid, a, name) != NC_NOERR || nc_inq_att(ncid, varid, name, &type, &len) != NC_NOERR)
        return bytes;
      bytes += nameBytes(name) + 8 + padded(len * typeBytes(type));
    }
    return bytes;
  };
  std::uintmax_t needed = 8 + 8;  // magic, number of records; the dimension list's tag and length
  for (int d = 0; d < ndims; ++d)
    if (nc_inq_dimname(ncid, d, name) == NC_NOERR) needed += nameBytes(name) + 4;
  needed += attributeBytes(NC_GLOBAL, natts) + 8;  // then the variable list's tag and length
  std::size_t records = 0;
  if (unlimited >= 0) nc_inq_dimlen(ncid, unlimited, &records);
  for (int v = 0; v < nvars; ++v) {
    nc_type type;
    int vdims = 0, vatts = 0, dimids[NC_MAX_VAR_DIMS];
    if (nc_inq_var(ncid, v, name, &type, &vdims, dimids, &vatts) != NC_NOERR) return;
    needed += nameBytes(name) + 4 + 4 * std::uintmax_t(vdims) + attributeBytes(v, vatts) + 8 +
              (format == NC_FORMAT_64BIT_OFFSET ? 8 : 4);
    std::uintmax_t size = typeBytes(type);
    bool record = false;
    for (int d = 0; d < vdims; ++d) {
      if (dimids[d] == unlimited) {
        record = true;
        continue;
      }
      std::size_t len = 0;
      nc_inq_dimlen(ncid, dimids[d], &len);
      size *= len;
    }
    needed += record ? size * records : size;
  }
  const auto actual = std::filesystem::file_size(path);
  if (actual < needed)
    throw InputError(path, "the file is " + std::to_string(actual) + " bytes, but its header and data need at least " +
                               std::to_string(needed) + ": it is truncated (a copy or a write cut short)");
}

ExodusFile openForReading(const std::string& path) {
  quietExodus();
  if (!std::filesystem::is_regular_file(path)) throw InputError(path, "file does not exist");
  detail::checkNetcdfHeader(path);  // before netCDF allocates what a damaged header says
  int cpuWordSize = sizeof(double), ioWordSize = 0;
  float version = 0;
  const int id = ex_open(path.c_str(), EX_READ | EX_ALL_INT64_API, &cpuWordSize, &ioWordSize, &version);
  if (id < 0) throw InputError(path, "not a readable Exodus II file (" + exodusMessage() + ")");
  ExodusFile file(id, path);
  checkNotTruncated(id, path);
  // Names as long as the file holds them.
  const int64_t longest = ex_inquire_int(id, EX_INQ_DB_MAX_USED_NAME_LENGTH);
  if (longest > 0) check(ex_set_max_name_length(id, static_cast<int>(longest)), "ex_set_max_name_length", path);
  return file;
}

// Fixed-size buffers behind the char** arrays the C API fills or reads.
class NameBuffers {
public:
  NameBuffers(std::size_t count, std::size_t length) : storage_(count, std::string(length + 1, '\0')) {
    for (auto& s : storage_) pointers_.push_back(s.data());
  }
  char** data() { return pointers_.data(); }
  std::string operator[](std::size_t i) const { return trimmed(storage_[i].c_str()); }
  static std::string trimmed(const char* s) {
    std::string name(s);
    while (!name.empty() && (name.back() == ' ' || name.back() == '\0')) name.pop_back();
    return name;
  }

private:
  std::vector<std::string> storage_;
  std::vector<char*> pointers_;
};

std::size_t nameLength(int exoid) {
  const int64_t n = ex_inquire_int(exoid, EX_INQ_MAX_READ_NAME_LENGTH);
  return static_cast<std::size_t>(std::max<int64_t>(n, MAX_STR_LENGTH));
}

std::string entityName(int exoid, ex_entity_type type, int64_t id) {
  std::string buffer(nameLength(exoid) + 1, '\0');
  if (ex_get_name(exoid, type, id, buffer.data()) < 0) return "";
  return NameBuffers::trimmed(buffer.c_str());
}

std::vector<int64_t> entityIds(int exoid, ex_entity_type type, int64_t count, const std::string& path) {
  std::vector<int64_t> ids(count);
  if (count > 0) check(ex_get_ids(exoid, type, ids.data()), "ex_get_ids", path);
  return ids;
}

struct BlockInfo {
  int64_t id;
  std::string topology;
  int64_t numElements, nodesPerElement;
};

std::vector<BlockInfo> readBlockInfo(int exoid, int64_t numBlocks, const std::string& path) {
  std::vector<BlockInfo> info;
  for (int64_t id : entityIds(exoid, EX_ELEM_BLOCK, numBlocks, path)) {
    ex_block block{};
    block.id = id;
    block.type = EX_ELEM_BLOCK;
    check(ex_get_block_param(exoid, &block), "ex_get_block_param", path);
    info.push_back({id, NameBuffers::trimmed(block.topology), block.num_entry, block.num_nodes_per_entry});
  }
  return info;
}

// The element type of a block, from its topology name and node count ("TETRA" with 10 nodes is a TETRA10).
ElementType blockElementType(const BlockInfo& block, const std::string& where) {
  ElementType type = elementTypeFromExodusName(block.topology, where);
  if (nodesPerElement(type) == block.nodesPerElement) return type;
  const bool tet = type == ElementType::Tet4 || type == ElementType::Tet10;
  for (ElementType candidate : tet ? std::vector<ElementType>{ElementType::Tet4, ElementType::Tet10}
                                   : std::vector<ElementType>{ElementType::Hex8, ElementType::Hex20})
    if (nodesPerElement(candidate) == block.nodesPerElement) return candidate;
  throw InputError(where, "element type " + block.topology + " with " + std::to_string(block.nodesPerElement) +
                              " nodes per element is not supported");
}

std::string uniqueName(std::string name, const std::string& fallback, std::set<std::string>& taken,
                       const std::string& where, const std::string& kind) {
  if (name.empty()) name = fallback;
  if (!taken.insert(name).second) throw InputError(where, "two " + kind + "s are named '" + name + "'");
  return name;
}

// Sets of one kind (node, element or side sets): id, name, entries and extra list.
struct SetData {
  int64_t id;
  std::string name;
  std::vector<int64_t> entries, extra;
};

std::vector<SetData> readSets(int exoid, ex_entity_type type, int64_t count, const std::string& path,
                              const std::string& kind, const std::string& fallbackPrefix) {
  std::vector<SetData> sets;
  std::set<std::string> taken;
  for (int64_t id : entityIds(exoid, type, count, path)) {
    int64_t numEntries = 0, numDistributionFactors = 0;
    check(ex_get_set_param(exoid, type, id, &numEntries, &numDistributionFactors), "ex_get_set_param", path);
    const std::string name = uniqueName(entityName(exoid, type, id), fallbackPrefix + std::to_string(id), taken,
                                        path, kind);
    if (numEntries == 0) {
      log::warn(path + ": " + kind + " '" + name + "' is empty and is left out");
      continue;
    }
    SetData set{id, name, std::vector<int64_t>(numEntries), {}};
    if (type == EX_SIDE_SET) set.extra.resize(numEntries);
    check(ex_get_set(exoid, type, id, set.entries.data(), set.extra.empty() ? nullptr : set.extra.data()),
          "ex_get_set", path);
    sets.push_back(std::move(set));
  }
  return sets;
}

std::vector<std::string> variableNames(int exoid, ex_entity_type type, const std::string& path) {
  int count = 0;
  check(ex_get_variable_param(exoid, type, &count), "ex_get_variable_param", path);
  if (count == 0) return {};
  NameBuffers names(count, nameLength(exoid));
  check(ex_get_variable_names(exoid, type, count, names.data()), "ex_get_variable_names", path);
  std::vector<std::string> result;
  for (int i = 0; i < count; ++i) result.push_back(names[i]);
  return result;
}

}  // namespace

Mesh readExodus(const std::string& path) {
  ExodusFile file = openForReading(path);
  const int exoid = file.id();
  ex_init_params init{};
  check(ex_get_init_ext(exoid, &init), "ex_get_init_ext", path);
  if (init.num_dim != 3)
    throw InputError(path, "the mesh is " + std::to_string(init.num_dim) + "-dimensional; Cyclone needs a 3D mesh");

  Mesh mesh;
  mesh.source = path;
  const int64_t numNodes = init.num_nodes;
  {
    std::vector<double> x(numNodes), y(numNodes), z(numNodes);
    if (numNodes > 0) check(ex_get_coord(exoid, x.data(), y.data(), z.data()), "ex_get_coord", path);
    mesh.coords.resize(numNodes);
    for (int64_t n = 0; n < numNodes; ++n) mesh.coords[n] = {x[n], y[n], z[n]};
    mesh.nodeIds.resize(numNodes);
    if (numNodes > 0) check(ex_get_id_map(exoid, EX_NODE_MAP, mesh.nodeIds.data()), "ex_get_id_map", path);
    // A truncated file reads as zeros past its end (issue 20: "node id 0 is used twice").
    for (int64_t n = 0; n < numNodes; ++n)
      if (mesh.nodeIds[n] <= 0)
        throw InputError(path, "node " + std::to_string(n + 1) + " of " + std::to_string(numNodes) + " has id " +
                                   std::to_string(mesh.nodeIds[n]) +
                                   ": ids are positive, so the file is truncated or damaged");
  }

  std::vector<int64_t> elementIdMap(init.num_elem);
  if (init.num_elem > 0) check(ex_get_id_map(exoid, EX_ELEM_MAP, elementIdMap.data()), "ex_get_id_map", path);
  std::set<std::string> blockNames;
  int64_t firstElement = 0;
  for (const auto& info : readBlockInfo(exoid, init.num_elem_blk, path)) {
    const std::string name = uniqueName(entityName(exoid, EX_ELEM_BLOCK, info.id), "block_" + std::to_string(info.id),
                                        blockNames, path, "element block");
    const std::string where = path + ": block '" + name + "' (id " + std::to_string(info.id) + ")";
    if (info.numElements == 0) {
      log::warn(where + " has no elements and is left out");
      continue;
    }
    if (info.id < 1 || info.id > std::numeric_limits<int>::max())
      throw InputError(where, "block id out of the supported range 1.." +
                                  std::to_string(std::numeric_limits<int>::max()));
    ElementBlock block;
    block.name = name;
    block.id = static_cast<int>(info.id);
    block.type = blockElementType(info, where);
    block.connectivity.resize(info.numElements * info.nodesPerElement);
    check(ex_get_conn(exoid, EX_ELEM_BLOCK, info.id, block.connectivity.data(), nullptr, nullptr), "ex_get_conn",
          path);
    for (auto& node : block.connectivity)
      if (--node < 0)  // 1-based in the file: 0 is what a truncated file reads as
        throw InputError(where, "its connectivity holds node 0: the file is truncated or damaged");
    block.elementIds.assign(elementIdMap.begin() + firstElement,
                            elementIdMap.begin() + firstElement + info.numElements);
    firstElement += info.numElements;
    mesh.blocks.push_back(std::move(block));
  }

  for (auto& set : readSets(exoid, EX_NODE_SET, init.num_node_sets, path, "node set", "nodeset_")) {
    for (auto& node : set.entries) --node;
    mesh.nodeSets[set.name] = std::move(set.entries);
  }
  for (auto& set : readSets(exoid, EX_ELEM_SET, init.num_elem_sets, path, "element set", "elemset_")) {
    for (auto& element : set.entries) --element;
    mesh.elementSets[set.name] = std::move(set.entries);
  }
  for (const auto& set : readSets(exoid, EX_SIDE_SET, init.num_side_sets, path, "side set", "sideset_")) {
    auto& sides = mesh.sideSets[set.name];
    for (std::size_t i = 0; i < set.entries.size(); ++i)
      sides.push_back({set.entries[i] - 1, static_cast<int>(set.extra[i]) - 1});
  }
  file.close();
  checkConsistency(mesh);
  checkElementGeometry(mesh);
  return mesh;
}

namespace {

// Writes a named set of one kind; entries already 1-based.
void writeSet(int exoid, ex_entity_type type, int64_t id, const std::string& name, const std::vector<int64_t>& entries,
              const std::vector<int64_t>* extra, const std::string& path) {
  check(ex_put_set_param(exoid, type, id, static_cast<int64_t>(entries.size()), 0), "ex_put_set_param", path);
  check(ex_put_set(exoid, type, id, entries.data(), extra ? extra->data() : nullptr), "ex_put_set", path);
  check(ex_put_name(exoid, type, id, name.substr(0, kMaxNameLength).c_str()), "ex_put_name", path);
}

void writeVariableNames(int exoid, ex_entity_type type, const std::vector<std::string>& names, const std::string& path) {
  if (names.empty()) return;
  check(ex_put_variable_param(exoid, type, static_cast<int>(names.size())), "ex_put_variable_param", path);
  std::vector<std::string> cut;
  for (const auto& name : names) cut.push_back(name.substr(0, kMaxNameLength));
  std::vector<char*> pointers;
  for (auto& name : cut) pointers.push_back(name.data());
  check(ex_put_variable_names(exoid, type, static_cast<int>(names.size()), pointers.data()), "ex_put_variable_names",
        path);
}

// Result sizes are checked step by step as they are written: a mismatch aborts the
// write, and AtomicFile then leaves nothing behind.
void checkSize(std::size_t have, std::size_t want, const std::string& path, std::size_t step, const std::string& what) {
  if (have != want)
    throw Error(path + ": step " + std::to_string(step + 1) + ": " + what + " has " + std::to_string(have) +
                " values, expected " + std::to_string(want));
}

}  // namespace

namespace {

void writeNodes(int exoid, const Mesh& mesh, const std::string& path) {
  const int64_t numNodes = mesh.numNodes();
  std::vector<double> x(numNodes), y(numNodes), z(numNodes);
  for (int64_t n = 0; n < numNodes; ++n) x[n] = mesh.coords[n][0], y[n] = mesh.coords[n][1], z[n] = mesh.coords[n][2];
  check(ex_put_coord(exoid, x.data(), y.data(), z.data()), "ex_put_coord", path);
  char xName[] = "x", yName[] = "y", zName[] = "z";
  char* coordNames[] = {xName, yName, zName};
  check(ex_put_coord_names(exoid, coordNames), "ex_put_coord_names", path);
  std::vector<int64_t> ids(numNodes);
  for (int64_t n = 0; n < numNodes; ++n) ids[n] = mesh.nodeIds.empty() ? n + 1 : mesh.nodeIds[n];
  check(ex_put_id_map(exoid, EX_NODE_MAP, ids.data()), "ex_put_id_map", path);
}

// Blocks without element ids are numbered as Mesh::assignDefaultIds would.
void writeBlocks(int exoid, const Mesh& mesh, const std::string& path) {
  int64_t nextId = 1;
  for (const auto& block : mesh.blocks)
    for (Index id : block.elementIds) nextId = std::max<int64_t>(nextId, id + 1);
  std::vector<int64_t> elementIds;
  for (const auto& block : mesh.blocks) {
    const int64_t ne = block.numElements(), n = nodesPerElement(block.type);
    check(ex_put_block(exoid, EX_ELEM_BLOCK, block.id, exodusName(block.type).c_str(), ne, n, 0, 0, 0),
          "ex_put_block", path);
    if (ne > 0) {
      std::vector<int64_t> conn(block.connectivity.begin(), block.connectivity.end());
      for (auto& node : conn) ++node;
      check(ex_put_conn(exoid, EX_ELEM_BLOCK, block.id, conn.data(), nullptr, nullptr), "ex_put_conn", path);
    }
    check(ex_put_name(exoid, EX_ELEM_BLOCK, block.id, block.name.substr(0, kMaxNameLength).c_str()), "ex_put_name",
          path);
    for (int64_t e = 0; e < ne; ++e)
      elementIds.push_back(block.elementIds.empty() ? nextId++ : block.elementIds[e]);
  }
  if (mesh.numElements() > 0) check(ex_put_id_map(exoid, EX_ELEM_MAP, elementIds.data()), "ex_put_id_map", path);

}

void writeSets(int exoid, const Mesh& mesh, const std::string& path) {
  int64_t setId = 1;
  for (const auto& [name, nodes] : mesh.nodeSets) {
    std::vector<int64_t> entries(nodes.begin(), nodes.end());
    for (auto& node : entries) ++node;
    writeSet(exoid, EX_NODE_SET, setId++, name, entries, nullptr, path);
  }
  setId = 1;
  for (const auto& [name, elements] : mesh.elementSets) {
    std::vector<int64_t> entries(elements.begin(), elements.end());
    for (auto& element : entries) ++element;
    writeSet(exoid, EX_ELEM_SET, setId++, name, entries, nullptr, path);
  }
  setId = 1;
  for (const auto& [name, sides] : mesh.sideSets) {
    std::vector<int64_t> elements, faces;
    for (const auto& side : sides) elements.push_back(side.element + 1), faces.push_back(side.side + 1);
    writeSet(exoid, EX_SIDE_SET, setId++, name, elements, &faces, path);
  }

}

void writeResultStep(int exoid, const Mesh& mesh, const ExodusResults& results, std::size_t s,
                     const std::string& path) {
  const int64_t numNodes = mesh.numNodes(), numElements = mesh.numElements();
  const auto& step = results.steps[s];
  const int exoStep = static_cast<int>(s) + 1;
  check(ex_put_time(exoid, exoStep, &step.time), "ex_put_time", path);
  checkSize(step.nodal.size(), results.nodalNames.size(), path, s, "the list of nodal fields");
  for (std::size_t v = 0; v < step.nodal.size(); ++v) {
    checkSize(step.nodal[v].size(), numNodes, path, s, "nodal field '" + results.nodalNames[v] + "'");
    if (numNodes > 0)
      check(ex_put_var(exoid, exoStep, EX_NODAL, static_cast<int>(v) + 1, 1, numNodes, step.nodal[v].data()),
            "ex_put_var", path);
  }
  checkSize(step.element.size(), results.elementNames.size(), path, s, "the list of element fields");
  for (std::size_t v = 0; v < step.element.size(); ++v) {
    checkSize(step.element[v].size(), numElements, path, s, "element field '" + results.elementNames[v] + "'");
    int64_t first = 0;
    for (const auto& block : mesh.blocks) {
      const int64_t ne = block.numElements();
      if (ne > 0)
        check(ex_put_var(exoid, exoStep, EX_ELEM_BLOCK, static_cast<int>(v) + 1, block.id, ne,
                         step.element[v].data() + first),
              "ex_put_var", path);
      first += ne;
    }
  }
  checkSize(step.global.size(), results.globalNames.size(), path, s, "the list of global values");
  if (!step.global.empty())
    check(ex_put_glob_vars(exoid, exoStep, static_cast<int>(step.global.size()), step.global.data()),
          "ex_put_glob_vars", path);
}

}  // namespace

void writeExodus(const std::string& path, const Mesh& mesh, const ExodusResults& results) {
  quietExodus();
  checkConsistency(mesh);
  AtomicFile out(path);
  int cpuWordSize = sizeof(double), ioWordSize = sizeof(double);
  const int exoid = ex_create(out.tempPath().c_str(), EX_CLOBBER | EX_ALL_INT64_API, &cpuWordSize, &ioWordSize);
  if (exoid < 0) throw Error(path + ": cannot create the Exodus file (" + exodusMessage() + ")");
  ExodusFile file(exoid, path);
  check(ex_set_max_name_length(exoid, kMaxNameLength), "ex_set_max_name_length", path);

  const int64_t numNodes = mesh.numNodes(), numElements = mesh.numElements();
  ex_init_params init{};
  std::strncpy(init.title, ("Cyclone: " + mesh.source).c_str(), MAX_LINE_LENGTH);
  init.num_dim = 3;
  init.num_nodes = numNodes;
  init.num_elem = numElements;
  init.num_elem_blk = static_cast<int64_t>(mesh.blocks.size());
  init.num_node_sets = static_cast<int64_t>(mesh.nodeSets.size());
  init.num_elem_sets = static_cast<int64_t>(mesh.elementSets.size());
  init.num_side_sets = static_cast<int64_t>(mesh.sideSets.size());
  check(ex_put_init_ext(exoid, &init), "ex_put_init_ext", path);

  writeNodes(exoid, mesh, path);
  writeBlocks(exoid, mesh, path);
  writeSets(exoid, mesh, path);
  writeVariableNames(exoid, EX_GLOBAL, results.globalNames, path);
  writeVariableNames(exoid, EX_NODAL, results.nodalNames, path);
  writeVariableNames(exoid, EX_ELEM_BLOCK, results.elementNames, path);
  const int numBlocks = static_cast<int>(mesh.blocks.size());
  const int numElementVars = static_cast<int>(results.elementNames.size());
  if (numElementVars > 0 && numBlocks > 0) {
    std::vector<int> truth(static_cast<std::size_t>(numBlocks) * numElementVars, 1);  // every variable on every block
    check(ex_put_truth_table(exoid, EX_ELEM_BLOCK, numBlocks, numElementVars, truth.data()), "ex_put_truth_table", path);
  }

  for (std::size_t s = 0; s < results.steps.size(); ++s) writeResultStep(exoid, mesh, results, s, path);
  file.close();
  out.commit();
}

ExodusResults readExodusResults(const std::string& path) {
  ExodusFile file = openForReading(path);
  const int exoid = file.id();
  ex_init_params init{};
  check(ex_get_init_ext(exoid, &init), "ex_get_init_ext", path);
  const auto blocks = readBlockInfo(exoid, init.num_elem_blk, path);

  ExodusResults results;
  results.globalNames = variableNames(exoid, EX_GLOBAL, path);
  results.nodalNames = variableNames(exoid, EX_NODAL, path);
  results.elementNames = variableNames(exoid, EX_ELEM_BLOCK, path);
  const int numElementVars = static_cast<int>(results.elementNames.size());
  // Which element variables each block stores; the others read as NaN.
  std::vector<int> truth(blocks.size() * numElementVars, 1);
  if (numElementVars > 0 && !blocks.empty())
    check(ex_get_truth_table(exoid, EX_ELEM_BLOCK, static_cast<int>(blocks.size()), numElementVars, truth.data()),
          "ex_get_truth_table", path);

  const int numSteps = static_cast<int>(ex_inquire_int(exoid, EX_INQ_TIME));
  std::vector<double> times(numSteps);
  if (numSteps > 0) check(ex_get_all_times(exoid, times.data()), "ex_get_all_times", path);
  for (int s = 0; s < numSteps; ++s) {
    const int exoStep = s + 1;
    ExodusResults::Step step;
    step.time = times[s];
    for (std::size_t v = 0; v < results.nodalNames.size(); ++v) {
      std::vector<double> values(init.num_nodes);
      if (init.num_nodes > 0)
        check(ex_get_var(exoid, exoStep, EX_NODAL, static_cast<int>(v) + 1, 1, init.num_nodes, values.data()),
              "ex_get_var", path);
      step.nodal.push_back(std::move(values));
    }
    for (int v = 0; v < numElementVars; ++v) {
      std::vector<double> values(init.num_elem, std::numeric_limits<double>::quiet_NaN());
      int64_t first = 0;
      for (std::size_t b = 0; b < blocks.size(); ++b) {
        if (blocks[b].numElements > 0 && truth[b * numElementVars + v])
          check(ex_get_var(exoid, exoStep, EX_ELEM_BLOCK, v + 1, blocks[b].id, blocks[b].numElements,
                           values.data() + first),
                "ex_get_var", path);
        first += blocks[b].numElements;
      }
      step.element.push_back(std::move(values));
    }
    if (!results.globalNames.empty()) {
      step.global.resize(results.globalNames.size());
      check(ex_get_glob_vars(exoid, exoStep, static_cast<int>(step.global.size()), step.global.data()),
            "ex_get_glob_vars", path);
    }
    results.steps.push_back(std::move(step));
  }
  file.close();
  return results;
}

}  // namespace cyclone::mesh
