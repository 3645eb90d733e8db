#include "SceneStages.hpp"

#include <Teuchos_Comm.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>

#include "cyclone/continuation/HomotopySolve.hpp"
#include "cyclone/continuation/NewtonSolve.hpp"
#include "cyclone/continuation/PeakSearch.hpp"
#include "cyclone/core/AtomicFile.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/hbm/BifurcationFlags.hpp"
#include "cyclone/hbm/HarmonicRefinement.hpp"
#include "cyclone/hbm/HillStability.hpp"
#include "cyclone/hbm/PeakMagnitude.hpp"
#include "cyclone/post/ResponseCurveFile.hpp"
#include "cyclone/post/SvgPlot.hpp"

namespace cyclone::scenes {

namespace {

// [begin, end) of each segment of a branch, as consecutive bounds (first 0, last the size).
std::vector<std::size_t> segmentBounds(const continuation::Branch& branch) {
  std::vector<std::size_t> bounds{0};
  for (std::size_t s : branch.segmentStarts)
    if (s > bounds.back() && s < branch.points.size()) bounds.push_back(s);
  bounds.push_back(branch.points.size());
  return bounds;
}

// The AFT sample count is checked by doubling it: the largest-response point
// is solved again with 2N samples and the change of its peak reported (friction
// and gaps place their events only to within a sample).
std::string samplesCheck(ForcedResponseSetup& setup, const continuation::BranchPoint& pt, double peak) {
  const auto [w, scale] = setup.apply(pt.parameter);
  const auto& hb = *setup.system;
  const int N = hb.aft().numSamples(), dof = setup.outputDofs.front(), nc = hb.numCoefficients();
  const auto doubled = hbm::withHarmonics(hb, hb.aft().harmonics(), 2 * N);
  // The force-scale form at this frequency: the same row scaling as the trace.
  const auto problem = continuationProblem(*doubled, ForcedResponseSetup::Parameter::ForceScale, w);
  Eigen::VectorXd X = pt.x;
  const auto newton = continuation::solveNewton(problem, X, scale, setup.continuation.tolerance);
  std::ostringstream out;
  if (!newton.converged) {
    out << "samples check: no solution with " << 2 * N << " samples at the peak (residual " << newton.residualNorm
        << "); the sample count " << N << " may be too small";
    log::warn(out.str());
    return out.str();
  }
  const double before = peak;
  const double after = hbm::peakMagnitude(hb.aft().harmonics(), Eigen::VectorXd(X.segment(dof * nc, nc)));
  const double change = std::abs(after / before - 1);
  out << "samples check: " << N << " -> " << 2 * N << " samples changes the peak max|x| of DOF " << dof << " by "
      << change << " (relative)";
  if (change > 1e-2) log::warn(out.str() + ": raise `samples`");
  return out.str();
}

// The solvers hold about four dense matrices of the unknowns' size (the Jacobian, the
// bordered one and the factors of two of them): refused where they would not fit in
// this machine's memory, a warning where each Newton iteration takes seconds (one
// Jacobian and LU took about 1 s at 2349 unknowns on the default disc).
void checkDenseSize(const hbm::HarmonicBalanceSystem& hb, const std::string& harmonicsKey) {
  constexpr double kMaxGigabytes = 12, kSlowUnknowns = 5000;
  const double n = hb.numUnknowns(), gigabytes = 4 * 8 * n * n / 1e9;
  std::ostringstream what;
  what.precision(3);
  what << hb.aft().harmonics().size() << " harmonics (up to " << hb.aft().harmonics().maxHarmonic() << ") on "
       << hb.numDofs() << " DOFs make " << hb.numUnknowns() << " unknowns";
  if (gigabytes > kMaxGigabytes) {
    what << ": the dense Jacobian and its factors would take " << gigabytes << " GB (at most " << kMaxGigabytes
         << " here); use fewer harmonics";
    throw InputError(harmonicsKey, what.str());
  }
  if (n > kSlowUnknowns)
    log::warn(what.str() + ": each Newton iteration factors a dense Jacobian of that size (about " +
              std::to_string(std::max(1, int(std::pow(n / 2349.0, 3)))) + " s each, from 1 s at 2349)");
}


// `set` and one harmonic more (h), with at least the system's samples.
hbm::HarmonicSet withHarmonic(const hbm::HarmonicSet& set, int h) {
  std::vector<int> list = set.harmonics();
  list.push_back(h);
  return hbm::HarmonicSet(list);
}
std::unique_ptr<hbm::HarmonicBalanceSystem> raisedSystem(const hbm::HarmonicBalanceSystem& hb,
                                                         const hbm::HarmonicSet& raised) {
  auto system = hbm::withHarmonics(hb, raised, std::max(hb.aft().numSamples(), raised.minimumSamples()));
  checkDenseSize(*system, "harmonics_check_to");
  return system;
}

// The largest response of DOF `dof` along a frequency curve near the solution X at
// `hz`: the peak search at fixed frequencies (PeakSearch.hpp), which passes the
// corners of friction paths where an arclength corrector stalls. Its parameter is the
// frequency in Hz (what its messages name). The window (+-5 %, and `offset` more for
// a start that far from the peak it seeks) holds the shift of a friction-damped peak
// between harmonic truncations.
continuation::PeakSearchResult searchPeak(const hbm::HarmonicBalanceSystem& system, const Eigen::VectorXd& X,
                                          double hz, double excitationScale, int dof, double tolerance,
                                          double offset = 0) {
  const auto byOmega = continuationProblem(system, ForcedResponseSetup::Parameter::Omega, 0, excitationScale);
  continuation::ContinuationProblem problem = byOmega;
  problem.residual = [byOmega](const Eigen::VectorXd& x, double f, Eigen::VectorXd& R) {
    byOmega.residual(x, 2 * M_PI * f, R);
  };
  problem.jacobian = [byOmega](const Eigen::VectorXd& x, double f, Eigen::MatrixXd& J) {
    byOmega.jacobian(x, 2 * M_PI * f, J);
  };
  const int nc = system.numCoefficients();
  const auto& H = system.aft().harmonics();
  continuation::PeakSearchOptions o;
  o.step = 1e-3 * hz, o.maxStep = 5e-3 * hz, o.minStep = 1e-8 * hz;
  o.window = 0.05 * hz + std::abs(offset), o.parameterTolerance = 1e-5 * hz;
  o.tolerance = tolerance;
  // From a neighbour's prediction Newton converges in a few iterations; one that does not
  // within 20 is cut (a step) or replaced (a flank start at a level's start), not waited for.
  o.maxNewtonIterations = 20;
  const auto measure = [&](const Eigen::VectorXd& x) {
    return hbm::peakMagnitude(H, Eigen::VectorXd(x.segment(dof * nc, nc)));
  };
  return continuation::findLocalPeak(problem, X, hz, measure, o);
}

// The solution X of the level below, carried to `system` (one harmonic more, h), solved
// at `hz`: Newton, or where it stalls the homotopy that switches the new harmonic's
// equations on (HomotopySolve.hpp). X is updated in place.
continuation::HomotopyResult solveCarried(const hbm::HarmonicBalanceSystem& system, Eigen::VectorXd& X, double hz,
                                          double excitationScale, int h, double tolerance) {
  const auto byOmega = continuationProblem(system, ForcedResponseSetup::Parameter::Omega, 0, excitationScale);
  const auto& set = system.aft().harmonics();
  const int nc = system.numCoefficients();
  std::vector<int> added;
  for (int d = 0; d < system.numDofs(); ++d) {
    added.push_back(d * nc + set.cosIndex(h));
    if (h > 0) added.push_back(d * nc + set.sinIndex(h));
  }
  return continuation::solveByHomotopy(byOmega, X, 2 * M_PI * hz, added, tolerance);
}

// One level of the harmonics check on a frequency curve.
struct PeakLevel {
  int maxHarmonic = 0;
  std::vector<int> harmonics;  ///< the level's harmonic set
  int samples = 0;             ///< and its samples per period
  continuation::PeakSearchResult peak;
  double seconds = 0;
  double startHz = 0;  ///< where the search started (the level below's peak, or its flank)
};

// Solutions of one harmonic set at frequencies (Hz) near its peak: the traced curve's
// points, a peak search's path.
using SolvedPoints = std::vector<std::pair<double, Eigen::VectorXd>>;

// A start for the raised system on the level below's flank, where the two differ
// less than at a peak that moves with H: the level below's solutions (`lower`) at
// least 0.5 % of the frequency from its peak, nearest first, each carried up and
// solved at its frequency (at most 6 tried). Empty when none converges.
std::pair<double, Eigen::VectorXd> flankStart(const hbm::HarmonicBalanceSystem& lowerSystem,
                                              const hbm::HarmonicBalanceSystem& raised, SolvedPoints lower,
                                              double peakHz, double scale, double tolerance) {
  const auto byOmega = continuationProblem(raised, ForcedResponseSetup::Parameter::Omega, 0, scale);
  std::sort(lower.begin(), lower.end(), [peakHz](const auto& a, const auto& b) {
    return std::abs(a.first - peakHz) < std::abs(b.first - peakHz);
  });
  int tried = 0;
  for (const auto& [f, x] : lower) {
    if (std::abs(f - peakHz) < 5e-3 * peakHz) continue;
    if (++tried > 6) break;
    Eigen::VectorXd y =
        hbm::transferCoefficients(x, lowerSystem.numDofs(), lowerSystem.aft().harmonics(), raised.aft().harmonics());
    if (continuation::solveNewton(byOmega, y, 2 * M_PI * f, tolerance, 10).converged) return {f, y};
  }
  return {0, Eigen::VectorXd()};
}

// The peak of the curve with H, then with H + 1, H + 2, ... up to `upTo`, each level's
// search started from the one below's peak (its solution carried to one more
// harmonic), or from the level below's flank when Newton finds nothing there (its
// search path; for the first raised level also `curve`, the traced points). Stops at
// a level whose peak is not found (a fold, no solution).
std::vector<PeakLevel> peakByHarmonics(const hbm::HarmonicBalanceSystem& hb, const Eigen::VectorXd& x, double hz,
                                       double scale, int dof, double tolerance, int upTo, const SolvedPoints& curve) {
  std::vector<PeakLevel> levels;
  std::unique_ptr<hbm::HarmonicBalanceSystem> lowerSystem, current;
  const hbm::HarmonicBalanceSystem* system = &hb;
  hbm::HarmonicSet set = hb.aft().harmonics();
  Eigen::VectorXd X = x;
  SolvedPoints lowerPoints;
  for (int H = set.maxHarmonic(); H <= upTo; ++H) {
    Timer timer;
    const hbm::HarmonicBalanceSystem* lower = system;
    if (H > set.maxHarmonic()) {
      const hbm::HarmonicSet raised = withHarmonic(set, H);
      lowerSystem = std::move(current);  // keeps `lower` alive
      current = raisedSystem(hb, raised);
      X = hbm::transferCoefficients(X, hb.numDofs(), set, raised);
      set = raised, system = current.get();
    }
    PeakLevel level;
    level.maxHarmonic = H;
    level.harmonics = set.harmonics(), level.samples = system->aft().numSamples();
    level.startHz = hz;
    bool started = true;  // X solves this level at hz (the search's own Newton would only repeat a failure)
    if (system != lower) {
      const auto carried = solveCarried(*system, X, hz, scale, H, tolerance);
      started = carried.newton.converged;
      if (carried.blockStart || carried.byHomotopy) {
        const std::string how = carried.blockStart ? "the added harmonic solved with the others held, then " : "";
        log::info("harmonics check: H " + std::to_string(H) + " at " + std::to_string(hz) + " Hz " +
                  (started ? "solved from H " + std::to_string(H - 1) + " by " + how +
                                 (carried.byHomotopy ? "the homotopy (" + std::to_string(carried.points) + " points)"
                                                     : "Newton")
                           : "not solved: " + carried.reason));
      }
      if (!started) level.peak.reason = "no solution at the start (" + carried.reason + ")";
    }
    if (started) level.peak = searchPeak(*system, X, hz, scale, dof, tolerance);
    if (level.peak.x.size() == 0 && system != lower) {
      const auto [f, start] = flankStart(*lower, *system, lowerPoints, hz, scale, tolerance);
      if (start.size() > 0) {
        level.startHz = f;
        level.peak = searchPeak(*system, start, f, scale, dof, tolerance, f - hz);
      } else {
        level.peak.reason += ", nor from the level below's solutions on its flank";
      }
    }
    level.seconds = timer.seconds();
    levels.push_back(level);
    if (!level.peak.found) break;
    X = level.peak.x, hz = level.peak.parameter;
    lowerPoints = level.peak.path;
    if (levels.size() == 1) lowerPoints.insert(lowerPoints.end(), curve.begin(), curve.end());
  }
  return levels;
}

// A free-text note as one CSV cell (the report's table splits at commas).
std::string csvCell(std::string text) {
  for (char& c : text)
    if (c == ',') c = ';';
  return text;
}

// <name>_harmonics.csv: the peak per harmonic truncation, its change from the level
// before, and what each level cost.
void writePeakLevels(const std::vector<PeakLevel>& levels, int dof, const std::string& path) {
  AtomicFile file(path);
  std::ofstream out(file.tempPath());
  out.precision(10);
  out << "max_harmonic,found,peak_max_abs_dof" << dof
      << ",freq_hz,relative_change,frequency_change,solves,seconds,note\n";
  for (std::size_t i = 0; i < levels.size(); ++i) {
    const auto& l = levels[i];
    out << l.maxHarmonic << "," << (l.peak.found ? 1 : 0) << ",";
    if (l.peak.x.size() == 0) {  // no solution at all: nothing to compare
      out << ",,,," << l.peak.solves << "," << l.seconds << "," << csvCell(l.peak.reason) << "\n";
      continue;
    }
    out << l.peak.value << "," << l.peak.parameter << ",";
    if (i > 0) {
      const auto& b = levels[i - 1].peak;
      out << std::abs(l.peak.value / b.value - 1) << "," << std::abs(l.peak.parameter / b.parameter - 1);
    } else {
      out << ",";
    }
    std::string note = l.peak.reason;
    if (i > 0 && l.startHz != levels[i - 1].peak.parameter) {
      std::ostringstream from;
      from << "started on the flank at " << l.startHz << " Hz" << (note.empty() ? "" : "; ");
      note = from.str() + note;
    }
    out << "," << l.peak.solves << "," << l.seconds << "," << csvCell(note) << "\n";
  }
  out.close();
  if (!out) throw Error("cannot write " + path);
  file.commit();
}

// The response at the point itself with harmonics 0..H+1: Newton from its solution
// carried over, at the same parameter.
std::string pointHarmonicsCheck(ForcedResponseSetup& setup, const continuation::BranchPoint& pt, double peak) {
  const auto [w, scale] = setup.apply(pt.parameter);
  const auto& hb = *setup.system;
  const auto& H = hb.aft().harmonics();
  const int dof = setup.outputDofs.front(), next = H.maxHarmonic() + 1;
  std::ostringstream out;
  out << "harmonics check: H " << H.maxHarmonic() << " -> " << next;
  const hbm::HarmonicSet raised = withHarmonic(H, next);
  const auto refined = raisedSystem(hb, raised);
  const auto problem = continuationProblem(*refined, ForcedResponseSetup::Parameter::ForceScale, w);
  Eigen::VectorXd X = hbm::transferCoefficients(pt.x, hb.numDofs(), H, raised);
  const auto newton = continuation::solveNewton(problem, X, scale, setup.continuation.tolerance);
  if (!newton.converged) {
    out << ": no solution at the peak (residual " << newton.residualNorm << ")";
    log::warn(out.str());
    return out.str();
  }
  const int nc = refined->numCoefficients();
  const double after = hbm::peakMagnitude(raised, Eigen::VectorXd(X.segment(dof * nc, nc)));
  const double change = std::abs(after / peak - 1);
  out << " changes the peak max|x| of DOF " << dof << " by " << change << " (relative)";
  if (change > 1e-2) log::warn(out.str() + ": the curve is not converged in the harmonics near its peak");
  return out.str();
}

// The harmonic truncation is checked by raising H: on a frequency curve the peaks
// with H, H + 1, ... (up to setup.harmonicsCheckTo) are compared, each found by the
// peak search (PeakSearch.hpp: fixed-frequency steps uphill, then golden section). A
// peak that moves in frequency changes the response at a fixed frequency far more
// than the peak itself, so the change at the traced point alone says little there.
// Other parameters (force, preload, ...), and a frequency curve whose largest point is
// no interior peak (it rises at the end of the range), compare the point with
// harmonics 0..H+1. Not possible when the system has nothing for a raised harmonic (a
// reduced model without that nodal diameter): said so.
std::string harmonicsCheck(ForcedResponseSetup& setup, const continuation::Branch& branch, std::size_t ip,
                           double peak, const std::string& csvPath, SceneSummary& summary,
                           HarmonicsConvergedPeak& best) {
  const auto& pt = branch.points[ip];
  try {
    if (setup.parameter != ForcedResponseSetup::Parameter::Omega) return pointHarmonicsCheck(setup, pt, peak);
    Timer timer;
    const auto [w, scale] = setup.apply(pt.parameter);
    const auto& hb = *setup.system;
    const int dof = setup.outputDofs.front();
    const int upTo = std::max(setup.harmonicsCheckTo, hb.aft().harmonics().maxHarmonic() + 1);
    // The traced points within 5 % of the peak: flank starts for the first raised level.
    SolvedPoints curve;
    for (const auto& p : branch.points) {
      const double f = setup.apply(p.parameter).first / (2 * M_PI);
      if (std::abs(f / (w / (2 * M_PI)) - 1) <= 0.05) curve.emplace_back(f, p.x);
    }
    setup.apply(pt.parameter);
    const auto levels =
        peakByHarmonics(hb, pt.x, w / (2 * M_PI), scale, dof, setup.continuation.tolerance, upTo, curve);
    writePeakLevels(levels, dof, csvPath);
    summary.written.push_back(csvPath);
    if (!levels.front().peak.found)  // no interior peak with the curve's own harmonics
      return pointHarmonicsCheck(setup, pt, peak) + " (no peak search: " + levels.front().peak.reason + ")";
    std::ostringstream out;
    out << "harmonics check: peak max|x| of DOF " << dof << " by harmonics:";
    out.precision(6);
    for (std::size_t i = 0; i < levels.size(); ++i) {
      const auto& l = levels[i];
      out << (i ? "; " : " ") << "H " << l.maxHarmonic << " ";
      if (l.peak.found) {
        out << l.peak.value << " at " << l.peak.parameter << " Hz";
        if (i > 0 && l.startHz != levels[i - 1].peak.parameter)
          out << " (searched from the flank at " << l.startHz << " Hz)";
      } else if (l.peak.x.size() == 0) {
        out << "not found (" << l.peak.reason << ")";
      } else {
        out << "not found (" << l.peak.reason << "; best point " << l.peak.value << " at " << l.peak.parameter
            << " Hz)";
      }
    }
    // The change between the last two levels whose peaks were both found.
    std::size_t j = levels.size() - 1;
    while (j >= 1 && !(levels[j].peak.found && levels[j - 1].peak.found)) --j;
    std::size_t reached = 0;
    for (; reached < levels.size() && levels[reached].peak.found; ++reached) {
      best.found = true;
      best.maxHarmonic = levels[reached].maxHarmonic, best.value = levels[reached].peak.value,
      best.hz = levels[reached].peak.parameter;
      best.x = levels[reached].peak.x, best.harmonics = levels[reached].harmonics, best.samples = levels[reached].samples;
    }
    if (best.found && reached < levels.size()) best.notFoundHarmonic = levels[reached].maxHarmonic;
    if (j >= 1) {
      const auto &before = levels[j - 1].peak, &after = levels[j].peak;
      const double change = std::abs(after.value / before.value - 1);
      if (levels[j].maxHarmonic == best.maxHarmonic) best.belowHarmonic = levels[j - 1].maxHarmonic, best.change = change;
      out << "; H " << levels[j - 1].maxHarmonic << " -> " << levels[j].maxHarmonic << " changes the peak by "
          << change << " (relative), its frequency by " << std::abs(after.parameter / before.parameter - 1) << "; "
          << timer.seconds() << " s";
      if (change > 1e-2) log::warn(out.str() + ": the curve is not converged in the harmonics near its peak");
      else log::info(out.str());
    } else {
      out << "; " << timer.seconds() << " s";
      log::warn(out.str() + ": the harmonic convergence of the peak is not known");
    }
    return out.str();
  } catch (const std::exception& e) {
    return std::string("harmonics check: not possible (") + e.what() + ")";
  }
}

}  // namespace

ForcedResponseResult traceAndWriteForcedResponse(ForcedResponseSetup& setup, const std::string& outDir,
                                                 const std::string& name, linalg::CommPtr comm, SceneSummary& summary) {
  auto& hb = *setup.system;
  const auto& opt = setup.continuation;
  const auto& dofs = setup.outputDofs;
  const auto& harmonics = hb.aft().harmonics();
  const int samples = hb.aft().numSamples();
  const int n = hb.numDofs();
  Timer timer;
  const bool byOmega = setup.parameter == ForcedResponseSetup::Parameter::Omega;
  const std::string parameterName = setup.parameterName();
  auto frequency = [&](double p) { return setup.apply(p).first; };
  {
    std::ostringstream msg;
    msg << "forced response: " << n << " DOFs, harmonics up to " << harmonics.maxHarmonic() << ", " << samples
        << " samples, " << parameterName << " " << (byOmega ? opt.from * setup.omegaUnit : opt.from) << " -> "
        << (byOmega ? opt.to * setup.omegaUnit : opt.to);
    if (!byOmega) msg << " at omega " << setup.omega;
    if (hb.isCyclic()) {
      msg << "; cyclic: " << hb.cyclic().sectors << " sectors, engine order " << hb.cyclic().engineOrder
          << ", harmonic -> nodal diameter:";
      for (int h : harmonics.harmonics()) msg << " " << h << "->" << hb.nodalDiameter(h);
    }
    log::info(msg.str());
  }
  checkDenseSize(hb, setup.harmonicsKey);
  const StartingPoint start = findStartingPoint(setup);
  if (start.x.size() > 0) {
    std::ostringstream msg;
    msg << "forced response: first point by " << start.method << " (" << start.seconds << " s)";
    log::info(msg.str());
  }
  const auto branch = traceForcedResponse(setup, start);
  if (branch.points.empty() && setup.whenNothingTraced == ForcedResponseSetup::WhenNothingTraced::Fail)
    throw SolverError(name + ": no point of the curve was computed, so nothing was written: " + branch.stopReason);

  // frc.csv: per point the frequency and, per output DOF, h0, amplitudes and max |x(t)|.
  const std::string csvPath = outDir + "/" + name + ".csv";
  std::vector<double> plotW, plotMax;
  std::vector<int> plotStable;
  bool hill = setup.stability != "false";
  for (const auto& c : hb.elements()) hill = hill && !c.element->usesVelocity();
  if (!hill && setup.stability != "false")
    log::warn("stability not computed: Hill's method with velocity-dependent elements is not supported yet");
  if (hill && hb.isReceptance()) {
    // Hill's method runs on the reduced models' modal realizations (ReceptanceHill.cpp): the
    // full FE compliance has none. Its cost is a dense LU of n nc per point.
    std::string why;
    int modes = 0;
    for (int h : harmonics.harmonics()) {
      const auto r = hb.receptance()->modalRealization(hb.phaseIndex(h));
      if (!r) {
        why = "the model of nodal diameter " + std::to_string(hb.nodalDiameter(h)) +
              " has no modal form (Hill's method needs one)";
        break;
      }
      modes += (h == 0 ? 1 : 2) * r->numModes();
    }
    if (!why.empty()) {
      hill = false;
      if (setup.stability == "true") throw InputError("output/stability", why);
      log::info("stability not computed: " + why + "; folds are still flagged from the curve's path");
    } else if (setup.stability == "auto" && hb.numUnknowns() > 1500) {
      hill = false;
      log::warn("stability not computed: Hill's method on the reduced model needs an LU of " +
                std::to_string(hb.numUnknowns()) + " per point (set output: stability: true to compute it anyway)");
    } else {
      log::info("stability by Hill's method on the reduced model's modal realization (" + std::to_string(modes) +
                " modal coordinates over the harmonics)");
    }
  }
  // Hill's eigenproblem is dense of size 2 n nc: about a second per point at
  // 1200, so larger systems skip it unless the scene insists.
  if (hill && !hb.isReceptance() && setup.stability == "auto" && 2 * hb.numUnknowns() > 1200) {
    hill = false;
    log::warn("stability not computed: Hill's eigenproblem has " + std::to_string(2 * hb.numUnknowns()) +
              " unknowns per point (set output: stability: true to compute it anyway)");
  }
  int unstablePoints = 0, undeterminedPoints = 0;
  // The receptance form's verdicts are checked with twice the AFT samples: a friction
  // contact's Jacobian moves with where its stick-slip events fall on the sample grid,
  // and near Re = 0 that can flip the sign of an exponent (the default disc: +-10 /s at
  // 256..2048 samples on a lightly damped stretch). A point whose verdict changes is
  // undetermined (stable = 2 in the CSV and HDF5), not called either way.
  std::unique_ptr<hbm::HarmonicBalanceSystem> finer;
  if (hill && hb.isReceptance()) finer = hbm::withHarmonics(hb, harmonics, 2 * samples);
  std::map<std::string, int> special;  // fold, branch_point, period_doubling, neimark_sacker
  if (comm->getRank() == 0) {
    // Stability of every point first: the flags need the neighbours.
    std::vector<hbm::CurvePointStability> stability;
    Timer stabilityTimer;
    for (const auto& pt : branch.points) {
      hbm::CurvePointStability st;
      st.parameter = pt.parameter;
      st.omega = frequency(pt.parameter);
      if (hill) {
        const auto fl = hbm::hillStability(hb, pt.x, st.omega);
        st.stable = fl.stable ? 1 : 0;
        if (finer && hbm::hillStability(*finer, pt.x, st.omega).stable != fl.stable) st.stable = 2;
        if (fl.exponents.size() > 0) st.leading = fl.exponents(0), st.hasLeading = true;
      }
      stability.push_back(st);
    }
    if (hill) {
      std::ostringstream msg;
      msg << "stability: " << branch.points.size() << " points by Hill's method in " << stabilityTimer.seconds() << " s";
      log::info(msg.str());
    }
    auto determined = stability;  // an undetermined point neither loses nor regains stability
    for (auto& st : determined)
      if (st.stable == 2) st.stable = -1;
    // Flags per segment: the last point of one sweep and the first of the next are no path.
    std::vector<std::string> flags;
    std::vector<int> segmentOf;
    const auto bounds = segmentBounds(branch);
    for (std::size_t s = 0; s + 1 < bounds.size(); ++s) {
      const std::vector<hbm::CurvePointStability> part(determined.begin() + long(bounds[s]),
                                                       determined.begin() + long(bounds[s + 1]));
      const auto f = hbm::bifurcationFlags(part);
      flags.insert(flags.end(), f.begin(), f.end());
      segmentOf.insert(segmentOf.end(), f.size(), int(s));
    }
    AtomicFile file(csvPath);
    std::ofstream csv(file.tempPath());
    csv.precision(12);
    csv << "point,omega_rad_s,freq_hz" << (byOmega ? "" : "," + parameterName);
    for (int d : dofs) {
      const std::string& name = setup.dofNames[d];
      csv << "," << name << "_h0";
      for (int h : harmonics.harmonics())
        if (h > 0) csv << "," << name << "_amp_h" << h;
      csv << "," << name << "_max";
    }
    csv << ",stable,max_floquet_real,bifurcation,segment\n";
    const int nc = hb.numCoefficients();
    for (std::size_t i = 0; i < branch.points.size(); ++i) {
      const auto& pt = branch.points[i];
      const double w = frequency(pt.parameter);
      csv << i << "," << w << "," << w / (2 * M_PI);
      if (!byOmega) csv << "," << pt.parameter;
      for (int d : dofs) {
        csv << "," << (harmonics.contains(0) ? pt.x(d * nc + harmonics.cosIndex(0)) : 0.0);
        for (int h : harmonics.harmonics())
          if (h > 0) csv << "," << hb.amplitude(pt.x, d, h);
        const double peak = hbm::peakMagnitude(harmonics, Eigen::VectorXd(pt.x.segment(d * nc, nc)));
        csv << "," << peak;
        if (d == dofs.front()) plotW.push_back(byOmega ? w / (2 * M_PI) : pt.parameter), plotMax.push_back(peak);
      }
      if (hill) {
        const auto& st = stability[i];
        csv << "," << st.stable << ",";
        if (st.hasLeading) csv << st.leading.real();
        plotStable.push_back(st.stable);
        unstablePoints += st.stable == 0 ? 1 : 0;
        undeterminedPoints += st.stable == 2 ? 1 : 0;
      } else {
        csv << ",,";
        plotStable.push_back(1);
      }
      csv << "," << flags[i] << "," << segmentOf[i] << "\n";
      if (!flags[i].empty()) ++special[flags[i]];
    }
    csv.close();
    if (!csv) throw Error("cannot write " + csvPath);
    file.commit();
    post::SvgPlot plot("Forced response (harmonic balance, arclength continuation)",
                       byOmega ? "frequency (Hz)" : parameterName,
                       "max |x(t)| of " + setup.dofNames[dofs.front()]);
    // Stable stretches solid, unstable ones dashed (each stretch shares its end points).
    bool labelled[2] = {false, false};
    for (std::size_t i = 0; i + 1 < plotW.size();) {
      if (segmentOf[i + 1] != segmentOf[i]) {  // a new sweep: no line across
        ++i;
        continue;
      }
      std::size_t j = i + 1;
      while (j + 1 < plotW.size() && segmentOf[j + 1] == segmentOf[i] && (plotStable[j] != 0) == (plotStable[i] != 0))
        ++j;
      const bool stablePart = plotStable[i] != 0;  // undetermined points drawn with the stable ones
      std::string label;
      if (!labelled[stablePart]) {
        label = (hill ? std::string(stablePart ? "stable" : "unstable") + ", " : std::string()) + "H = " +
                std::to_string(harmonics.maxHarmonic());
        labelled[stablePart] = true;
      }
      plot.addLine(std::vector<double>(plotW.begin() + i, plotW.begin() + j + 1),
                   std::vector<double>(plotMax.begin() + i, plotMax.begin() + j + 1), post::SvgPlot::palette(0), label,
                   !stablePart);
      i = j;
    }
    plot.write(outDir + "/" + name + ".svg");
    // The full coefficient vectors, for post-processing and restarts.
    post::ResponseCurve curve;
    curve.numDofs = n;
    curve.numCoefficients = hb.numCoefficients();
    curve.samples = samples;
    curve.harmonics = harmonics.harmonics();
    for (std::size_t i = 0; i < branch.points.size(); ++i) {
      curve.omega.push_back(frequency(branch.points[i].parameter));
      curve.parameter.push_back(branch.points[i].parameter);
      curve.coefficients.push_back(branch.points[i].x);
      curve.stable.push_back(hill ? plotStable[i] : -1);
      curve.segment.push_back(segmentOf[i]);
    }
    post::writeResponseCurveHdf5(outDir + "/" + name + ".h5", curve);
  }
  summary.written.push_back(outDir + "/" + name + ".h5");
  summary.written.push_back(csvPath);
  summary.written.push_back(outDir + "/" + name + ".svg");
  std::ostringstream line;
  line << name << ": " << branch.points.size() << " points (";
  if (hill) {
    line << unstablePoints << " unstable by Hill's method";
    if (finer) line << ", " << undeterminedPoints << " undetermined (verdict changes with 2x samples)";
  }
  else line << "stability not computed";
  line << ") in " << timer.seconds() << " s, " << branch.stopReason;
  for (const auto& [kind, count] : special) line << "; " << count << " " << kind;
  summary.computed.push_back(line.str());
  if (special.count("turn")) {
    std::ostringstream msg;
    msg << name << ": the path turns at " << special["turn"] << " point(s) where Hill's method finds the same stability "
        << "on both sides: no fold; the continuation jumped or stalled there, and what follows may be another branch";
    log::warn(msg.str());
    summary.computed.push_back("warning: " + msg.str());
  }
  if (!branch.finished)
    log::warn("forced response incomplete: " + branch.stopReason + "; the branch so far is written");
  ForcedResponseResult result;
  result.branch = branch;
  result.seconds = timer.seconds();
  result.startMethod = start.method;
  if (!plotMax.empty()) {
    const std::size_t ip = std::max_element(plotMax.begin(), plotMax.end()) - plotMax.begin();
    result.peak = plotMax[ip];
    result.peakParameter = branch.points[ip].parameter;
    result.peakOmega = frequency(branch.points[ip].parameter);
    // Both checks at the largest-response point.
    result.samplesCheck = samplesCheck(setup, branch.points[ip], plotMax[ip]);
    summary.computed.push_back(result.samplesCheck);  // rank 0
    if (setup.harmonicsCheckTo >= 0) {
      result.harmonicsCheck =
          harmonicsCheck(setup, branch, ip, plotMax[ip], outDir + "/" + name + "_harmonics.csv", summary,
                         result.harmonicsPeak);
      summary.computed.push_back(result.harmonicsCheck);
    }
  }
  return result;
}

}  // namespace cyclone::scenes
