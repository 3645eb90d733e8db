#pragma once
// Continuation of a dense nonlinear system F(x; p) = 0 in one parameter p,
// through turning points and the corners of friction contacts, by one of two
// engines (docs/architecture.md, "Continuation"):
//  - Cyclone's predictor-corrector (PredictorCorrector.cpp; the default): unknowns
//    scaled by their current size, a tangent predictor, a pseudo-arclength corrector
//    with a spherical one as the fallback at sharp turns, steps from Newton's
//    iteration count and the turning angle;
//  - LOCA's stepper (LOCA::LAPACK, LocaContinuation.cpp): a
//    hyperplane corrector and LOCA's adaptive step, with kink bridging around it.
// The branch up to a failure is kept, with the reason it stopped.
#include <Eigen/Dense>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cyclone/continuation/JacobianOperator.hpp"
#include "cyclone/continuation/KrylovSolve.hpp"

namespace cyclone::continuation {

class TraceCheckpoints;  // TraceCheckpoint.hpp

struct ContinuationProblem {
  int size = 0;
  /// F(x; p). Throwing counts as a failed evaluation (the step is cut).
  std::function<void(const Eigen::VectorXd& x, double p, Eigen::VectorXd& F)> residual;
  /// dF/dx(x; p), size x size.
  std::function<void(const Eigen::VectorXd& x, double p, Eigen::MatrixXd& J)> jacobian;
  /// Optional response measure g(x) (e.g. the peak magnitude of a response DOF). The
  /// predictor-corrector locates each local maximum of g along the path to 1e-5 of
  /// the steps around it and adds it as a point: a curve's peak is then a solution,
  /// not the best of its samples.
  std::function<double(const Eigen::VectorXd& x)> measure;
  /// Optional, per unknown: the group whose own size scales it in the predictor-
  /// corrector's arclength (empty: one group). A harmonic balance puts its mean
  /// coefficients in one group and the oscillating ones in another: a preload's static
  /// deformation is no longer the yardstick of the vibration, so a step cannot leap
  /// over a sharp resonance whose motion is small beside it.
  std::vector<int> scaleGroups;
  /// Optional dF/dp(x; p): LOCA's engine uses it instead of its difference in p (one
  /// evaluation of F per Newton iteration of its corrector).
  std::function<void(const Eigen::VectorXd& x, double p, Eigen::VectorXd& dFdp)> parameterDerivative;
  /// Optional: dF/dx(x; p) as an operator with a preconditioner, never formed
  /// (JacobianOperator.hpp). Where the options choose Krylov (useKrylov), the
  /// predictor-corrector's and solveNewton's steps are GMRES solves with it, and
  /// `jacobian` is not called.
  std::function<std::shared_ptr<JacobianOperator>(const Eigen::VectorXd& x, double p)> jacobianOperator;
};

struct ContinuationOptions {
  /// Cyclone's predictor-corrector by default (fewer points on every shipped scene but
  /// one, docs/scenes.md); LOCA stays selectable (docs/architecture.md, "Continuation").
  enum class Engine { PredictorCorrector, Loca };
  Engine engine = Engine::PredictorCorrector;
  double from = 0, to = 1;          ///< parameter range (either direction)
  /// Arclength steps. PredictorCorrector: in the scaled (x / ||x||, p / |to - from|)
  /// space, so 0.1 is a tenth of the range or a 10 % change of the solution. Loca: in
  /// LOCA's units (the unknowns' RMS and the parameter); locaOptions() gives LOCA's
  /// defaults. The predictor-corrector's maximum is long: the turn of the tangent and
  /// Newton's effort shorten the steps where the curve needs them, and each local
  /// maximum of the measure is located on the curve whatever the step.
  double initialStep = 0.01;
  double minStep = 1e-6, maxStep = 0.2;
  int maxSteps = 5000;
  /// PredictorCorrector: parameter values no step passes over; a predictor that would is
  /// shortened to land on the first. A forced response's linear resonances: far from them
  /// the response barely changes, the steps grow long, and over a wide range one step
  /// carried a Duffing curve from 0.327 to 1000.3 rad/s, over its resonance at 1.27.
  std::vector<double> parameterMarks;
  double tolerance = 1e-10;         ///< Newton: ||F||_2
  int maxNewtonIterations = 15;
  /// PredictorCorrector: the turn of the tangent per step the step size aims at
  /// (radians). A half circle of the response (the phase through a resonance) takes
  /// about pi / turnAngle points.
  double turnAngle = 0.25;
  /// PredictorCorrector: where the tangent's turn holds the step at a corner's size for
  /// most of the last ten steps (a stair of kinks: a sampled contact law's stick, slip and
  /// lift-off instants crossing the time samples, thousands along a hammering shroud's
  /// resonance), steps follow the last chord, held by its turn only beyond one radian,
  /// until the tangent turns less than turnAngle for five steps in a row
  /// (ContinuationStatistics::secantSteps; docs/solvers.md).
  bool secantOverKinks = true;
  /// PredictorCorrector: the bordered Jacobian's LU in single precision with every
  /// solve refined in double (DenseLu's mixed precision, from n = 200): the same
  /// iterates to rounding, the LU about 1.9x faster; a matrix single precision cannot
  /// serve is factored again in double (ContinuationStatistics::doubleFallbacks).
  bool mixedPrecisionLu = true;
  /// PredictorCorrector: a Newton step's bordered Jacobian solved with the last
  /// factors kept (of the iteration or point before) by preconditioned GMRES to a double
  /// LU's accuracy, and factored only where that does not converge or stops paying
  /// (DenseLu::reuseFactorsFor): the same iterates to rounding, fewer LUs.
  bool reuseFactorizations = true;
  /// How Newton steps are solved: Dense (the Jacobian formed and factored by LU), Krylov
  /// (GMRES on the problem's jacobianOperator, preconditioned by its preconditioner), or
  /// Auto: Krylov for problems with an operator from krylovFrom unknowns, where its cost,
  /// about linear in the unknowns, falls below the LU's cubic one (docs/solvers.md).
  enum class LinearSolver { Auto, Dense, Krylov };
  LinearSolver linearSolver = LinearSolver::Auto;
  static constexpr int krylovFrom = 1000;
  KrylovOptions krylov;
  /// LOCA's rescaling of the parameter against the unknowns in the arclength. Off for
  /// unknowns scaled to order one beforehand (the FE disc): LOCA's rescaling then
  /// shrank the steps near a resonance to a creep (2000 points short of the peak).
  bool arcLengthScaling = true;  // Loca only
  /// Stop a run that goes back along its own path for a few points (BranchTurn.hpp),
  /// or whose step fell below the minimum, and try a step over the kink (at a fixed
  /// parameter, then a secant arclength step); the curve ends with that reason if
  /// neither passes. Off by default: a true fold whose two halves nearly coincide (the
  /// force ramp of NLvib's example 03) looks the same. On for the FE disc scenes,
  /// whose H = 3 curve LOCA otherwise walked back to the start, calling it finished.
  bool stopWhereItTurnsBack = false;  // Loca only (the predictor-corrector never turns back)
  /// Drop a point whose step is far longer than the step before it (BranchTurn.hpp:
  /// branchJump: the corrector left the predictor's neighbourhood for another branch)
  /// and restart from the last point with a quarter of the step; after 6 restarts
  /// without progress the curve ends there with that reason.
  bool restartWhereTheCorrectorJumps = true;  // Loca only
  /// LOCA's dF/dp: a forward difference of step perturbation (perturbation + |p|)
  /// (LOCA::DerivUtils; LOCA's own is 1e-6). A residual that is continuous but only
  /// piecewise smooth in p at a fine scale (a peak condition through sampled friction
  /// laws) needs a step that spans its pieces (continuePeak).
  double locaParameterPerturbation = 1e-6;  // Loca only
  /// NOX's line search in LOCA's corrector. Full steps are LOCA's default; a
  /// backtracking or polynomial line search can keep Newton from cycling at the
  /// kinks of many friction contacts (docs/scenes.md: the default disc at H = 3).
  enum class LineSearch { FullStep, Backtrack, Polynomial };
  LineSearch lineSearch = LineSearch::FullStep;  // Loca only
  /// Where the trace saves its state as it goes and looks for a saved one to continue
  /// (TraceCheckpoint.hpp); none: nothing is saved. Not part of the trace's key.
  std::shared_ptr<TraceCheckpoints> checkpoints;
};

/// LOCA's engine with its own step defaults (its steps are in its units; a maximum of
/// 0.05 there, not the predictor-corrector's 0.2).
ContinuationOptions locaOptions();

/// What a curve cost: counts and seconds of the engine's work.
struct ContinuationStatistics {
  int newtonIterations = 0;  ///< corrector iterations, all steps (rejected ones too)
  int rejectedSteps = 0;     ///< corrections that failed or were refused (the step was cut)
  int sphericalSteps = 0;    ///< steps taken by the spherical corrector (sharp turns)
  /// Steps taken along the last chord, not the tangent, over a stair of kinks (a
  /// hammering shroud's contact instants crossing the time samples; PredictorCorrector.cpp).
  long secantSteps = 0;
  long residuals = 0, jacobians = 0, factorizations = 0;
  /// Factorisations made again in double where the single-precision LU's refinement
  /// did not reach a double LU's accuracy (DenseLu); their time is in factorSeconds.
  long doubleFallbacks = 0;
  /// Newton steps solved with kept factors (reuseFactorizations), and their GMRES
  /// iterations (their time is in solveSeconds; a factorisation they ended in is counted
  /// with the factorisations).
  long reusedFactorizations = 0, krylovIterations = 0;
  /// Krylov (ContinuationOptions::linearSolver): the GMRES solves on the operator (their
  /// iterations in krylovIterations, time in solveSeconds) and the preconditioners'
  /// set-up (factorisation of their blocks).
  long krylovSolves = 0;
  double preconditionerSeconds = 0;
  double residualSeconds = 0, jacobianSeconds = 0, factorSeconds = 0, solveSeconds = 0, seconds = 0;
};

struct BranchPoint {
  double parameter;
  Eigen::VectorXd x;
};

/// How a trace ended: what a calling program branches on. Branch::stopReason says the
/// same as a sentence, with where, how far and what was tried.
enum class BranchEnd {
  Running,           ///< not ended (a trace in progress: a checkpoint's)
  RangeEnd,          ///< the end of the parameter range reached (Branch::finished)
  MetFromTheEnd,     ///< the range covered by a sweep from each end (finished; Branch::segmentStarts)
  SinglePoint,       ///< the range is a single point (finished: that point)
  ReturnedToStart,   ///< folded back and ran out at the bound it started from (Branch::reached)
  Wall,              ///< no step passes a point: the correctors failed down to the smallest step
  PointBudget,       ///< the largest number of points (max_points) spent
  NoStart,           ///< no converged first point
  StartFailed,       ///< the residual or Jacobian failed, or the Jacobian was singular, at the first point
  EngineStopped,     ///< LOCA stopped: an exception, or its step below the minimum
};
/// The outcome's name in files ("range_end", "wall", ...).
const char* branchEndName(BranchEnd end);
/// The engine's name in scenes and files ("predictor_corrector", "loca": a scene's
/// continuation/engine key).
const char* engineKey(ContinuationOptions::Engine engine);
/// The engine a key names (engineKey's inverse, so the names live in one place);
/// nullopt for a name that is no engine's.
std::optional<ContinuationOptions::Engine> engineFromKey(const std::string& key);

struct Branch {
  std::vector<BranchPoint> points;
  bool finished = false;  ///< reached the end of the range
  BranchEnd end = BranchEnd::Running;
  std::string stopReason;
  int failedSteps = 0;
  /// The branch folded back and ran out at the bound it started from; `reached` is the
  /// farthest parameter it got to (the range beyond was not traced).
  bool returnedToStart = false;
  double reached = 0;
  /// Where later segments start in `points` (empty: one segment). A curve traced again
  /// from the other end of the range (response::traceForcedResponse) is a second segment:
  /// consecutive points across a start are not neighbours on a path.
  std::vector<std::size_t> segmentStarts;
  ContinuationStatistics statistics;  ///< PredictorCorrector only
  /// How a curve that needed more than one trace was obtained (response::traceForcedResponse's
  /// retries), what stopReason says in words: the engine whose trace this is, whether the
  /// other engine was tried because one left the curve incomplete, the AFT samples of the
  /// kept trace as a multiple of the system's, and every multiple tried beyond 1.
  struct Retraces {
    ContinuationOptions::Engine engine = ContinuationOptions::Engine::PredictorCorrector;
    bool otherEngineTried = false;
    int samplesFactor = 1;
    std::vector<int> samplesFactorsTried;
  } retraces;
};

/// Newton steps by GMRES on problem.jacobianOperator (see ContinuationOptions::linearSolver).
bool useKrylov(const ContinuationProblem& problem, const ContinuationOptions& options);

/// Traces from x0 (a solution, or a good guess, at p = options.from; it is
/// corrected by solveNewton (NewtonSolve.hpp) before LOCA takes it, whose first Newton solve has no
/// line search).
Branch traceBranch(const ContinuationProblem& problem, const Eigen::VectorXd& x0, const ContinuationOptions& options);

}  // namespace cyclone::continuation
