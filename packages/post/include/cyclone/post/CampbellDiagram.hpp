#pragma once
// Campbell and SAFE (ZZENF) diagrams from cyclic modes at several speeds.
// Modes are grouped into families per nodal diameter (a travelling-wave pair
// is one family) and tracked across speeds by subspace MAC, not by order, so a
// branch follows its mode shape through veerings and crossings.
#include <string>
#include <vector>

#include "cyclone/cyclic/CyclicModalAnalysis.hpp"

namespace cyclone::post {

struct Branch {
  int nd = 0;
  int family = 0;  ///< 1-based, the order at the first speed
  std::vector<double> rpm, freqHz;
  double worstMac = 1;  ///< lowest MAC along the tracking (low: the branch veered)
};

/// Needs the same nodal diameters and mode counts at every speed (the scene guarantees it).
std::vector<Branch> trackFamilies(const std::vector<cyclic::SpeedModes>& speeds);

/// Nodal diameter an engine order excites in an N-sector disc: EO mod N folded into 0..N/2.
int foldEngineOrder(int engineOrder, int sectors);

struct Resonance {
  int engineOrder, nd, family;
  double rpm, freqHz;
};
/// Crossings of each branch at ND = fold(EO) with the line f = EO rpm / 60, by linear
/// interpolation between the computed speeds (no extrapolation beyond them).
std::vector<Resonance> findResonances(const std::vector<Branch>& branches, int sectors,
                                      const std::vector<int>& engineOrders);

/// Family-subspace MAC between the modes of one nodal diameter at two speeds
/// (rows: families at `a`, columns: families at `b`); a pair counts as one family.
Eigen::MatrixXd familyMac(const cyclic::NodalDiameterModes& a, const cyclic::NodalDiameterModes& b);

void writeCampbellCsv(const std::string& path, const std::vector<Branch>& branches);
void writeResonancesCsv(const std::string& path, const std::vector<Resonance>& resonances);
/// Frequency vs rpm, one line per branch (coloured by ND), dashed engine-order lines.
void writeCampbellSvg(const std::string& path, const std::vector<Branch>& branches,
                      const std::vector<int>& engineOrders, const std::vector<Resonance>& resonances);
/// Frequency vs ND at the lowest and highest speed per family, the engine orders'
/// zig-zag lines at the highest speed, and the resonances.
void writeSafeSvg(const std::string& path, const std::vector<Branch>& branches, int sectors,
                  const std::vector<int>& engineOrders, const std::vector<Resonance>& resonances);

}  // namespace cyclone::post
