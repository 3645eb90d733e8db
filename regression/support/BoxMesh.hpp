#pragma once
// Structured meshes of a box for tests and benchmarks: nx*ny*nz cells as hex8,
// hex20, or each cell split into 6 tets (Kuhn split, conforming) as tet4/tet10.
// Node sets "x0","x1","y0","y1","z0","z1" hold the nodes on each face, and
// "all" every node.
#include "cyclone/mesh/Mesh.hpp"

namespace cyclone::test_support {

cyclone::mesh::Mesh makeBoxMesh(double lx, double ly, double lz, int nx, int ny, int nz,
                                cyclone::mesh::ElementType type);

}  // namespace cyclone::test_support
