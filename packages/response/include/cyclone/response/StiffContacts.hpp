#pragma once
// Friction contacts far stiffer than the system they join, named: a contact's kt or kn
// against the system's own stiffness along the element's coordinate. A tangential
// stiffness far above it makes the contact stick and slip within a tiny fraction of a
// period (rigid-plastic in effect), which the samples cannot place, and the balance finds
// no start; the failure said so at length without naming the value behind it. The same
// for a cubic spring's k3 against the system at the linear response's amplitude.
#include <string>
#include <vector>

#include "cyclone/response/ForcedResponseSetup.hpp"

namespace cyclone::response {

struct StiffContact {
  int element = 0;          ///< index into system->elements() (and setup.elementNames)
  std::string parameter;    ///< kt or kn
  double stiffness = 0;     ///< the contact's
  double systemStiffness = 0;  ///< w^T K w / w^T w along the coordinate (w: its column of W)
  double value = 0;            ///< the parameter's value (a contact's kt or kn: its stiffness; a cubic spring's k3)
  double amplitude = 0;        ///< a cubic spring's: the linear response's along its direction
  double ratio() const { return stiffness / systemStiffness; }
};

/// The friction contacts' kt (each tangential coordinate, the stiffest) and kn above
/// `ratio` times the system's K along the coordinate, stiffest first. A coordinate along
/// which K is zero or negative is skipped (no scale to compare with).
std::vector<StiffContact> stiffContacts(const ForcedResponseSetup& setup, double ratio);

/// The cubic springs whose stiffness 3 k3 a^2 at the amplitude a of the linear response
/// (the system without its elements, at frequency omega) along their direction is above
/// `ratio` times the system's K there (parameter k3, stiffness 3 k3 a^2): k3 = 1e300 on the
/// Duffing scene found no start and named nothing (a fifth probe), its response a scale
/// the unknowns, made on the linear response, do not reach. Matrix form only (else none).
std::vector<StiffContact> stiffCubicSprings(const ForcedResponseSetup& setup, double omega, double ratio);

}  // namespace cyclone::response
