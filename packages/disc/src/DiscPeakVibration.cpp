#include "cyclone/disc/DiscPeakVibration.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "cyclone/continuation/NewtonSolve.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/hbm/HarmonicLoads.hpp"
#include "cyclone/hbm/HarmonicRefinement.hpp"
#include "cyclone/hbm/ProjectedReceptance.hpp"

namespace cyclone::disc {

PeakPoint referencePeakPoint(response::ForcedResponseSetup& setup, const response::ForcedResponseResult& reference) {
  PeakPoint p;
  std::ostringstream what;
  what.precision(6);
  const auto& best = reference.harmonicsCheck.converged;
  if (best.found && best.x.size() > 0) {
    p.raised = hbm::withHarmonics(*setup.system, hbm::HarmonicSet(best.harmonics), best.samples);
    p.system = p.raised.get();
    p.x = best.x, p.omega = 2 * M_PI * best.hz;
    what << "the peak with harmonics 0.." << best.maxHarmonic << " at " << best.hz << " Hz";
    std::ostringstream caveat;
    caveat.precision(3);
    if (best.change < 0) caveat << "its convergence in the harmonics is not known";
    else if (best.change > 1e-2)
      caveat << "H " << best.belowHarmonic << " -> " << best.maxHarmonic << " changed the peak by " << 100 * best.change
             << " %";
    if (best.notFoundHarmonic >= 0)
      caveat << (caveat.tellp() > 0 ? ", and " : "") << "H = " << best.notFoundHarmonic << " found no peak";
    if (caveat.tellp() > 0)
      p.caveat = "an estimate, as the peak it stands on (" + caveat.str() + "): the vibratory stress carries that error";
  } else {
    const auto& pts = reference.branch.points;
    if (pts.empty()) throw Error("no point of the reference curve to write its peak at");
    const auto it = std::min_element(pts.begin(), pts.end(), [&](const auto& a, const auto& b) {
      return std::abs(a.parameter - reference.peakParameter) < std::abs(b.parameter - reference.peakParameter);
    });
    p.system = setup.system.get();
    p.x = it->x, p.omega = setup.apply(it->parameter).first;
    what << "the traced point nearest the peak, " << p.omega / (2 * M_PI) << " Hz, harmonics 0.."
         << setup.system->aft().harmonics().maxHarmonic();
    p.caveat = "an estimate: the harmonic convergence of this point is not known (no harmonics check found its peak)";
  }
  p.what = what.str();
  return p;
}

PeakPoint referencePointAt(response::ForcedResponseSetup& setup, const response::ForcedResponseResult& reference, double hz) {
  const auto& pts = reference.branch.points;
  if (pts.empty()) throw Error("no point of the reference curve");
  double lo = 1e300, hi = -1e300;
  const continuation::BranchPoint* nearest = nullptr;
  double nearestGap = 1e300;
  for (const auto& pt : pts) {
    const double f = setup.apply(pt.parameter).first / (2 * M_PI);
    lo = std::min(lo, f), hi = std::max(hi, f);
    if (std::abs(f - hz) < nearestGap) nearestGap = std::abs(f - hz), nearest = &pt;
  }
  if (hz < lo || hz > hi)
    throw InputError("disc_response/peak_stress/at_hz", std::to_string(hz) + " Hz lies outside the traced curve (" +
                                                            std::to_string(lo) + ".." + std::to_string(hi) + " Hz)");
  PeakPoint p;
  p.system = setup.system.get();
  p.omega = 2 * M_PI * hz;
  p.x = nearest->x;
  const auto problem = continuationProblem(*p.system, response::ForcedResponseSetup::Parameter::ForceScale, p.omega);
  const auto newton = continuation::solveNewton(problem, p.x, setup.excitationScale, setup.continuation.tolerance);
  if (!newton.converged)
    throw SolverError("disc_response/peak_stress/at_hz: no solution at " + std::to_string(hz) +
                      " Hz from the traced point nearest it (residual " + std::to_string(newton.residualNorm) + ")");
  std::ostringstream what;
  what.precision(6);
  what << hz << " Hz (harmonics 0.." << p.system->aft().harmonics().maxHarmonic() << ")";
  p.what = what.str();
  p.caveat = "at a chosen frequency of the reference curve, whose harmonics check concerns its peak";
  return p;
}

DiscPeakVibration solveDiscPeakVibration(const mesh::Mesh& mesh, const DiscReducedModels& models,
                                         const DiscModelSpec& modelSpec, const PeakPoint& point,
                                         double excitationScale, const fatigue::FatigueMaterial* margin,
                                         linalg::CommPtr comm) {
  const auto loads = hbm::harmonicLoads(*point.system, point.x, point.omega, excitationScale);
  // The reduced model's own response to these loads at its retained DOFs: the harmonic
  // balance solution there (the condensed unknowns' base model).
  const auto projected = std::dynamic_pointer_cast<const hbm::ProjectedReceptance>(point.system->receptance());
  const hbm::ReceptanceModel& base = projected ? projected->base() : *point.system->receptance();
  const auto solution = hbm::harmonicResponse(base, loads, point.omega);
  const auto prestress = discPrestress(mesh, models.sector, modelSpec, comm);
  rom::NodalDiameterModelProblem problem;
  problem.material = modelSpec.material;
  problem.fixedNodeSets = modelSpec.fixedNodeSets;
  problem.retainedNodeSets = modelSpec.retainedNodeSets;
  problem.retainedMeans = modelSpec.retainedMeans;
  problem.lossFactor = modelSpec.lossFactor;
  if (prestress) problem.prestress = std::make_shared<const cyclic::PrestressState>(*prestress);
  DiscPeakVibration out;
  out.harmonics = int(loads.size());
  out.vibration = fatigue::recoverSectorVibration(mesh, models.sector, problem, loads, point.omega, comm);
  double diff = 0, scale = 0;
  for (std::size_t k = 0; k < solution.size(); ++k) {
    diff = std::max(diff, (out.vibration.retainedResponse[k] - solution[k]).cwiseAbs().maxCoeff());
    scale = std::max(scale, solution[k].cwiseAbs().maxCoeff());
  }
  out.modelError = diff / scale;
  if (margin) out.fatigue = fatigue::assessFatigue(out.vibration, *margin);
  return out;
}

}  // namespace cyclone::disc
