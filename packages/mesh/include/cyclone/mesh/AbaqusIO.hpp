#pragma once
// CalculiX / Abaqus input decks (.inp): the mesh part.
//
// Read: *NODE (NSET=), *ELEMENT (TYPE=, ELSET=), *NSET and *ELSET (with GENERATE,
// or lists of ids and names of other sets), *INCLUDE (INPUT= relative to the
// including file). Keywords and parameter names are case-insensitive; ** starts
// a comment; other keywords (*MATERIAL, *STEP, ...) and their data are skipped.
// Element types: C3D4*, C3D10*, C3D8*, C3D20* with any suffix letters (C3D10T,
// C3D20R, C3D8I, ...) map to tet4, tet10, hex8, hex20; any other *ELEMENT type is
// an error. A data line ending with a comma continues on the next line (C3D20).
//
// Element blocks: one per ELSET name (or, without ELSET=, per TYPE as written,
// e.g. "C3D10"), ids 1, 2, ... in order of appearance; an ELSET holding two element
// types gives two blocks "<ELSET>_<EXODUS TYPE>". ELSET= on *ELEMENT also defines
// that element set, as in Abaqus.
// Set names are kept as written and, unlike Abaqus, compared case-sensitively
// (here and by Mesh::nodeSet): "Fix" and "FIX" are two sets.
//
// Errors are InputError "file:line: what": unknown element type, missing or
// duplicated node id, element referring to a missing node, bad number, set
// referring to a missing id or set, empty set, inverted element (by element id).
#include <string>

#include "cyclone/mesh/Mesh.hpp"

namespace cyclone::mesh {

/// Reads the mesh of a deck and runs checkConsistency and checkElementGeometry.
Mesh readAbaqusInp(const std::string& path);

/// Writes nodes, elements (per block, ELSET=<block name>), node sets and element
/// sets, with 16 significant digits. Atomic (AtomicFile): nothing half-written.
/// Element sets named like a block are not repeated (the block's ELSET defines them).
void writeAbaqusInp(const std::string& path, const Mesh& mesh);

}  // namespace cyclone::mesh
