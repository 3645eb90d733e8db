#pragma once
// The in-memory mesh: nodes, element blocks, node/element/side sets.
// All indices are 0-based positions in this mesh; the ids the file used
// (1-based, possibly with gaps) are kept for messages and output.
#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "cyclone/mesh/ElementType.hpp"

namespace cyclone::mesh {

using Index = std::int64_t;
using Point = std::array<double, 3>;

struct ElementBlock {
  std::string name;
  int id = 1;                       ///< Exodus block id
  ElementType type = ElementType::Tet10;
  std::vector<Index> connectivity;  ///< nodesPerElement(type) node indices per element, Exodus order
  std::vector<Index> elementIds;    ///< file ids of the elements, one per element

  Index numElements() const;
  /// Node indices of element e (pointer to nodesPerElement(type) entries).
  const Index* element(Index e) const;
  /// "element 7 (block 'EALL')" for messages: the file id if known, else e + 1.
  std::string describeElement(Index e) const;
};

struct SideEntry {
  Index element;  ///< global element index (blocks numbered consecutively)
  int side;       ///< 0-based local face, Exodus numbering
};

class Mesh {
public:
  std::vector<Point> coords;     ///< one per node
  std::vector<Index> nodeIds;    ///< file id of each node
  std::vector<ElementBlock> blocks;
  std::map<std::string, std::vector<Index>> nodeSets;     ///< name -> node indices
  std::map<std::string, std::vector<Index>> elementSets;  ///< name -> global element indices
  std::map<std::string, std::vector<SideEntry>> sideSets;
  std::string source;  ///< where it came from, for messages ("deck.inp", "built-in sector")

  Index numNodes() const { return static_cast<Index>(coords.size()); }
  Index numElements() const;
  /// Node set by name; throws InputError naming the set, the mesh and the sets
  /// that do exist if it is missing or empty.
  const std::vector<Index>& nodeSet(const std::string& name) const;
  /// Global element index -> (block, local element).
  std::pair<int, Index> locateElement(Index globalElement) const;
  /// "element <file id> (block '<name>')", for messages.
  std::string elementName(Index globalElement) const;
  /// Fills nodeIds 1..n and block elementIds consecutively where they are empty.
  void assignDefaultIds();
};

/// The diagonal of the nodes' bounding box (0 for no nodes): the mesh's size, against
/// which displacements and clearances are judged small.
double boundingDiagonal(const Mesh& mesh);

/// Nodes that belong to no element (indices, ascending): nothing holds them, so a solve
/// with their DOFs free is singular.
std::vector<Index> orphanNodes(const Mesh& mesh);

/// Structural checks every reader runs before handing a mesh out: ids unique,
/// connectivity in range, sets in range and not empty. Throws InputError.
void checkConsistency(const Mesh& mesh);

}  // namespace cyclone::mesh
