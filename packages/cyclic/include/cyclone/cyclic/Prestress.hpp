#pragma once
// Centrifugal prestress and the tangent it leaves for modal analysis.
// Linear: K u = f_Omega on the undeformed geometry; the modal tangent at speed
// Omega is then K + K_sigma(sigma(u)) - K_Omega (stress stiffening, spin
// softening). Nonlinear (NLGEOM): Total Lagrangian St Venant-Kirchhoff with the
// centrifugal load on the deformed position, f(u) = f_Omega + K_Omega u, solved
// by NOX's line search (backtracking) with Broyden directions started from the
// linear stiffness's factor, load stepping on Omega^2 and step cutting; the modal tangent is K_T(u) (material at the deformed state +
// geometric with the 2nd Piola-Kirchhoff stress) - K_Omega. Coriolis terms are neglected (a real symmetric eigenproblem; the
// travelling-wave splitting they cause is small for discs stiff in-plane).
// For a cyclic sector the prestress is solved with the k = 0 transform.
#include <array>
#include <vector>

#include "cyclone/fe/Assembler.hpp"

namespace cyclone::cyclic {

enum class PrestressKind { None, Linear, Nonlinear };

struct PrestressState {
  double speedRpm = 0;
  double omega = 0;  ///< rad/s
  mesh::RotationAxis axis;
  std::vector<std::array<double, 3>> displacement;                   ///< per node
  /// Per element at the stiffness-rule points: the small-strain stress (linear) or the
  /// Cauchy stress (nonlinear); what the output shows and the linear tangent uses.
  std::vector<Eigen::Matrix<double, Eigen::Dynamic, 6>> stress;
  bool nonlinear = false;
  int loadSteps = 0, newtonIterations = 0;
  int tangentFactorizations = 0;  ///< K_T factored (besides the linear stiffness)
  double solveSeconds = 0;
};

struct NonlinearPrestressOptions {
  int maxNewtonIterations = 20;
  double tolerance = 1e-10;     ///< ||residual|| / ||applied load||
  double initialLoadStep = 1.0; ///< fraction of Omega^2 tried first
  double minLoadStep = 1e-3;    ///< below this the speed is reported unreachable
};

/// Linear centrifugal prestress on the unknowns of `transform` (k = 0 for a sector).
PrestressState solveLinearPrestress(const mesh::Mesh& mesh, const fe::DofTransform& transform,
                                    const fe::IsotropicElastic& material, double speedRpm, const mesh::RotationAxis& axis,
                                    linalg::CommPtr comm);

/// Geometrically nonlinear centrifugal prestress. Throws SolverError naming the
/// highest speed reached when the full speed cannot be (e.g. buckling-like
/// softening or a step that fails however small).
PrestressState solveNonlinearPrestress(const mesh::Mesh& mesh, const fe::DofTransform& transform,
                                       const fe::IsotropicElastic& material, double speedRpm, const mesh::RotationAxis& axis,
                                       linalg::CommPtr comm, const NonlinearPrestressOptions& options = {});

/// Exodus file of a prestress state: nodal ux uy uz von_mises, element s_xx..s_xy and
/// von_mises (means over the integration points), one step at time = rpm.
void writePrestressExodus(const std::string& path, const mesh::Mesh& mesh, const PrestressState& state);

/// One element's modal tangent K, or K + K_sigma - K_Omega (linear prestress), or
/// K_T(u) - K_Omega (nonlinear) when a prestress is given; and its mass when M is given
/// (fe::elementModalMatrices: one pass per rule, nothing allocated).
void modalElementMatrices(const mesh::Mesh& mesh, mesh::Index e, fe::ElementType type, const fe::ElementCoords& X,
                          const fe::IsotropicElastic& material, const PrestressState* prestress, fe::ElementMatrix& K,
                          fe::ElementMatrix* M = nullptr);
/// The tangent alone.
fe::ElementMatrix tangentElementMatrix(const mesh::Mesh& mesh, mesh::Index e, fe::ElementType type,
                                       const fe::ElementCoords& X, const fe::IsotropicElastic& material,
                                       const PrestressState* prestress);

/// K (+ K_sigma - K_Omega when a prestress is given) on the assembler's unknowns.
Teuchos::RCP<linalg::Matrix> tangentStiffness(const fe::Assembler& assembler, const fe::IsotropicElastic& material,
                                              const PrestressState* prestress);

}  // namespace cyclone::cyclic
