#pragma once
// Reads a mesh file, choosing the reader by extension (case-insensitive):
//   .exo .e .g .ex2  Exodus II      .inp  CalculiX/Abaqus      .msh  gmsh
#include <string>

#include "cyclone/mesh/Mesh.hpp"

namespace cyclone::mesh {

/// Throws InputError naming the file if it does not exist or its extension is unknown.
Mesh readMesh(const std::string& path);

}  // namespace cyclone::mesh
