#pragma once
// The disc's mistuned ring of reduced sectors by the subset of nominal modes
// (SubsetOfNominalModes.hpp), from the sector alone: the tuned sector's modes of every
// nodal diameter with their full shapes (cyclic::solveCyclicModes on the reduced models'
// sector, spec and prestress, the same modes the hybrid models keep at the retained
// DOFs), each phase's travelling-wave shape Phi_p = real + sign i imag of one mode of a
// pair (rom::SectorReceptance's sign), its retained rows U_p = G Phi_p, V_p = conj(U_p), and
// the hybrid model's constant part R_p (the tuned static correction, kept as it is: the
// method's approximation besides the modes' span); the blade elements' stiffness projected
// element by element, Phi^H K_blade Phi = sum_e Phi_e^H K_e Phi_e (the element stiffness at
// the spec's E; the prestress' geometric stiffness is not scaled), and the pattern's
// Young's modulus factors f_j through delta_j = f_j - 1.
#include <memory>
#include <vector>

#include "cyclone/disc/DiscReducedModels.hpp"
#include "cyclone/hbm/ModalReceptance.hpp"
#include "cyclone/mistuning/BladeMistuning.hpp"
#include "cyclone/mistuning/RingReceptance.hpp"
#include "cyclone/mistuning/SubsetOfNominalModes.hpp"

namespace cyclone::mistuning {

/// The tuned sector's modes per phase index 0..N-1, with their full shapes.
struct DiscNominalModes {
  int sectors = 0;
  /// Per phase p: the modal realization at the retained DOFs (U = G Phi_p, V = conj(U), l,
  /// the hybrid model's R, its loss factor), as a cyclic model.
  std::shared_ptr<const hbm::ModalReceptance> sectorModel;
  /// Per phase p: Phi_p, 3 x nodes rows (node-major x, y, z, sector 0's frame) x m_p.
  std::vector<Eigen::MatrixXcd> shapes;
  std::vector<int> modesPerPhase;
  double seconds = 0;
};

/// InputError naming reduced_model/nodal_diameters where a nodal diameter of 0..N/2 is
/// missing (checkRingModels), reduced_model/kind for models without a modal form (not
/// hybrid), reduced_model/retained_means where the models retain weighted means (not
/// supported here). Error where a pair's frequencies are degenerate beyond a pair.
DiscNominalModes discNominalModes(const mesh::Mesh& mesh, const disc::DiscReducedModels& models,
                                  const disc::DiscModelSpec& spec, linalg::CommPtr comm);

/// Phi^H K_blade Phi over `shapes` stacked phase by phase: the element stiffness of each
/// of `bladeElements` (mesh's global indices) at `material`, its rows of the shapes.
Eigen::MatrixXcd bladeModalProjection(const mesh::Mesh& mesh, const std::vector<mesh::Index>& bladeElements,
                                      const fe::IsotropicElastic& material, const std::vector<Eigen::MatrixXcd>& shapes);

struct DiscMistunedRing {
  std::shared_ptr<const RingReceptance> tuned;             ///< over nominal.sectorModel
  std::shared_ptr<const MistunedRingReceptance> mistuned;  ///< the pattern's
  Eigen::MatrixXcd bladeProjection;                        ///< for other patterns of the same disc
  std::vector<int> modesPerPhase;
};

/// The ring (every sector's retained DOFs, RingReceptance's order) tuned and with the
/// pattern (validated against N: InputError naming mistuning/youngs_modulus_factors).
DiscMistunedRing makeDiscMistunedRing(const mesh::Mesh& mesh, const DiscNominalModes& nominal,
                                      const fe::IsotropicElastic& material,
                                      const std::vector<mesh::Index>& bladeElements, const BladeMistuning& pattern);

}  // namespace cyclone::mistuning
