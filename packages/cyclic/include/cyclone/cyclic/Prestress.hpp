#pragma once
// Centrifugal prestress and the tangent it leaves for modal analysis.
// Linear: K u = f_Omega on the undeformed geometry; the modal tangent at speed
// Omega is then K + K_sigma(sigma(u)) - K_Omega (stress stiffening, spin
// softening). Coriolis terms are neglected (a real symmetric eigenproblem; the
// travelling-wave splitting they cause is small for discs stiff in-plane).
// For a cyclic sector the prestress is solved with the k = 0 transform.
#include <array>
#include <vector>

#include "cyclone/fe/Assembler.hpp"

namespace cyclone::cyclic {

enum class PrestressKind { None, Linear };

struct PrestressState {
  double speedRpm = 0;
  double omega = 0;  ///< rad/s
  fe::Axis axis;
  std::vector<std::array<double, 3>> displacement;                   ///< per node
  std::vector<Eigen::Matrix<double, Eigen::Dynamic, 6>> stress;      ///< per element, at stiffness-rule points
  double solveSeconds = 0;
};

/// Linear centrifugal prestress on the unknowns of `transform` (k = 0 for a sector).
PrestressState solveLinearPrestress(const mesh::Mesh& mesh, const fe::DofTransform& transform,
                                    const fe::IsotropicElastic& material, double speedRpm, const fe::Axis& axis,
                                    linalg::CommPtr comm);

/// Exodus file of a prestress state: nodal ux uy uz von_mises, element s_xx..s_xy and
/// von_mises (means over the integration points), one step at time = rpm.
void writePrestressExodus(const std::string& path, const mesh::Mesh& mesh, const PrestressState& state);

/// K (+ K_sigma - K_Omega when a prestress is given) on the assembler's unknowns.
Teuchos::RCP<linalg::Matrix> tangentStiffness(const fe::Assembler& assembler, const fe::IsotropicElastic& material,
                                              const PrestressState* prestress);

}  // namespace cyclone::cyclic
