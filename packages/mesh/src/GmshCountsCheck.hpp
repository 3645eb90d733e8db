#pragma once
// Private to GmshIO: a Gmsh file's counts checked against its size before gmsh
// reads it. gmsh allocates what a count says before it reads the
// data, so a damaged 600-byte file took 16.9 GB (issue 20); here every count of
// entities, nodes and elements is walked block by block and must fit in the
// bytes left, or the file is refused with the section and the byte offset.
#include <string>

namespace cyclone::mesh::detail {

/// Returns quietly for a file whose counts fit; InputError naming the file otherwise. A
/// binary file is walked block by block; an ASCII one (whose reader reserves what its
/// counts say too) has its section counts checked against the file's size.
/// `nodesPerElement` gives the node count of a gmsh element type (throws for an unknown type).
void checkMshCounts(const std::string& path, int (*nodesPerElement)(int gmshType));

}  // namespace cyclone::mesh::detail
