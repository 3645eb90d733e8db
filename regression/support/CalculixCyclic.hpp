#pragma once
// CalculiX (ccx) on a cyclic sector as the independent reference of the modal chain:
// the mesh as a deck with *CYCLIC SYMMETRY MODEL, an optional *STATIC NLGEOM step
// with CENTRIF, and a perturbation *FREQUENCY step with *SELECT CYCLIC SYMMETRY
// MODES; run in a directory of its own with a given thread count, timed, its peak
// memory taken from the kernel (wait4), its frequencies read from the .dat file.
#include <map>
#include <string>
#include <vector>

#include "cyclone/fe/Material.hpp"
#include "cyclone/mesh/Mesh.hpp"

namespace cyclone::regression {

struct CalculixCyclicCase {
  std::string directory;                       ///< emptied and written
  std::vector<std::string> left, right;        ///< node sets of the two side faces
  std::string fixedSet = "bore";               ///< held in all directions, left out of the tie
  int sectors = 12;
  double rpm = 0;                              ///< > 0: NLGEOM prestress step first
  fe::IsotropicElastic material;
  int modesPerNd = 2;                          ///< distinct frequencies per nodal diameter
  int maxNd = 6;                               ///< nodal diameters 0..maxNd
  int threads = 1;
  /// Newton tolerances far below ccx's defaults (*CONTROLS, PARAMETERS=FIELD): the
  /// default leaves about 2e-4 in the prestressed frequencies of a cantilever sector.
  bool tightNewton = false;
};

struct CalculixCyclicRun {
  std::map<int, std::vector<double>> frequenciesHz;  ///< distinct, per nodal diameter
  double seconds = 0;
  double peakMemoryMb = 0;  ///< the kernel's high-water resident memory
  double peakPssMb = 0;     ///< sampled physical memory (MeasuredCommand.hpp)
};

/// Throws std::runtime_error naming the log when ccx fails.
CalculixCyclicRun runCalculixCyclic(const mesh::Mesh& mesh, const CalculixCyclicCase& c);

}  // namespace cyclone::regression
