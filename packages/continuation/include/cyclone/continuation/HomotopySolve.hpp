#pragma once
// A solution of F(x; p) = 0 at a fixed parameter from a guess that already solves
// all but some equations: a harmonic balance solution carried to one more harmonic
// (the new harmonic's coefficients zero, the old equations holding). Newton from
// such a guess stalls at the kinks of a friction system (the default disc's peak
// carried from H = 3 to 4 found no solution), so the added equations are switched
// on gradually: the homotopy
//   G_i(x; s) = F_i(x; p)                                 (the other rows)
//   G_i(x; s) = s F_i(x; p) + (1 - s) c (x_i - x0_i)       (the added rows i)
// is solved by x0 at s = 0 and is F at s = 1; the predictor-corrector traces it
// through the folds in s that plain Newton cannot pass. c is the added rows'
// typical diagonal of dF/dx, so both parts weigh alike. Before the homotopy, the
// added unknowns are solved with the others held (Newton on the added rows alone);
// where those rows then hold, Newton on the whole starts from there, and where it
// still fails the homotopy does, x0 being that block solution (on the default disc
// H = 3 is then reached by Newton alone, H = 4 by a homotopy of 8 points instead of
// 51).
#include <string>
#include <vector>

#include "cyclone/continuation/NewtonSolve.hpp"

namespace cyclone::continuation {

struct HomotopyResult {
  NewtonResult newton;   ///< the last Newton solve at s = 1 (converged: x solves F)
  /// Plain Newton from x0 failed and the added unknowns were solved with the others
  /// held (their rows then hold); Newton, or the homotopy, went on from there.
  bool blockStart = false;
  bool byHomotopy = false;  ///< plain Newton from x0 failed and the homotopy was traced
  int points = 0;        ///< points of the homotopy path (0 when Newton sufficed)
  std::string reason;    ///< why no solution was found (empty when converged)
};

/// `added`: the indices of the added equations, the same as the added unknowns (a
/// square layout, as in the harmonic balance). Updates x in place: the solution, or
/// on failure the farthest point of the homotopy path.
HomotopyResult solveByHomotopy(const ContinuationProblem& problem, Eigen::VectorXd& x, double p,
                               const std::vector<int>& added, double tolerance);

}  // namespace cyclone::continuation
