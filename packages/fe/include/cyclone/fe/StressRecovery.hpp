#pragma once
// Stresses from a displacement field: the mean small-strain Cauchy stress of
// each element over its integration points, and nodal values averaged from
// the elements around a node (what a Goodman diagram's mean stress needs).
#include <array>
#include <vector>

#include "cyclone/fe/Assembler.hpp"

namespace cyclone::fe {

struct StressField {
  std::vector<std::array<double, 6>> elementStress;  ///< Voigt xx yy zz yz xz xy, global element order
  std::vector<double> elementVonMises;
  std::vector<std::array<double, 6>> nodalStress;    ///< averaged over adjacent elements
  std::vector<double> nodalVonMises;
};

/// Nodal values as the mean of the adjacent elements' values (global element order);
/// nodes in no element get zero.
std::vector<std::array<double, 6>> averageToNodes(const mesh::Mesh& mesh,
                                                  const std::vector<std::array<double, 6>>& elementValues);

/// Same result on every rank (each element is evaluated by the rank that assembles it).
StressField recoverStresses(const Assembler& assembler, const IsotropicElastic& material,
                            const std::vector<std::array<double, 3>>& nodalDisplacement);

}  // namespace cyclone::fe
