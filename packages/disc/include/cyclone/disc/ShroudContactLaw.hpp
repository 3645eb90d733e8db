#pragma once
// Each shroud contact pair's law from the spec (ShroudContactSpec::Law): per pair as
// given, or per unit area, the pair's share of the interface by the tributary area of its
// right-face node.
#include <string>
#include <vector>

#include "cyclone/disc/DiscHarmonicBalance.hpp"
#include "cyclone/mesh/RotatedNodePairing.hpp"

namespace cyclone::disc {

struct ShroudContactValues {
  std::vector<double> area;             ///< per pair, mm^2 (Law::PerArea; empty for PerPair)
  std::vector<double> kn, kt, preload;  ///< per pair: N/mm, N/mm, N
  double totalArea = 0;                 ///< the interface's (Law::PerArea)
  double totalKn = 0, totalKt = 0, totalPreload = 0;  ///< sums over the pairs
  /// The preload's share of each pair (its area's for PerArea, 1 / pairs for PerPair) and
  /// the stiffness's factor (its area for PerArea, 1 for PerPair): a study of the spec's
  /// preload or stiffness moves each pair's by these.
  std::vector<double> preloadShare, stiffnessFactor;
  std::string text;  ///< one line: the law and the interface's totals
};

/// InputError naming `contact` for a negative or non-finite value, and (PerArea) where
/// the right set's nodes do not make a surface (mesh::tributaryAreas).
ShroudContactValues shroudContactValues(const mesh::Mesh& mesh, const mesh::NodePairing& pairs,
                                        const ShroudContactSpec& contact);

}  // namespace cyclone::disc
