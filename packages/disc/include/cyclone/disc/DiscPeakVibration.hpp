#pragma once
// The disc's vibration at one point of its forced response: the point (the harmonics
// check's highest level found at the peak, else the traced point nearest it, or a chosen
// frequency of the curve), the whole sector's field there by a full FE solve per
// harmonic under the loads the harmonic balance solution puts on the retained DOFs
// (fatigue::recoverSectorVibration), its stresses and, given fatigue data, the
// Goodman-Haigh margin per node.
#include <memory>
#include <optional>
#include <string>

#include <Eigen/Dense>

#include "cyclone/disc/DiscReducedModels.hpp"
#include "cyclone/fatigue/GoodmanHaigh.hpp"
#include "cyclone/fatigue/SectorVibration.hpp"
#include "cyclone/response/ForcedResponse.hpp"

namespace cyclone::disc {

/// A solution of the reference curve's system (or of it raised to more harmonics).
struct PeakPoint {
  std::unique_ptr<hbm::HarmonicBalanceSystem> raised;  ///< owns `system` when raised
  const hbm::HarmonicBalanceSystem* system = nullptr;
  Eigen::VectorXd x;
  double omega = 0;
  std::string what;  ///< "the peak with harmonics 0..4 at 1397.8 Hz", for titles and summaries
  /// Empty when the point is converged in the harmonics to 1 %; else why it is an estimate,
  /// for every number computed at it.
  std::string caveat;
};
/// The harmonics check's highest level found (its system raised to those harmonics),
/// else the traced point nearest the located peak with the curve's own system.
PeakPoint referencePeakPoint(response::ForcedResponseSetup& setup, const response::ForcedResponseResult& reference);
/// The reference curve's solution at `hz` (its harmonics): Newton at that frequency from the
/// traced point nearest it (on a fold, the branch that point is on); SolverError when
/// Newton does not converge, InputError when hz lies outside the traced points.
PeakPoint referencePointAt(response::ForcedResponseSetup& setup, const response::ForcedResponseResult& reference,
                           double hz);

struct DiscPeakVibration {
  fatigue::SectorVibration vibration;       ///< per harmonic the whole field, stresses, prestress
  std::optional<fatigue::FatigueMap> fatigue;  ///< per node the cycle's measures and safety factor
  /// The field at the retained DOFs against the harmonic balance solution there, relative to
  /// its largest motion: the reduced model's error at this point.
  double modelError = 0;
  int harmonics = 0;
};
/// The sector's vibration at `point` (forces scaled by excitationScale), on the models'
/// prestress; with `margin` the Goodman-Haigh map.
DiscPeakVibration solveDiscPeakVibration(const mesh::Mesh& mesh, const DiscReducedModels& models,
                                         const DiscModelSpec& modelSpec, const PeakPoint& point,
                                         double excitationScale, const fatigue::FatigueMaterial* margin,
                                         linalg::CommPtr comm);

}  // namespace cyclone::disc
