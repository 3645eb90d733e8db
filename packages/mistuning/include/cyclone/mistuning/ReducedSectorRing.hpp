#pragma once
// The full ring of reduced sectors: the harmonic balance of all N sectors of a bladed disc
// at every sector's retained DOFs, its linear part the tuned sector's reduced models of
// every nodal diameter brought back to the physical sectors (RingReceptance.hpp), a
// friction contact between every pair of neighbouring sectors and the engine-order
// excitation on every blade (sector j's that of sector 0 delayed by j 2 pi EO / N). No
// cyclic constraint is imposed: tuned, its solution is the cyclic sector's on every blade
// (hbm::ringCoefficients), and a blade-to-blade scatter breaks that (mistuning, the
// ring's modal part: RingReceptance.hpp).
#include <memory>
#include <vector>

#include "cyclone/disc/DiscHarmonicBalance.hpp"
#include "cyclone/hbm/HarmonicBalanceSystem.hpp"
#include "cyclone/response/ForcedResponseSetup.hpp"

namespace cyclone::mistuning {

/// The nodal diameters 0..N/2: what disc::buildDiscReducedModels must be asked for so
/// that the ring has every phase (a tuned cyclic chain builds only those h EO reaches).
std::vector<int> everyNodalDiameter(int sectors);

/// The ring's system from a cyclic sector's in the receptance form: the linear part a
/// RingReceptance over the sector's model; every element of the sector once per sector j,
/// its W on sector j's DOFs and its W_next on sector j+1's (sector N-1's on sector 0's);
/// the excitation and static loads of sector j the sector's delayed by j 2 pi EO / N
/// (hbm::ringCoefficients). The same harmonics, samples and statement (dynamic stiffness
/// or compliance). InputError naming "ring" for a system not cyclic or in the matrix form
/// (hbm::expandToFullRing expands that one).
std::unique_ptr<hbm::HarmonicBalanceSystem> ringOfSectors(const hbm::HarmonicBalanceSystem& sector);
/// The same with `ringModel` as the ring's linear part in place of the RingReceptance over
/// the sector's model: a mistuned ring (MistunedRingReceptance), its DOFs in the same order
/// (sector j's at j n ..), so the sector's elements and excitation attach as in the tuned
/// ring. InputError naming "ring" for a model that is cyclic or of another size.
std::unique_ptr<hbm::HarmonicBalanceSystem> ringOfSectors(const hbm::HarmonicBalanceSystem& sector,
                                                          std::shared_ptr<const hbm::ReceptanceModel> ringModel);

/// The disc's ring and the cyclic sector it comes from.
struct DiscRing {
  /// The cyclic sector (disc::makeDiscForcedResponse, not condensed: its unknowns are the
  /// retained DOFs, as each of the ring's sectors').
  response::ForcedResponseSetup sector;
  /// The ring (ringOfSectors): output DOFs blade 0's, the continuation settings the sector's.
  response::ForcedResponseSetup ring;
  int sectors = 0, sectorDofs = 0;
  /// Per blade j, the sector's output DOFs in the ring (+ j sectorDofs).
  std::vector<std::vector<int>> bladeOutputDofs;
};

/// InputError naming reduced_model/nodal_diameters where the models lack a nodal
/// diameter of 0..N/2 (they are listed).
void checkRingModels(const disc::DiscReducedModels& models);

/// The disc's ring of reduced sectors for the response spec (contacts, excitation,
/// harmonics as disc::makeDiscForcedResponse reads them; spec.condensed is ignored).
DiscRing makeDiscRing(const mesh::Mesh& mesh, const disc::DiscReducedModels& models, const disc::DiscResponseSpec& spec,
                      double referenceHz = 1.0);

}  // namespace cyclone::mistuning
