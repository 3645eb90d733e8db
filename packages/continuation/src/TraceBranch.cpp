#include <cmath>
#include <sstream>

#include "ContinuationEngines.hpp"
#include "cyclone/continuation/TraceCheckpoint.hpp"
#include "cyclone/core/ContentHash.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/core/Log.hpp"

namespace cyclone::continuation {

const char* branchEndName(BranchEnd end) {
  switch (end) {
    case BranchEnd::Running: return "running";
    case BranchEnd::RangeEnd: return "range_end";
    case BranchEnd::MetFromTheEnd: return "met_from_the_end";
    case BranchEnd::SinglePoint: return "single_point";
    case BranchEnd::ReturnedToStart: return "returned_to_start";
    case BranchEnd::Wall: return "wall";
    case BranchEnd::PointBudget: return "point_budget";
    case BranchEnd::NoStart: return "no_start";
    case BranchEnd::StartFailed: return "start_failed";
    case BranchEnd::EngineStopped: return "engine_stopped";
  }
  return "unknown";
}

const char* engineKey(ContinuationOptions::Engine engine) {
  switch (engine) {
    case ContinuationOptions::Engine::PredictorCorrector: return "predictor_corrector";
    case ContinuationOptions::Engine::Loca: return "loca";
  }
  return "unknown";
}

std::optional<ContinuationOptions::Engine> engineFromKey(const std::string& key) {
  for (const auto engine : {ContinuationOptions::Engine::PredictorCorrector, ContinuationOptions::Engine::Loca})
    if (key == engineKey(engine)) return engine;
  return std::nullopt;
}

std::string noConvergedStart(const NewtonResult& start, double tolerance) {
  std::ostringstream why;
  why << "no converged solution at the start of the range: Newton with line search from the guess stopped at ||R|| = "
      << start.residualNorm << " (tolerance " << tolerance
      << "; round-off of very different forces, e.g. a huge preload against a tiny excitation, needs a looser "
         "continuation tolerance)";
  return why.str();
}

bool useKrylov(const ContinuationProblem& problem, const ContinuationOptions& o) {
  using S = ContinuationOptions::LinearSolver;
  if (o.linearSolver == S::Dense) return false;
  if (!problem.jacobianOperator) {
    if (o.linearSolver == S::Krylov)
      throw InputError("continuation/linear_solver", "Krylov needs the problem's Jacobian as an operator (jacobianOperator)");
    return false;
  }
  return o.linearSolver == S::Krylov || problem.size >= ContinuationOptions::krylovFrom;
}

ContinuationOptions locaOptions() {
  ContinuationOptions o;
  o.engine = ContinuationOptions::Engine::Loca;
  o.maxStep = 0.05;
  return o;
}

std::string traceKey(const ContinuationProblem& problem, const Eigen::VectorXd& guess, const ContinuationOptions& o) {
  ContentHash h;
  h.add(std::string("cyclone trace 7")).add(int(useKrylov(problem, o))).add(problem.size).add(int(o.engine)).add(o.from).add(o.to);
  h.add(o.initialStep).add(o.minStep).add(o.maxStep).add(o.maxSteps).add(o.tolerance).add(o.maxNewtonIterations);
  h.add(o.turnAngle).add(int(o.secantOverKinks)).add(int(o.mixedPrecisionLu)).add(int(o.reuseFactorizations)).add(int(o.arcLengthScaling)).add(int(o.stopWhereItTurnsBack));
  h.add(int(o.restartWhereTheCorrectorJumps)).add(o.locaParameterPerturbation).add(int(o.lineSearch)).add(int(bool(problem.measure)));
  h.add((long long)o.parameterMarks.size());
  if (!o.parameterMarks.empty()) h.add(o.parameterMarks.data(), o.parameterMarks.size() * sizeof(double));
  h.add((long long)guess.size()).add(guess.data(), std::size_t(guess.size()) * sizeof(double));
  h.add((long long)problem.scaleGroups.size());
  if (!problem.scaleGroups.empty()) h.add(problem.scaleGroups.data(), problem.scaleGroups.size() * sizeof(int));
  // The residual tells the problem: at the guess, and at points around it over many
  // decades, because a start from rest does not show what acts only in motion (a
  // friction coefficient, a contact stiffness, a gap's clearance, a cubic spring, the
  // damping): a clearance study's curve at 0.01 mm was read back from the trace at 0
  // (docs/decisions.md, 2026-11-26). The probes are deterministic, so the same problem
  // gives the same key.
  Eigen::VectorXd F, probe(guess.size());
  for (Eigen::Index i = 0; i < probe.size(); ++i) probe(i) = std::sin(1.0 + 0.6180339887498949 * double(i));
  const double size = std::max(1.0, guess.size() > 0 ? guess.cwiseAbs().maxCoeff() : 0.0);
  for (const double amplitude : {0.0, 1e-6, 1e-3, 1.0, 1e3}) {
    try {
      problem.residual(guess + (amplitude * size) * probe, o.from, F);
      h.add((long long)F.size()).add(F.data(), std::size_t(F.size()) * sizeof(double));
    } catch (...) {
      h.add(std::string("residual failed at a probe"));
    }
  }
  return h.hex();
}

namespace {

void saveQuietly(TraceCheckpoints& store, const std::string& key, const TraceState& state) {
  try {
    store.save(key, state);
  } catch (const std::exception& e) {
    log::warn(std::string("continuation: the trace's checkpoint was not saved (the run goes on): ") + e.what());
  }
}

}  // namespace

Branch traceBranch(const ContinuationProblem& problem, const Eigen::VectorXd& guess, const ContinuationOptions& o) {
  const bool loca = o.engine == ContinuationOptions::Engine::Loca;
  if (!(o.locaParameterPerturbation > 0 && o.locaParameterPerturbation < 1))
    throw InputError("continuation/locaParameterPerturbation",
                     "must lie in (0, 1) (LOCA's relative difference step for dF/dp), not " +
                         std::to_string(o.locaParameterPerturbation));
  if (!o.checkpoints) return loca ? traceBranchWithLoca(problem, guess, o) : traceBranchWithPredictorCorrector(problem, guess, o);
  TraceCheckpoints& store = *o.checkpoints;
  const std::string key = traceKey(problem, guess, o);
  std::optional<TraceState> saved = store.load(key);
  if (saved && saved->complete) {
    log::info("continuation: trace " + key.substr(0, 8) + " read back from its checkpoint (" +
              std::to_string(saved->branch.points.size()) + " points; " + saved->branch.stopReason + ")");
    return std::move(saved->branch);
  }
  Branch branch;
  if (loca) {
    branch = traceBranchWithLoca(problem, guess, o);
  } else {
    if (saved)
      log::info("continuation: trace " + key.substr(0, 8) + " resumed from its checkpoint (" +
                std::to_string(saved->branch.points.size()) + " points, to p = " +
                std::to_string(saved->branch.points.empty() ? o.from : saved->branch.points.back().parameter) + ")");
    const TraceCheckpointing checkpointing{saved ? &*saved : nullptr,
                                           [&store, &key](const TraceState& s) { saveQuietly(store, key, s); },
                                           store.intervalSeconds};
    branch = traceBranchWithPredictorCorrector(problem, guess, o, &checkpointing);
  }
  TraceState done;
  done.branch = branch;
  done.complete = true;
  saveQuietly(store, key, done);
  return branch;
}

}  // namespace cyclone::continuation
