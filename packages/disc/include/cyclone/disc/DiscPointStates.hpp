#pragma once
// What the shroud contacts and the output DOFs do at one point of a disc curve (its
// peak): per contact the energy friction dissipates per cycle, the mean normal force and
// the first harmonic's slip amplitude; the hysteresis loops of chosen contacts over one
// period from the sampled contact law; the output DOFs over that period. Values for a
// calling program; post/DiscPointFiles.hpp writes them.
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "cyclone/disc/DiscPeakVibration.hpp"
#include "cyclone/hbm/ElementStates.hpp"

namespace cyclone::disc {

struct ContactAtPoint {
  double energyPerCycle = 0;   ///< the work the contact force does on the relative motion over one period
  double meanNormalForce = 0;  ///< the zeroth harmonic of the normal (last) coordinate's force
  /// The first harmonic's tangential amplitude: sqrt of the sum over the tangential
  /// coordinates of cos^2 + sin^2 (0 for a gap element, which has none).
  double slipAmplitude = 0;
};

/// A contact's loop: its relative motion w and force f over one period (N x d samples,
/// the normal coordinate last), from the sampled law.
struct ContactLoop {
  int contact = 0;
  hbm::ElementPeriod period;
};

struct DiscPointStates {
  double omega = 0;                     ///< rad/s
  std::vector<ContactAtPoint> contacts;  ///< one per nonlinear element, in the system's order
  int mostDissipating = -1;              ///< the contact that dissipates most
  std::vector<ContactLoop> loops;        ///< the chosen contacts' loops
  std::vector<double> phase;             ///< t / T of the period's samples, 0..(N-1)/N
  Eigen::MatrixXd response;              ///< N x outputs: the output DOFs over one period
};

/// The contacts and outputs at `point` of a disc curve whose setup is `setup` (its output
/// DOFs). `loopContacts`: the contacts whose loops are wanted (empty: the one that
/// dissipates most); InputError naming one that is not a contact of the system.
DiscPointStates discPointStates(const response::ForcedResponseSetup& setup, const PeakPoint& point,
                                const std::vector<int>& loopContacts);

}  // namespace cyclone::disc
