#pragma once
// Mistuning input: per blade a Young's modulus factor of the blade's elements, E_j = f_j E
// (blade j's elements only; the disc keeps E), given as the factors themselves, as the
// blade-alone frequency deviations delta_j = (w_j / w)^2 - 1 (ANSYS' input: a blade whose
// stiffness scales with E has w_j^2 proportional to E_j, so f_j = 1 + delta_j), or drawn at
// random (randomPattern: normal deviations of a standard deviation, a seed). And which
// elements are the blade: a named element set of the mesh, or for a mesh without one the
// elements whose centroid lies farther from the axis than the disc's rim
// (bladeElementsAboveRadius; the built-in sector's one element block holds disc and
// blade together, the rim radius between them).
#include <cstdint>
#include <string>
#include <vector>

#include "cyclone/mesh/Mesh.hpp"
#include "cyclone/mesh/RotatedNodePairing.hpp"

namespace cyclone::mistuning {

struct BladeMistuning {
  /// Per blade j = 0..N-1 (sector j of the ring), E_j / E: 1 tuned.
  std::vector<double> youngsFactors;
  int blades() const { return int(youngsFactors.size()); }
  /// f_j - 1: the blade stiffness deviations (delta_j of MistuningPattern.hpp).
  std::vector<double> deviations() const;
  /// InputError naming mistuning/youngs_modulus_factors where there are not `blades`
  /// factors, or a factor is not finite or not positive (its blade named).
  void validate(int blades) const;
};

/// The factors as given (validated).
BladeMistuning youngsModulusFactors(std::vector<double> factors, int blades);
/// From the blade-alone frequency deviations delta_j = (w_j / w)^2 - 1: f_j = 1 + delta_j.
/// InputError naming mistuning/frequency_deviations (wrong length, NaN, delta_j <= -1).
BladeMistuning fromFrequencyDeviations(const std::vector<double>& deltas, int blades);
/// Random: delta_j from randomPattern(blades, sigma, seed), f_j = 1 + delta_j. InputError
/// naming mistuning/standard_deviation (negative, NaN, or a draw <= -1).
BladeMistuning randomBladeMistuning(int blades, double sigma, std::uint64_t seed);

/// The element set the blade is taken from when a scene or a caller names none.
inline const std::string kBladeElementSet = "blade";

/// The mesh's elements (global indices, ascending) whose centroid (mean of the element's
/// nodes) is farther than `radius` from the axis: for the built-in shrouded sector with
/// radius = ShroudedSectorParameters::rimRadius, the blade and its shroud (its mesh conforms
/// to the rim cylinder the blade is fused onto, so no element straddles it: checked in
/// disc_mistuned_ring). InputError naming "blade_elements" when none or every element is
/// found.
std::vector<mesh::Index> bladeElementsAboveRadius(const mesh::Mesh& mesh, const mesh::RotationAxis& axis,
                                                  double radius);

/// The blade's elements: the mesh's element set `setName`. InputError naming
/// mistuning/blade_element_set where the mesh has no such set or it is empty.
std::vector<mesh::Index> bladeElements(const mesh::Mesh& mesh, const std::string& setName = kBladeElementSet);

}  // namespace cyclone::mistuning
