#pragma once
// The cyclic modes of a sector over a list of speeds: at each speed the centrifugal
// prestress (linear or geometrically nonlinear, on the k = 0 transform) and the modes
// of every requested nodal diameter on its prestressed tangent. What a Campbell and a
// SAFE diagram are drawn from (post::trackFamilies, post::findResonances).
#include <functional>
#include <vector>

#include "cyclone/cyclic/CyclicModalAnalysis.hpp"
#include "cyclone/cyclic/Prestress.hpp"

namespace cyclone::cyclic {

struct ModalSweepProblem {
  CyclicModalProblem modes;  ///< its `prestress` is set per speed
  std::vector<double> speedsRpm{0.0};  ///< non-negative, increasing
  PrestressKind prestress = PrestressKind::Linear;  ///< None, or at 0 rpm: the unstressed K
  mesh::RotationAxis axis;  ///< the rotation axis of the centrifugal load
};

/// Called after each speed with its prestress (null when none) and modes, e.g. to write
/// them while the sweep goes on; the state lives only during the call.
using ModalSweepVisitor = std::function<void(const PrestressState* prestress, const SpeedModes& modes)>;

/// The modes at every speed (InputError naming speeds_rpm for negative or non-increasing
/// speeds, as solveCyclicModes for the rest).
std::vector<SpeedModes> solveModalSweep(const mesh::Mesh& mesh, const CyclicSector& sector,
                                        const ModalSweepProblem& problem, linalg::CommPtr comm,
                                        const ModalSweepVisitor& visit = {});

}  // namespace cyclone::cyclic
