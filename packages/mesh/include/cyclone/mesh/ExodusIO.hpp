#pragma once
// Exodus II meshes and results (ExodusII 6.02 C API): element blocks, node sets,
// element sets and side sets with their names, node/element id maps, and nodal,
// element and global result variables over time steps.
#include <string>
#include <vector>

#include "cyclone/mesh/Mesh.hpp"

namespace cyclone::mesh {

/// Result variables over steps. Element values are given for every element, in global
/// element order (blocks one after another); the file stores them per block.
struct ExodusResults {
  std::vector<std::string> nodalNames, elementNames, globalNames;
  struct Step {
    double time = 0;
    std::vector<std::vector<double>> nodal;    ///< per nodal name, numNodes values
    std::vector<std::vector<double>> element;  ///< per element name, numElements values
    std::vector<double> global;                ///< per global name
  };
  std::vector<Step> steps;
};

/// Reads blocks (named by their Exodus names, or "block_<id>"), node sets, element
/// sets and side sets (named, or "nodeset_<id>", "elemset_<id>", "sideset_<id>"),
/// and the id maps; indices become 0-based. Runs checkConsistency and
/// checkElementGeometry. Throws InputError naming the file.
Mesh readExodus(const std::string& path);

/// Writes mesh and results. Atomic: written under a temporary name and renamed
/// when complete, so a failure (bad result sizes, disk full) leaves no file and an
/// earlier file of the same name untouched. Names longer than 80 characters are cut.
void writeExodus(const std::string& path, const Mesh& mesh, const ExodusResults& results = {});

/// Result variables and steps of a file written by writeExodus (or any Exodus file).
ExodusResults readExodusResults(const std::string& path);

}  // namespace cyclone::mesh
