#pragma once
// The built-in parametric sector of a shrouded bladed disc (Cyclone's default
// model): an annular disc sector, a flat staggered blade and a tip shroud whose
// two side faces lie in the cyclic planes like the disc's. Meshed by gmsh with
// periodic side faces, so left and right faces have identical node layouts
// under the rotation by 2 pi / N about the z axis.
//
// Coordinates: z is the rotation axis; the sector spans angles -pi/N..+pi/N;
// the blade's stacking line is the +x axis. Units are the user's (defaults in mm).
#include <string>

#include "cyclone/mesh/Mesh.hpp"

namespace cyclone::mesh {

struct ShroudedSectorParameters {
  int sectors = 24;
  double boreRadius = 40.0;
  double rimRadius = 100.0;
  double discThickness = 20.0;   ///< axial
  double bladeHeight = 60.0;     ///< rim to shroud, radial
  double bladeChord = 20.0;
  double bladeThickness = 3.0;
  double bladeStaggerDeg = 30.0; ///< rotation of the blade section about the radial axis
  double shroudThickness = 4.0;  ///< radial
  double shroudWidth = 20.0;     ///< axial
  double meshSize = 6.0;         ///< target element edge length
  int elementOrder = 2;          ///< 2: tet10, 1: tet4

  double tipRadius() const { return rimRadius + bladeHeight; }
  /// Throws InputError naming the parameter (prefixed by `where`) for impossible geometry,
  /// e.g. a blade wider than the sector at the rim.
  void validate(const std::string& where) const;
};

/// Named node sets of the result:
///   bore                              nodes on the bore (to be fixed)
///   disc_left, disc_right             disc side faces (angle -pi/N, +pi/N)
///   shroud_left, shroud_right         shroud side faces
///   shroud_contact_left/right         shroud face nodes in pair order: right[i] = R left[i]
///   mid_blade                         the node at the blade's mid-height centre, embedded in
///                                     the mesh (the same material point at every mesh size)
/// One element block "sector". Progress goes to the log.
Mesh generateShroudedSector(const ShroudedSectorParameters& parameters);

}  // namespace cyclone::mesh
