#pragma once
// Private to GmshIO: a binary Gmsh 4.1 file's counts checked against its size
// before gmsh reads it. gmsh allocates what a count says before it reads the
// data, so a damaged 600-byte file took 16.9 GB (issue 20); here every count of
// entities, nodes and elements is walked block by block and must fit in the
// bytes left, or the file is refused with the section and the byte offset.
#include <string>

namespace cyclone::mesh::detail {

/// Returns quietly for an ASCII file (gmsh's ASCII reader grows as it reads) and for a
/// binary file whose counts fit; InputError naming the file otherwise. `nodesPerElement`
/// gives the node count of a gmsh element type (throws for an unknown type).
void checkBinaryMshCounts(const std::string& path, int (*nodesPerElement)(int gmshType));

}  // namespace cyclone::mesh::detail
