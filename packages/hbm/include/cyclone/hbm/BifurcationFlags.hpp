#pragma once
// Special points along a traced curve of periodic solutions, from the
// parameter's path and Hill's Floquet exponents: turning points (folds), and
// where the stability changes without a fold, the kind of the crossing: a real
// exponent (branch point, e.g. symmetry breaking), a pair at +-i w/2 (period
// doubling) or any other complex pair (Neimark-Sacker, a torus). A turning
// point of the path where the stability is known on both sides and the same is
// no saddle-node fold (there one real exponent crosses zero): "turn", the
// continuation turned without a fold (a jump to another branch, or a stall).
#include <complex>
#include <string>
#include <vector>

namespace cyclone::hbm {

struct CurvePointStability {
  double parameter = 0;  ///< the continuation parameter
  double omega = 0;      ///< the fundamental frequency at the point
  int stable = -1;       ///< 1, 0, or -1 when not computed
  std::complex<double> leading;  ///< the Floquet exponent with the largest real part
  bool hasLeading = false;       ///< false when Hill's pick left none (a stable point)
};

/// One flag per point: "" or fold, turn, branch_point, period_doubling, neimark_sacker.
std::vector<std::string> bifurcationFlags(const std::vector<CurvePointStability>& points);

}  // namespace cyclone::hbm
