#pragma once
// Each shroud contact's law from the spec (ShroudContactSpec::Law): per pair as given, or
// per unit area, the pair's share of the interface by the tributary area of its right-face
// node. A contact is a node pair, or a patch of them (ShroudContactSpec::patches): the
// patch's law is the sum of its pairs', on their mean motion (ShroudContactPatches.hpp).
#include <string>
#include <vector>

#include "cyclone/disc/DiscHarmonicBalance.hpp"
#include "cyclone/mesh/RotatedNodePairing.hpp"
#include "cyclone/rom/RetainedDofs.hpp"

namespace cyclone::disc {

struct ShroudContactValues {
  /// Per contact: its node pairs (indices into the pairing) and the weights of their
  /// motions in the contact's (summing to 1: by tributary area for PerArea, equal for
  /// PerPair). Without patches each contact is one pair of weight 1.
  std::vector<std::vector<int>> members;
  std::vector<std::vector<double>> memberWeights;
  std::vector<double> area;             ///< per contact, mm^2 (Law::PerArea; empty for PerPair)
  std::vector<double> kn, kt, preload;  ///< per contact: N/mm, N/mm, N
  int pairs = 0;                        ///< node pairs over all contacts
  double totalArea = 0;                 ///< the interface's (Law::PerArea)
  double totalKn = 0, totalKt = 0, totalPreload = 0;  ///< sums over the contacts
  /// What multiplies the spec's preload and stiffness to give each contact's (its area's
  /// share and its area for PerArea, its number of pairs for PerPair): a study of the
  /// spec's preload or stiffness moves each contact's by these.
  std::vector<double> preloadFactor, stiffnessFactor;
  std::string text;  ///< one line: the law, the patches and the interface's totals
};

/// InputError naming `contact` for a negative or non-finite value, (PerArea or patches)
/// where the right set's nodes do not make a surface (mesh::tributaryAreas), and
/// `contact/patches` for more patches than pairs.
ShroudContactValues shroudContactValues(const mesh::Mesh& mesh, const mesh::NodePairing& pairs,
                                        const ShroudContactSpec& contact);

/// The patches' mean motions a reduced model retains in place of every face node (two per
/// patch: "patch c right" of its right-face nodes, then "patch c left" of the left-face
/// ones, by the pairs' weights in the patch): with 27 patches the static correction solves
/// 162 load cases where it solved one per face node DOF (1929 at the seed's mesh size).
/// InputError naming `contact/patches` when the spec has none.
std::vector<rom::RetainedMean> shroudPatchMeans(const mesh::NodePairing& pairs, const ShroudContactValues& values,
                                                const ShroudContactSpec& contact);

/// `models` made to retain the contact patches' mean motions (shroudPatchMeans) in place
/// of the contact faces' nodes, whose node sets leave models.retainedNodeSets.
/// InputError naming `contact_dofs` for a contact without patches, `retained_node_sets`
/// where only the contact faces were retained (nothing would be left for the excitation).
DiscModelSpec retainingPatchMeans(DiscModelSpec models, const mesh::Mesh& mesh, const ShroudContactSpec& contact);

}  // namespace cyclone::disc
