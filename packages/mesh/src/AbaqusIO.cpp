#include "cyclone/mesh/AbaqusIO.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <unordered_map>
#include <unordered_set>

#include "cyclone/core/AtomicFile.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/mesh/MeshGeometryCheck.hpp"

namespace cyclone::mesh {
namespace {

using Id = long long;
constexpr Id kLargestId = 2147483647;  // Exodus II's 32-bit ids

std::string upper(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::toupper(c); });
  return s;
}

std::string trim(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return "";
  const auto last = s.find_last_not_of(" \t\r\n");
  return s.substr(first, last - first + 1);
}

// Where a line came from: index into the parser's file names, and the 1-based line.
struct Location {
  int file = 0;
  long line = 0;
};

// "*ELEMENT, TYPE=C3D10, ELSET=EALL" -> keyword "ELEMENT", parameters {TYPE: C3D10, ELSET: EALL}.
struct Keyword {
  std::string name;                           // upper case, without '*'
  std::unordered_map<std::string, std::string> parameters;  // upper-case key -> value as written
  bool has(const std::string& key) const { return parameters.count(key) > 0; }
  std::string get(const std::string& key) const {
    const auto it = parameters.find(key);
    return it == parameters.end() ? "" : it->second;
  }
};

Keyword parseKeyword(const std::string& line) {
  Keyword keyword;
  std::size_t start = 1;  // after '*'
  bool first = true;
  while (start <= line.size()) {
    std::size_t comma = line.find(',', start);
    if (comma == std::string::npos) comma = line.size();
    const std::string field = trim(line.substr(start, comma - start));
    start = comma + 1;
    if (first) {
      keyword.name = upper(field);
      first = false;
      continue;
    }
    if (field.empty()) continue;
    const auto eq = field.find('=');
    std::string key = upper(trim(field.substr(0, eq)));
    std::string value = eq == std::string::npos ? "" : trim(field.substr(eq + 1));
    if (value.size() >= 2 && value.front() == '"' && value.back() == '"') value = value.substr(1, value.size() - 2);
    keyword.parameters[key] = value;
  }
  return keyword;
}

// Comma-separated fields of a data line; a trailing comma leaves no empty last field.
std::vector<std::string> splitFields(const std::string& line, bool& trailingComma) {
  std::vector<std::string> fields;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    fields.push_back(trim(line.substr(start, comma == std::string::npos ? std::string::npos : comma - start)));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  trailingComma = fields.size() > 1 && fields.back().empty();
  if (trailingComma) fields.pop_back();
  return fields;
}

// Element type from an Abaqus/CalculiX name: C3D<nodes><letters>, e.g. C3D10, C3D20R, C3D8I.
bool elementTypeFromAbaqus(const std::string& name, ElementType& type) {
  const std::string u = upper(name);
  if (u.rfind("C3D", 0) != 0) return false;
  std::size_t i = 3;
  while (i < u.size() && std::isdigit(static_cast<unsigned char>(u[i]))) ++i;
  const std::string digits = u.substr(3, i - 3);
  for (std::size_t j = i; j < u.size(); ++j)
    if (!std::isalpha(static_cast<unsigned char>(u[j]))) return false;
  if (digits == "4") type = ElementType::Tet4;
  else if (digits == "10") type = ElementType::Tet10;
  else if (digits == "8") type = ElementType::Hex8;
  else if (digits == "20") type = ElementType::Hex20;
  else return false;
  return true;
}

std::string abaqusTypeName(ElementType type) {
  switch (type) {
    case ElementType::Tet4: return "C3D4";
    case ElementType::Tet10: return "C3D10";
    case ElementType::Hex8: return "C3D8";
    case ElementType::Hex20: return "C3D20";
  }
  throw Error("abaqusTypeName: invalid element type");
}

// The whole deck is parsed in one pass; *INCLUDE inserts the included file's lines
// where it stands, as Abaqus does, so the parser state simply carries on.
class DeckParser {
public:
  explicit DeckParser(const std::string& path) { files_.push_back(path); }

  Mesh parse() {
    readFile(0, 0);
    finishElement();
    return assemble();
  }

private:
  enum class Section { None, Node, Element, NodeSet, ElementSet, Skip };

  struct ElementGroup {  // becomes one element block
    std::string name;
    ElementType type;
    std::vector<Id> nodeIds;  // file ids, resolved at the end (nodes may follow elements)
    std::vector<Id> elementIds;
    std::vector<Location> lines;
  };
  struct SetBuild {
    std::vector<Id> ids;
    std::unordered_set<Id> members;
    Location defined;
  };

  std::vector<std::string> files_;
  Location here_;
  Section section_ = Section::None;
  Keyword keyword_;
  Location keywordLine_;

  std::vector<Point> coords_;
  std::vector<Id> nodeIds_;
  std::vector<Location> nodeLines_;
  std::unordered_map<Id, Index> nodeIndex_;

  std::vector<ElementGroup> groups_;
  std::unordered_map<Id, std::pair<int, Index>> elementIndex_;  // id -> (group, local)
  int group_ = -1;                                                 // group of the current *ELEMENT
  std::vector<Id> pendingElement_;                                 // element spanning several lines
  Location pendingLine_;

  std::map<std::string, SetBuild> nodeSets_, elementSets_;
  std::string currentSet_;  // of the current *NODE NSET=, *ELEMENT ELSET=, *NSET or *ELSET
  bool generate_ = false;

  std::string where(const Location& at) const { return atLine(files_[at.file], at.line); }
  [[noreturn]] void fail(const std::string& what) const { throw InputError(where(here_), what); }
  [[noreturn]] void failAt(const Location& at, const std::string& what) const { throw InputError(where(at), what); }

  // `what` names the number for the message; a callable, so hot loops build no strings.
  template <class What>
  Id parseId(const std::string& field, const What& what) const {
    errno = 0;
    char* end = nullptr;
    if (field.empty()) fail("missing " + std::string(what()));
    const Id value = std::strtoll(field.c_str(), &end, 10);
    if (*end != '\0' || errno == ERANGE) fail("bad number '" + field + "' for " + std::string(what()));
    // Abaqus ids are positive; Exodus stores 32-bit ones (a larger id was read, solved,
    // and failed only at the Exodus write: issue 20).
    if (value < 1 || value > kLargestId)
      fail(std::string(what()) + " " + field + " must lie in 1.." + std::to_string(kLargestId));
    return value;
  }
  Id parseId(const std::string& field, const char* what) const {
    return parseId(field, [what] { return what; });
  }

  template <class What>
  double parseReal(std::string field, const What& what) const {
    std::replace(field.begin(), field.end(), 'd', 'e');  // Fortran exponents, 1.0D3
    std::replace(field.begin(), field.end(), 'D', 'e');
    errno = 0;
    char* end = nullptr;
    if (field.empty()) fail("missing " + std::string(what()));
    const double value = std::strtod(field.c_str(), &end);
    if (*end != '\0' || errno == ERANGE) fail("bad number '" + field + "' for " + std::string(what()));
    if (!std::isfinite(value)) fail("'" + field + "' for " + std::string(what()) + " is not a finite number");
    return value;
  }

  void readFile(int file, int depth) {
    if (depth > 20) fail("*INCLUDE nested more than 20 deep (does a file include itself?)");
    std::ifstream in(files_[file]);
    if (!in) {
      if (depth == 0) throw InputError(files_[file], "cannot open the file");
      fail("cannot open included file '" + files_[file] + "'");
    }
    std::string raw;
    long lineNumber = 0;
    while (std::getline(in, raw)) {
      ++lineNumber;
      here_ = {file, lineNumber};
      std::string line = trim(raw);
      if (line.empty() || line.rfind("**", 0) == 0) continue;
      if (line[0] != '*') {
        dataLine(line);
        continue;
      }
      // A keyword line ending with a comma continues on the next line.
      const Location start = here_;
      while (line.back() == ',' && std::getline(in, raw)) {
        ++lineNumber;
        line += trim(raw);
      }
      here_ = start;
      finishElement();
      const Keyword keyword = parseKeyword(line);
      if (keyword.name == "INCLUDE") {
        include(keyword, file, depth);
        continue;
      }
      beginSection(keyword);
    }
  }

  void include(const Keyword& keyword, int file, int depth) {
    const std::string input = keyword.get("INPUT");
    if (input.empty()) fail("*INCLUDE needs INPUT=<file>");
    std::filesystem::path target(input);
    if (target.is_relative()) target = std::filesystem::path(files_[file]).parent_path() / target;
    if (!std::filesystem::is_regular_file(target)) fail("included file '" + target.string() + "' does not exist");
    files_.push_back(target.string());
    const Location back = here_;
    readFile(static_cast<int>(files_.size()) - 1, depth + 1);
    here_ = back;
  }

  void onlyParameters(const Keyword& keyword, std::initializer_list<const char*> allowed) const {
    for (const auto& [key, value] : keyword.parameters)
      if (std::none_of(allowed.begin(), allowed.end(), [&](const char* a) { return key == a; }))
        fail("parameter " + key + " of *" + keyword.name + " is not supported by Cyclone");
  }

  SetBuild& defineSet(std::map<std::string, SetBuild>& sets, const std::string& name) {
    auto [it, inserted] = sets.try_emplace(name);
    if (inserted) it->second.defined = here_;
    return it->second;
  }

  void beginSection(const Keyword& keyword) {
    keyword_ = keyword;
    keywordLine_ = here_;
    currentSet_.clear();
    generate_ = false;
    if (keyword.name == "NODE") {
      onlyParameters(keyword, {"NSET"});
      section_ = Section::Node;
      currentSet_ = keyword.get("NSET");
      if (keyword.has("NSET") && currentSet_.empty()) fail("*NODE has an empty NSET= name");
      if (!currentSet_.empty()) defineSet(nodeSets_, currentSet_);
    } else if (keyword.name == "ELEMENT") {
      onlyParameters(keyword, {"TYPE", "ELSET"});
      section_ = Section::Element;
      const std::string typeName = upper(keyword.get("TYPE"));
      if (typeName.empty()) fail("*ELEMENT needs TYPE=");
      ElementType type;
      if (!elementTypeFromAbaqus(typeName, type))
        fail("unknown element type " + typeName +
             " (Cyclone reads the solids C3D4, C3D10, C3D8 and C3D20 and their variants such as C3D10T or C3D20R;" +
             " remove other elements, e.g. surface elements a mesher exported, from the deck)");
      currentSet_ = keyword.get("ELSET");
      if (keyword.has("ELSET") && currentSet_.empty()) fail("*ELEMENT has an empty ELSET= name");
      const std::string groupName = currentSet_.empty() ? typeName : currentSet_;
      const auto it = std::find_if(groups_.begin(), groups_.end(),
                                   [&](const ElementGroup& g) { return g.name == groupName && g.type == type; });
      group_ = static_cast<int>(it - groups_.begin());
      if (it == groups_.end()) groups_.push_back({groupName, type, {}, {}, {}});
      if (!currentSet_.empty()) defineSet(elementSets_, currentSet_);
    } else if (keyword.name == "NSET" || keyword.name == "ELSET") {
      onlyParameters(keyword, {keyword.name.c_str(), "GENERATE", "UNSORTED", "INTERNAL"});
      const bool nodes = keyword.name == "NSET";
      section_ = nodes ? Section::NodeSet : Section::ElementSet;
      currentSet_ = keyword.get(keyword.name);
      if (currentSet_.empty()) fail("*" + keyword.name + " needs " + keyword.name + "=<name>");
      generate_ = keyword.has("GENERATE");
      defineSet(nodes ? nodeSets_ : elementSets_, currentSet_);
    } else {
      section_ = Section::Skip;  // *MATERIAL, *STEP, *BOUNDARY, ...: not the mesh
    }
  }

  void dataLine(const std::string& line) {
    bool trailingComma = false;
    const auto fields = splitFields(line, trailingComma);
    switch (section_) {
      case Section::Node: return nodeLine(fields);
      case Section::Element: return elementLine(fields, trailingComma);
      case Section::NodeSet: return setLine(fields, true);
      case Section::ElementSet: return setLine(fields, false);
      case Section::None:
      case Section::Skip: return;
    }
  }

  void nodeLine(const std::vector<std::string>& fields) {
    if (fields.size() < 3 || fields.size() > 4) fail("*NODE data must be 'id, x, y[, z]', got '" + join(fields) + "'");
    const Id id = parseId(fields[0], "node id");
    Point x{0, 0, 0};
    for (std::size_t d = 1; d < fields.size(); ++d)
      x[d - 1] = parseReal(fields[d], [&] {
        return "coordinate " + std::to_string(d) + " of node " + std::to_string(id);
      });
    const auto [it, inserted] = nodeIndex_.emplace(id, static_cast<Index>(coords_.size()));
    if (!inserted)
      fail("duplicated node id " + std::to_string(id) + " (first defined at " + where(nodeLines_[it->second]) + ")");
    coords_.push_back(x);
    nodeIds_.push_back(id);
    nodeLines_.push_back(here_);
    if (!currentSet_.empty()) addToSet(nodeSets_.at(currentSet_), id);
  }

  static std::string join(const std::vector<std::string>& fields) {
    std::string s;
    for (const auto& f : fields) s += (s.empty() ? "" : ", ") + f;
    return s;
  }

  void elementLine(const std::vector<std::string>& fields, bool trailingComma) {
    if (pendingElement_.empty()) pendingLine_ = here_;
    auto& group = groups_[group_];
    const std::size_t needed = 1 + nodesPerElement(group.type);
    for (const auto& field : fields)
      pendingElement_.push_back(parseId(field, [&] {
        return pendingElement_.empty() ? std::string("element id")
                                       : "node " + std::to_string(pendingElement_.size()) + " of element " +
                                             std::to_string(pendingElement_[0]);
      }));
    if (pendingElement_.size() > needed)
      failAt(pendingLine_, "element " + std::to_string(pendingElement_[0]) + " has " +
                               std::to_string(pendingElement_.size() - 1) + " nodes, type " +
                               upper(keyword_.get("TYPE")) + " has " + std::to_string(needed - 1));
    if (pendingElement_.size() == needed) return finishElement();
    if (!trailingComma) finishElement();  // too few nodes and no continuation: reported there
  }

  // Completes the element being read (possibly spread over lines).
  void finishElement() {
    if (pendingElement_.empty()) return;
    auto& group = groups_[group_];
    const std::size_t needed = 1 + nodesPerElement(group.type);
    const Id id = pendingElement_[0];
    if (pendingElement_.size() != needed)
      failAt(pendingLine_, "element " + std::to_string(id) + " has " + std::to_string(pendingElement_.size() - 1) +
                               " nodes, type " + upper(keyword_.get("TYPE")) + " has " +
                               std::to_string(needed - 1) + " (a line ending with a comma continues)");
    const auto [it, inserted] =
        elementIndex_.emplace(id, std::make_pair(group_, static_cast<Index>(group.elementIds.size())));
    if (!inserted)
      failAt(pendingLine_, "duplicated element id " + std::to_string(id) + " (first defined at " +
                               where(groups_[it->second.first].lines[it->second.second]) + ")");
    group.elementIds.push_back(id);
    group.nodeIds.insert(group.nodeIds.end(), pendingElement_.begin() + 1, pendingElement_.end());
    group.lines.push_back(pendingLine_);
    if (!currentSet_.empty()) addToSet(elementSets_.at(currentSet_), id);
    pendingElement_.clear();
  }

  static void addToSet(SetBuild& set, Id id) {
    if (set.members.insert(id).second) set.ids.push_back(id);
  }

  void setLine(const std::vector<std::string>& fields, bool nodes) {
    auto& sets = nodes ? nodeSets_ : elementSets_;
    SetBuild& set = sets.at(currentSet_);
    const std::string kind = nodes ? "node" : "element";
    const std::string setName = kind + " set '" + currentSet_ + "'";
    auto addId = [&](Id id) {
      const bool exists = nodes ? nodeIndex_.count(id) > 0 : elementIndex_.count(id) > 0;
      if (!exists) fail(setName + " refers to missing " + kind + " " + std::to_string(id));
      addToSet(set, id);
    };
    if (generate_) {
      if (fields.size() < 2 || fields.size() > 3)
        fail(setName + ": GENERATE data must be 'first, last[, increment]', got '" + join(fields) + "'");
      const Id first = parseId(fields[0], "the first id"), last = parseId(fields[1], "the last id");
      const Id step = fields.size() == 3 ? parseId(fields[2], "the increment") : 1;
      if (step <= 0 || last < first)
        fail(setName + ": GENERATE needs first <= last and a positive increment, got '" + join(fields) + "'");
      for (Id id = first; id <= last; id += step) addId(id);
      return;
    }
    for (const auto& field : fields) {
      if (field.empty()) fail(setName + ": empty field in '" + join(fields) + "'");
      const bool number = std::isdigit(static_cast<unsigned char>(field[0])) || field[0] == '-' || field[0] == '+';
      if (number) {
        addId(parseId(field, [&] { return kind + " id"; }));
        continue;
      }
      const auto other = sets.find(field);
      if (other == sets.end()) fail(setName + " refers to missing " + kind + " set '" + field + "'");
      const std::vector<Id> ids = other->second.ids;  // copy: the set may refer to itself
      for (Id id : ids) addToSet(set, id);
    }
  }

  Mesh assemble() {
    Mesh mesh;
    mesh.source = files_[0];
    mesh.coords = std::move(coords_);
    mesh.nodeIds.assign(nodeIds_.begin(), nodeIds_.end());

    std::vector<Index> groupOffset;
    Index offset = 0;
    std::vector<Location> elementLines;
    for (std::size_t g = 0; g < groups_.size(); ++g) {
      auto& group = groups_[g];
      const bool mixed = std::count_if(groups_.begin(), groups_.end(),
                                       [&](const ElementGroup& o) { return o.name == group.name; }) > 1;
      ElementBlock block;
      block.name = mixed ? group.name + "_" + exodusName(group.type) : group.name;
      block.id = static_cast<int>(g) + 1;
      block.type = group.type;
      const int n = nodesPerElement(group.type);
      block.connectivity.reserve(group.nodeIds.size());
      for (std::size_t i = 0; i < group.nodeIds.size(); ++i) {
        const auto it = nodeIndex_.find(group.nodeIds[i]);
        if (it == nodeIndex_.end())
          failAt(group.lines[i / n], "element " + std::to_string(group.elementIds[i / n]) + " refers to missing node " +
                                         std::to_string(group.nodeIds[i]));
        block.connectivity.push_back(it->second);
      }
      block.elementIds.assign(group.elementIds.begin(), group.elementIds.end());
      groupOffset.push_back(offset);
      offset += block.numElements();
      mesh.blocks.push_back(std::move(block));
    }
    if (mesh.blocks.empty()) throw InputError(files_[0], "the deck defines no elements (*ELEMENT)");

    for (const auto& [name, set] : nodeSets_) {
      if (set.ids.empty()) failAt(set.defined, "node set '" + name + "' is empty");
      auto& nodes = mesh.nodeSets[name];
      for (Id id : set.ids) nodes.push_back(nodeIndex_.at(id));
    }
    for (const auto& [name, set] : elementSets_) {
      if (set.ids.empty()) failAt(set.defined, "element set '" + name + "' is empty");
      auto& elements = mesh.elementSets[name];
      for (Id id : set.ids) {
        const auto [g, local] = elementIndex_.at(id);
        elements.push_back(groupOffset[g] + local);
      }
    }

    checkConsistency(mesh);
    checkElementGeometry(mesh, [&](int block, Index element) { return where(groups_[block].lines[element]); });
    return mesh;
  }
};

// Set and block names go after NSET=/ELSET=: no commas; quoted if they hold blanks.
std::string abaqusName(const std::string& name, const std::string& fallback) {
  std::string s = name.empty() ? fallback : name;
  std::replace(s.begin(), s.end(), ',', '_');
  std::replace(s.begin(), s.end(), '"', '_');
  if (s.find_first_of(" \t") != std::string::npos) s = "\"" + s + "\"";
  return s;
}

// Abaqus data lines hold at most 16 entries; longer lists continue after a trailing comma.
void writeIdLines(std::FILE* f, const std::vector<Id>& ids, bool continuation) {
  for (std::size_t i = 0; i < ids.size(); ++i) {
    const bool lineEnd = (i + 1) % 16 == 0 || i + 1 == ids.size();
    std::fprintf(f, "%lld%s", ids[i], lineEnd ? (continuation && i + 1 < ids.size() ? ",\n" : "\n") : ", ");
  }
}

}  // namespace

Mesh readAbaqusInp(const std::string& path) {
  if (!std::filesystem::is_regular_file(path)) throw InputError(path, "file does not exist");
  return DeckParser(path).parse();
}

// A number in at most 20 characters, CalculiX's field width (it rejects longer
// fields), with as many significant digits as fit (16 when they do).
static std::string deckNumber(double value) {
  char buffer[40];
  for (int digits = 16; digits > 6; --digits) {
    std::snprintf(buffer, sizeof buffer, "%.*g", digits, value);
    if (std::strlen(buffer) <= 20) break;
  }
  return buffer;
}

void writeAbaqusInp(const std::string& path, const Mesh& input) {
  checkConsistency(input);
  // Ids for messages and for the deck; a copy only if the mesh lacks some.
  bool complete = !input.nodeIds.empty() || input.coords.empty();
  for (const auto& block : input.blocks)
    complete = complete && static_cast<Index>(block.elementIds.size()) == block.numElements();
  Mesh withIds;
  if (!complete) {
    withIds = input;
    withIds.assignDefaultIds();
  }
  const Mesh& mesh = complete ? input : withIds;

  AtomicFile out(path);
  std::FILE* f = std::fopen(out.tempPath().c_str(), "w");
  if (!f) throw Error(path + ": cannot create " + out.tempPath());
  struct Closer {
    std::FILE*& f;
    ~Closer() {
      if (f) std::fclose(f);
    }
  } closer{f};

  std::fprintf(f, "** Cyclone mesh written from %s\n", mesh.source.c_str());
  std::fprintf(f, "*NODE\n");
  for (Index n = 0; n < mesh.numNodes(); ++n)
    std::fprintf(f, "%lld, %s, %s, %s\n", static_cast<Id>(mesh.nodeIds[n]), deckNumber(mesh.coords[n][0]).c_str(),
                 deckNumber(mesh.coords[n][1]).c_str(), deckNumber(mesh.coords[n][2]).c_str());

  std::vector<Id> globalElementIds;
  for (const auto& block : mesh.blocks) {
    const std::string name = abaqusName(block.name, "EB" + std::to_string(block.id));
    std::fprintf(f, "*ELEMENT, TYPE=%s, ELSET=%s\n", abaqusTypeName(block.type).c_str(), name.c_str());
    const int n = nodesPerElement(block.type);
    std::vector<Id> line(n + 1);
    for (Index e = 0; e < block.numElements(); ++e) {
      line[0] = block.elementIds[e];
      for (int a = 0; a < n; ++a) line[a + 1] = mesh.nodeIds[block.element(e)[a]];
      writeIdLines(f, line, true);
      globalElementIds.push_back(block.elementIds[e]);
    }
  }

  for (const auto& [name, nodes] : mesh.nodeSets) {
    std::fprintf(f, "*NSET, NSET=%s\n", abaqusName(name, "").c_str());
    std::vector<Id> ids;
    for (Index node : nodes) ids.push_back(mesh.nodeIds[node]);
    writeIdLines(f, ids, false);
  }
  for (const auto& [name, elements] : mesh.elementSets) {
    // A block's ELSET already defines the set of its name; write only what it adds.
    const auto block = std::find_if(mesh.blocks.begin(), mesh.blocks.end(), [&](const ElementBlock& b) {
      return abaqusName(b.name, "EB" + std::to_string(b.id)) == abaqusName(name, "");
    });
    std::unordered_set<Id> inBlock;
    if (block != mesh.blocks.end()) inBlock.insert(block->elementIds.begin(), block->elementIds.end());
    std::vector<Id> ids;
    for (Index e : elements)
      if (!inBlock.count(globalElementIds[e])) ids.push_back(globalElementIds[e]);
    if (block != mesh.blocks.end() && elements.size() - ids.size() < inBlock.size())
      log::warn(path + ": element set '" + name + "' lacks elements of the block of the same name; " +
                "in the deck it will hold the whole block");
    if (ids.empty()) continue;
    std::fprintf(f, "*ELSET, ELSET=%s\n", abaqusName(name, "").c_str());
    writeIdLines(f, ids, false);
  }
  if (std::ferror(f) || std::fclose(f) != 0) {
    f = nullptr;
    throw Error(path + ": writing failed (disk full?)");
  }
  f = nullptr;
  out.commit();
}

}  // namespace cyclone::mesh
