#pragma once
// The HDF5 form of a forced-response curve: every converged point's full
// coefficient vector, so a curve can be post-processed or restarted without
// recomputing it. Schema (docs/scenes.md):
//   /omega            [P]            excitation frequency, rad/s
//   /coefficients     [P x n*nc]     X[dof * nc + c], coefficient order of /harmonics
//   /harmonics        [H]            the harmonic numbers ([x0] then [cos, sin] per h > 0)
//   /stable           [P]            1 stable, 0 unstable, -1 not computed, 2 undetermined (Hill's verdict changes with 2x AFT samples)
//   /parameter        [P]            the continuation parameter (= /omega, or the force scale)
//   /segment          [P]            the sweep each point belongs to (0; 1 for a second sweep from
//                                    the range's end when the first folded back to its start)
//   attributes on /: num_dofs, num_coefficients, samples
#include <Eigen/Dense>
#include <string>
#include <vector>

namespace cyclone::io {

struct ResponseCurve {
  int numDofs = 0, numCoefficients = 0, samples = 0;
  std::vector<int> harmonics;
  std::vector<double> omega;
  std::vector<double> parameter;  ///< empty: the same as omega
  std::vector<Eigen::VectorXd> coefficients;
  std::vector<int> stable;
  std::vector<int> segment;  ///< empty on writing: all 0
};

/// Written under a temporary name and renamed when complete.
void writeResponseCurveHdf5(const std::string& path, const ResponseCurve& curve);
ResponseCurve readResponseCurveHdf5(const std::string& path);

}  // namespace cyclone::io
