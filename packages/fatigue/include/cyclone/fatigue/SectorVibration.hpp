#pragma once
// The whole sector's vibration at one point of a forced-response curve (the
// friction-damped peak, say) and the fatigue margin it leaves.
//
// Each time harmonic h of the harmonic balance solution travels around the disc
// with the phase index p_h = h EO mod N; the forces it puts on the reduced
// model's retained DOFs (hbm::harmonicLoads: excitation, contact forces) drive
// the full FE sector of that nodal diameter in one complex solve
// (rom::NodalDiameterModel::fieldResponse), harmonic 0 the undamped static one.
// That is the exact field under those forces, not a modal expansion: its value
// at the retained DOFs differs from the harmonic balance solution only by the
// reduced model's error, which `retainedResponse` lets the caller report.
// Stresses per harmonic are the small-strain stresses of the real and imaginary
// fields on the undeformed geometry (the vibration about the prestressed state
// is small), averaged from the elements to the nodes; the mean stress is the
// prestress (when given) plus harmonic 0's stress.
#include <memory>
#include <vector>

#include "cyclone/fatigue/GoodmanHaigh.hpp"
#include "cyclone/fatigue/StressCycle.hpp"
#include "cyclone/hbm/HarmonicLoads.hpp"
#include "cyclone/rom/NodalDiameterModel.hpp"

namespace cyclone::fatigue {

struct SectorVibration {
  double omega = 0;                                        ///< the fundamental (rad/s)
  std::vector<int> harmonics;                              ///< per entry below: the time harmonic
  std::vector<int> nodalDiameters;                         ///< and its nodal diameter
  std::vector<std::vector<Eigen::Vector3cd>> displacement; ///< per harmonic, per node: Re(U e^{i h w t})
  std::vector<std::vector<ComplexVoigt>> stress;           ///< per harmonic, per node (harmonic 0: real)
  std::vector<Voigt> prestress;                            ///< per node; zero without a prestress
  std::vector<Eigen::VectorXcd> retainedResponse;          ///< per harmonic: the field at the retained DOFs
  double seconds = 0;

  /// The displacement at phase theta = w t, per node (harmonic 0 included).
  std::vector<Eigen::Vector3d> displacementAt(double theta) const;
  /// The mean stress of a node: prestress + harmonic 0.
  Voigt meanStress(std::size_t node) const;
  /// The harmonics h >= 1 of a node's stress.
  std::vector<HarmonicStress> alternatingStress(std::size_t node) const;
};

/// `problem`: the models' inputs (material, held sets, retained sets, loss factor,
/// prestress; its harmonic is set per load). `loads`: on the retained DOFs of one copy, in
/// the order of problem.retainedNodeSets' DOFs.
SectorVibration recoverSectorVibration(const mesh::Mesh& mesh, const cyclic::CyclicSector& sector,
                                       rom::NodalDiameterModelProblem problem, const std::vector<hbm::HarmonicLoad>& loads,
                                       double omega, linalg::CommPtr comm);

/// Per node: the cycle's measures and the Goodman-Haigh safety factor (alternating
/// von Mises against the signed mean von Mises); the critical node is the one with
/// the smallest factor.
struct FatigueMap {
  std::vector<CycleMeasures> cycle;
  std::vector<double> safetyFactor;
  std::size_t critical = 0;
  /// The nodes by safety factor, smallest (worst) first; equal factors in node order.
  std::vector<std::size_t> nodesWorstFirst() const;
};
FatigueMap assessFatigue(const SectorVibration& vibration, const FatigueMaterial& material, int samples = 64);

}  // namespace cyclone::fatigue
