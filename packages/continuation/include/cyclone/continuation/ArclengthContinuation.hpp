#pragma once
// Pseudo-arclength continuation of a dense nonlinear system F(x; p) = 0 in one
// parameter p, through turning points, with LOCA (LOCA::LAPACK: the harmonic
// balance systems of reduced models are dense and small). Newton by NOX inside
// each step; the step size adapts and is cut when Newton fails or the residual
// throws; the branch up to a failure is kept.
#include <Eigen/Dense>
#include <functional>
#include <string>
#include <vector>

namespace cyclone::continuation {

struct ContinuationProblem {
  int size = 0;
  /// F(x; p). Throwing counts as a failed evaluation (the step is cut).
  std::function<void(const Eigen::VectorXd& x, double p, Eigen::VectorXd& F)> residual;
  /// dF/dx(x; p), size x size.
  std::function<void(const Eigen::VectorXd& x, double p, Eigen::MatrixXd& J)> jacobian;
};

struct ContinuationOptions {
  double from = 0, to = 1;          ///< parameter range (either direction)
  double initialStep = 0.01;        ///< arclength units (scaled with the solution)
  double minStep = 1e-6, maxStep = 0.05;
  int maxSteps = 5000;
  double tolerance = 1e-10;         ///< Newton: ||F||_2
  int maxNewtonIterations = 15;
  /// LOCA's rescaling of the parameter against the unknowns in the arclength. Off for
  /// unknowns scaled to order one beforehand (the FE disc): LOCA's rescaling then
  /// shrank the steps near a resonance to a creep (2000 points short of the peak).
  bool arcLengthScaling = true;
  /// Stop a run that goes back along its own path for a few points (BranchTurn.hpp),
  /// or whose step fell below the minimum, and try a step over the kink (at a fixed
  /// parameter, then a secant arclength step); the curve ends with that reason if
  /// neither passes. Off by default: a true fold whose two halves nearly coincide (the
  /// force ramp of NLvib's example 03) looks the same. On for the FE disc scenes,
  /// whose H = 3 curve LOCA otherwise walked back to the start, calling it finished.
  bool stopWhereItTurnsBack = false;
  /// Drop a point whose step is far longer than the step before it (BranchTurn.hpp:
  /// branchJump: the corrector left the predictor's neighbourhood for another branch)
  /// and restart from the last point with a quarter of the step; after 6 restarts
  /// without progress the curve ends there with that reason.
  bool restartWhereTheCorrectorJumps = true;
  /// NOX's line search in LOCA's corrector. Full steps are LOCA's default; a
  /// backtracking or polynomial line search can keep Newton from cycling at the
  /// kinks of many friction contacts (docs/scenes.md: the default disc at H = 3).
  enum class LineSearch { FullStep, Backtrack, Polynomial };
  LineSearch lineSearch = LineSearch::FullStep;
};

struct BranchPoint {
  double parameter;
  Eigen::VectorXd x;
};

struct Branch {
  std::vector<BranchPoint> points;
  bool finished = false;  ///< reached the end of the range
  std::string stopReason;
  int failedSteps = 0;
  /// The branch folded back and ran out at the bound it started from; `reached` is the
  /// farthest parameter it got to (the range beyond was not traced).
  bool returnedToStart = false;
  double reached = 0;
  /// Where later segments start in `points` (empty: one segment). A curve traced again
  /// from the other end of the range (scenes::traceForcedResponse) is a second segment:
  /// consecutive points across a start are not neighbours on a path.
  std::vector<std::size_t> segmentStarts;
};

/// Traces from x0 (a solution, or a good guess, at p = options.from; it is
/// corrected by solveNewton (NewtonSolve.hpp) before LOCA takes it, whose first Newton solve has no
/// line search).
Branch traceBranch(const ContinuationProblem& problem, const Eigen::VectorXd& x0, const ContinuationOptions& options);

}  // namespace cyclone::continuation
