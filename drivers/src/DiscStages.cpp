// The scene stages of the disc chain: reduced models per nodal diameter
// (`analysis: reduced_model`), and the forced response with friction at the
// shroud with its parameter studies (`analysis: disc_response`). Keys in docs/scenes.md.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <set>
#include <sstream>

#include "DiscStages.hpp"

#include <Teuchos_Comm.hpp>
#include "cyclone/core/AtomicFile.hpp"
#include "cyclone/core/NumberText.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/hbm/HarmonicBalanceSystem.hpp"
#include "cyclone/hbm/PeakMagnitude.hpp"
#include "cyclone/mesh/Mesh.hpp"
#include "cyclone/post/SweepInTimeFiles.hpp"
#include "cyclone/post/SvgPlot.hpp"
#include "cyclone/rom/HybridFrfModel.hpp"
#include "cyclone/disc/ShroudContactLaw.hpp"
#include "cyclone/disc/DiscHarmonicBalance.hpp"
#include "cyclone/disc/DiscForcedResponse.hpp"
#include "cyclone/disc/DiscPointStates.hpp"
#include "cyclone/post/DiscPointFiles.hpp"
#include "cyclone/disc/DiscParameterStudy.hpp"
#include "cyclone/disc/DiscReducedModels.hpp"
#include "cyclone/scenes/SceneSection.hpp"

namespace cyclone::scenes {

namespace {

// The reduced models per nodal diameter (cached), their check against the full FE
// compliance as rom_check.svg/.csv, and the summary's lines.
DiscReducedModels reducedModelsStage(const mesh::Mesh& mesh, const DiscPlan& plan, const std::string& outDir,
                                     linalg::CommPtr comm, SceneSummary& summary) {
  const auto& ms = plan.modelSpec;
  const std::string kind = disc::reducedModelKindName(ms.kind);
  Timer timer;
  auto models = disc::buildDiscReducedModels(mesh, ms, plan.nds, plan.cacheDir, comm);
  const auto& c = models.check;
  std::ostringstream estimate;
  if (c.nodalDiameter >= 0) {
    estimate << "largest relative error " << c.maxError() << " against the full FE compliance at ND "
             << c.nodalDiameter << " over " << c.hz.size() << " frequencies (" << c.hz.front() << ".." << c.hz.back()
             << " Hz)";
    if (c.reused) estimate << "; the model reused, checked when it was built (" << c.checkedAt << ")";
    if (comm->getRank() == 0) {
      post::SvgPlot plot("Reduced model (" + kind + ", " + std::to_string(ms.modes) +
                             " modes) against the full FE model, ND " + std::to_string(c.nodalDiameter),
                         "frequency (Hz)", "|A| at the mid-blade node (mm/N)");
      plot.addLine(c.hz, c.full, post::SvgPlot::palette(0), "full FE (complex solve)");
      plot.addMarkers(c.hz, c.reduced, post::SvgPlot::palette(1), "reduced model");
      plot.write(outDir + "/rom_check.svg");
      disc::writeReducedModelCheckCsv(outDir + "/rom_check.csv", c);
    }
    summary.written.push_back(outDir + "/rom_check.svg");
    summary.written.push_back(outDir + "/rom_check.csv");
    summary.computed.push_back("reduced model check: " + estimate.str());
  } else if (!c.notMade.empty()) {
    estimate << "not checked: " << c.notMade;
    summary.computed.push_back("reduced model check: not made, " + c.notMade);
  } else {
    estimate << "not checked (a reused model built before the check, or check_frequencies: 0)";
  }
  summary.stages.push_back({"reduced models (" + kind + ")", timer.seconds(), estimate.str()});
  std::ostringstream line;
  line << "reduced models (" << kind << ", " << ms.modes << " natural frequencies per ND, "
       << models.retainedNodes.size() << " retained nodes";
  if (!models.retainedMeans.empty()) line << " and " << models.retainedMeans.size() << " patch means";
  line << ") for ND";
  for (const auto& [k, m] : models.models) line << " " << k;
  line << " at " << ms.rpm << " rpm: " << models.built << " built, " << models.reused << " reused, "
       << models.seconds << " s";
  summary.computed.push_back(line.str());
  for (const auto& [k, f] : models.files) summary.written.push_back(f);
  return models;
}

// The reference curve disc_frc: traced, written, its headline first in the summary.
disc::DiscForcedResponse referenceStage(const mesh::Mesh& mesh, const DiscReducedModels& models, const DiscPlan& plan,
                                        const disc::DiscSweepOptions& sweep, const std::string& outDir,
                                        linalg::CommPtr comm, SceneSummary& summary) {
  const auto& spec = plan.spec;
  Timer timer;
  auto solved = disc::solveDiscForcedResponse(mesh, models, spec, sweep);
  std::ostringstream line;
  line << "engine order " << spec.engineOrder << " on ND " << plan.modelSpec.checkNodalDiameter << ": "
       << solved.estimateText << "; sweep " << solved.fromHz << " -> " << solved.toHz << " Hz";
  summary.computed.push_back(line.str());
  // The interface the contacts make up: its law, total stiffness and load.
  const auto contact = disc::shroudContactValues(
      mesh, disc::shroudContactPairs(mesh, models.sectors, models.sector.axis, spec.contact), spec.contact);
  summary.computed.push_back(contact.text);
  log::info(contact.text);
  log::info(line.str());
  const auto& reference = solved.curve;
  // Contacts far stiffer than the sector at their pairs (kn = 1e7 N/mm^3 on the default
  // disc, 4e5 times: no first point, and the failure did not say why; 4e4 times traced).
  const std::string stiff =
      solved.contactStiffnessRatio > 1e4
          ? "the shroud contacts' normal stiffness is up to " + numberText(solved.contactStiffnessRatio, 3) +
                " times the sector's own at their pairs: far more than holds the faces together, and it makes the "
                "balance stiff (lower disc_response/contact/kn and kt)"
          : std::string();
  if (reference.branch.points.empty()) {
    const std::string roundoff = disc::preloadRoundoffText(
        disc::preloadOverExcitation(mesh, plan.modelSpec.sectors, plan.modelSpec.axis, spec),
        sweep.continuation.tolerance);
    throw SolverError("disc_frc: no point of the curve was computed, so nothing was written" +
                      (roundoff.empty() ? "" : "; " + roundoff) + ": " + reference.branch.stopReason +
                      (stiff.empty() ? "" : "; " + stiff));
  }
  if (solved.contactStiffnessRatio > 1e5) {
    log::warn(stiff);
    summary.computed.push_back("warning: disc_frc: " + stiff);
  }
  writeDiscCurve(solved, solved.setup, reference, "disc_frc", solved.warnings, outDir, comm, summary);
  summary.stages.push_back(
      {"forced response (H = " + std::to_string(solved.setup.system->aft().harmonics().maxHarmonic()) + ", " +
           std::to_string(reference.branch.points.size()) + " points)",
       // the time domain's own stages are not the curve's (they have their rows)
       timer.seconds() - (solved.peakInTime ? solved.peakInTime->seconds : 0.0) -
           (solved.sweepsInTime ? solved.sweepsInTime->seconds : 0.0),
       "Newton tolerance " + numberText(sweep.continuation.tolerance) + " (residual relative to the forces); " +
           reference.samplesCheck.text + "; " + reference.harmonicsCheck.text});
  // The headline: the peak at the highest harmonic count reached, converged or labelled
  // an estimate with the last change next to it.
  if (solved.headline.found()) {
    summary.computed.insert(summary.computed.begin(), solved.headline.text);
    if (solved.peakInTime) {
      summary.computed.insert(summary.computed.begin() + 1, solved.peakInTime->text);
      post::writePeakInTimeFiles(outDir + "/disc_peak_in_time.csv", outDir + "/disc_peak_in_time.svg",
                                 *solved.peakInTime);
      summary.written.push_back(outDir + "/disc_peak_in_time.csv");
      summary.written.push_back(outDir + "/disc_peak_in_time.svg");
      const auto& td = *solved.peakInTime;
      summary.stages.push_back({"time-domain check at the peak", td.seconds,
                                "the ring of " + std::to_string(td.sectors) + " sectors by the central difference, " +
                                    std::to_string(td.stepsPerPeriod) + " steps a period, " +
                                    std::to_string(td.periods) + " periods: " +
                                    (td.steady() ? "settled" : "not settled (its range is the answer)")});
    }
    if (solved.beyondSmallDisplacements()) {
      const std::string why = "disc_frc: the peak's motion, " + numberText(solved.headline.peak.value) +
                              " mm, is " + numberText(100 * solved.headline.peak.value / solved.sectorSize, 3) +
                              " % of the sector's size (its bounding box's diagonal, " +
                              numberText(solved.sectorSize, 4) +
                              " mm): beyond the small displacements the linear reduced models hold (check "
                              "disc_response/excitation/amplitude)";
      log::warn(why);  // log::warn puts "warning: " before it
      summary.computed.insert(summary.computed.begin() + 1, "warning: " + why);
    }
  } else {
    // No peak is the run's main answer missing: said first, with what stopped it.
    std::string why = "disc_frc: no friction-damped peak was found (" + reference.harmonicsCheck.text + ")";
    if (plan.modelSpec.lossFactor == 0)
      why += "; the reduced model has no damping (reduced_model/loss_factor: 0), so where the contacts stay stuck "
             "the response grows without bound";
    log::warn(why);
    summary.computed.insert(summary.computed.begin(), "warning: " + why);
  }
  // The band swept in time: the disc's amplitude where the periodic response is not its
  // motion (the hammering shroud), so written whether or not a periodic peak was found.
  if (solved.sweepsInTime) {
    summary.computed.insert(summary.computed.begin() + 1, solved.sweepsInTime->text());
    for (const auto& path : post::writeSweepInTimeFiles(outDir, "disc_time_sweep", *solved.sweepsInTime))
      summary.written.push_back(path);
    const auto& first = solved.sweepsInTime->sweeps.front();
    summary.stages.push_back(
        {"time-domain sweep (" + std::to_string(solved.sweepsInTime->sweeps.size()) + " preloads, " +
             std::to_string(first.points.size()) + " frequencies)",
         solved.sweepsInTime->seconds,
         "the ring of " + std::to_string(first.sectors) + " sectors by the central difference, " +
             std::to_string(first.stepsPerPeriod) + " steps a period; the amplitude's resolution in frequency is the "
             "grid's step, " + numberText(first.resolutionHz(), 3) + " Hz"});
  }
  return solved;
}

}  // namespace

// Writes a disc curve with its summary lines (a range-end warning says where to widen it).
void writeDiscCurve(const disc::DiscForcedResponse& solved, const ForcedResponseSetup& setup,
                    const ForcedResponseResult& result, const std::string& name, const std::vector<std::string>& warnings,
                    const std::string& outDir, linalg::CommPtr comm, SceneSummary& summary) {
  writeForcedResponse(setup, result, outDir, name, comm, summary);
  for (const auto& w : warnings)
    summary.computed.push_back("warning: " + name + ": " + w + " (" + solved.estimateText +
                               "); widen disc_response/frequency_range_hz");
}

DiscStagePlan readDiscStagePlan(SceneSection& scene, const mesh::Mesh& mesh, int builtInSectors, bool forcedResponse,
                                const std::string& outDir,
                                const std::shared_ptr<continuation::TraceCheckpoints>& checkpoints) {
  auto r = scene.section("reduced_model");
  auto d = scene.section("disc_response");
  DiscStagePlan stages{readDiscPlan(scene, r, d, mesh, builtInSectors, forcedResponse, outDir), forcedResponse,
                       {}, {}, d.section("studies")};
  if (forcedResponse) {
    stages.sweep = readSweepOptions(d, stages.plan, checkpoints);
    // A preload whose round-off alone is far above the tolerance, relative to the
    // excitation: an amplitude of 1e-140 N against the default disc's 2e4 N passed the
    // floor of 1e-150 and failed only after the reduced models, as "no start". Refused
    // here from 100 times the tolerance (1e-4 N, 4 times, already found no start: the
    // reference curve's failure names the keys from a tenth).
    const auto& plan = stages.plan;
    const double tolerance = stages.sweep->continuation.tolerance;
    const double ratio = disc::preloadOverExcitation(mesh, plan.modelSpec.sectors, plan.modelSpec.axis, plan.spec);
    if (ratio * std::numeric_limits<double>::epsilon() > 100 * tolerance)
      throw InputError(d.where("excitation/amplitude"), disc::preloadRoundoffText(ratio, tolerance));
    stages.hysteresisContacts = readHysteresisContacts(d, mesh, stages.plan.spec);
  }
  // The studies' values are read with their curves; their names here, so a misspelt one
  // costs no work.
  std::set<std::string> studyNames(std::begin(kStudyNames), std::end(kStudyNames));
  stages.studies.rejectKeysOtherThan(studyNames);
  for (const auto& name : studyNames)
    if (stages.studies.has(name) && stages.studies.getDoubleList(name, {}).empty())
      throw InputError(stages.studies.where(name), "needs a list of values");
  // And each value, before any work (a negative mu was refused after the reference curve).
  if (forcedResponse) {
    const auto& plan = stages.plan;
    int top = plan.harmonicsCheckTo;
    for (int h : plan.spec.harmonics) top = std::max(top, h);
    for (const auto& name : studyNames) {
      if (!stages.studies.has(name)) continue;
      const auto values = stages.studies.getDoubleList(name, {});
      stages.studies.underKey(name, [&] {
        disc::checkDiscStudyValues(mesh, plan.modelSpec.sectors, plan.modelSpec.axis, plan.spec,
                                   *disc::discStudyParameterFromName(name), values, plan.modelSpec.modes, top,
                                   plan.modelSpec.material.E);
      });
    }
  }
  d.rejectUnknownKeys();
  return stages;
}

void discStages(const DiscStagePlan& stages, const mesh::Mesh& mesh, const std::string& outDir, linalg::CommPtr comm,
                SceneSummary& summary) {
  const DiscPlan& readPlan = stages.plan;
  const bool forcedResponse = stages.forcedResponse;
  if (readPlan.rebuildCache && comm->getRank() == 0) std::filesystem::remove_all(readPlan.cacheDir);
  const auto models = reducedModelsStage(mesh, readPlan, outDir, comm, summary);
  if (!forcedResponse) return;
  const auto& sweep = *stages.sweep;
  const auto& hysteresisContacts = stages.hysteresisContacts;
  auto solved = referenceStage(mesh, models, readPlan, sweep, outDir, comm, summary);
  // Harmonics by an error target traced the reference again with the harmonics that met
  // it: the stages after it (studies, peak following) work with those.
  DiscPlan plan = readPlan;
  if (solved.curve.harmonicsTarget.retraced) {
    const auto& hb = *solved.setup.system;
    plan.spec.harmonics = hb.aft().harmonics().harmonics();
    plan.spec.samples = hb.aft().numSamples();
  }
  peakOutputsStage(mesh, models, plan, solved, hysteresisContacts, outDir, comm, summary);

  // Parameter studies: one curve per value; then the peaks followed over a parameter,
  // compared with those curves' tops. The studies' line in the stage table comes after
  // the peak following's, its time through it (as the run report has always shown them).
  Timer studiesTimer;
  const auto studies = valueStudiesStage(stages.studies, mesh, models, plan, solved, sweep, outDir, comm, summary);
  followDiscPeaks(plan.peakStudies, mesh, models, plan, solved.setup, solved.curve, solved.fromHz, solved.toHz,
                  studies.tops, outDir, comm, summary);
  if (studies.curves > 0)
    summary.stages.push_back({"parameter studies (" + std::to_string(studies.curves) + " curves)",
                              studiesTimer.seconds(),
                              "the samples check per curve (summary); the harmonic truncation: the reference curve's check"});
}

}  // namespace cyclone::scenes
