#pragma once
// Geometric sanity of a mesh: no inverted or collapsed elements. Readers run it
// before handing a mesh out, so a bad element is reported with its id and block
// instead of surfacing later as a singular or indefinite stiffness matrix.
#include <functional>
#include <string>

#include "cyclone/mesh/Mesh.hpp"

namespace cyclone::mesh {

/// Every element's minJacobianDeterminant must be positive, beyond round-off
/// (relative to the element's size cubed). Otherwise InputError naming
/// mesh.source, the block, the element id and the determinant found.
/// Expects a mesh that passed checkConsistency.
void checkElementGeometry(const Mesh& mesh);

/// Same, with the message's location given by `where(block, element)` (e.g. the deck
/// line the element came from) instead of mesh.source.
void checkElementGeometry(const Mesh& mesh, const std::function<std::string(int block, Index element)>& where);

}  // namespace cyclone::mesh
