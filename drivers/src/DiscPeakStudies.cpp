// disc_response/peak_studies: the scene's keys onto disc::followDiscPeak (the library
// follows the peak), its files (post::writePeakFollowingFiles) and the summary's line.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include <Teuchos_Comm.hpp>

#include "DiscStages.hpp"
#include "cyclone/disc/DiscPeakFollowing.hpp"
#include "cyclone/core/AtomicFile.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/core/NumberText.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/post/PeakFollowingFiles.hpp"
#include "cyclone/scenes/SceneSection.hpp"

namespace cyclone::scenes {

namespace {

// The summary's line: the work, the optimum and where it lies, the difference from the
// value-list study's frequency curves at shared values.
std::string peakStudyLine(const std::string& name, const std::vector<double>& range, const disc::DiscPeakFollowing& f,
                          const std::vector<continuation::KnownPeak>& curvePeaks) {
  const auto& whole = f.curve;
  const bool byForce = f.byForce;
  const auto merit = [&f](const continuation::FollowedPeak& p) { return f.merit(p); };
  std::ostringstream line;
  line.precision(6);
  if (f.continued)
    line << "peak continued over the " << name << " " << range[0] << ".." << range[1] << " by LOCA: "
         << whole.points.size() << " points in " << whole.seconds << " s (" << whole.searches << " LOCA steps, "
         << whole.solves << " Newton solves); ";
  else
    line << "peak following over the " << name << " " << range[0] << ".." << range[1] << ": " << whole.points.size()
         << " values in " << whole.seconds << " s (" << whole.searches << " peak searches, " << whole.solves
         << " Newton solves, " << whole.sweeps << " band sweeps, " << whole.jumps() << " jumps to another peak); ";
  if (whole.optimum < 0) {  // the speed: an operating condition, its largest peak
    const auto& p = whole.points[whole.largestPeak()];
    line << "largest peak " << p.measure << " at " << name << " " << p.parameter << " (" << p.frequency / (2 * M_PI)
         << " Hz; the reduced models built at each " << name << ")";
  } else {
    const auto& best = whole.points[std::size_t(whole.optimum)];
    line << "smallest peak" << (byForce ? " per unit force " : " ") << merit(best) << " at " << name << " "
         << best.parameter << " (" << best.frequency / (2 * M_PI) << " Hz, "
         << (f.optimumAtRangeEnd() ? "at the range's end: the optimum may lie beyond it"
                 : whole.optimumLocated ? "located between its neighbours" : "the grid's")
         << ")";
  }
  // The optimum's peak with more harmonics: its truncation error, as the headline's.
  if (const auto& check = f.optimumCheck; !check.levels.empty()) {
    line << "; the optimum with harmonics";
    for (std::size_t l = 0; l < check.levels.size(); ++l) {
      const auto& level = check.levels[l];
      line << (l ? ", " : " ") << "0.." << level.maxHarmonic << ": ";
      if (level.peak.found)
        line << level.peak.value;
      else
        line << "not found";
    }
    constexpr double kTolerance = 0.01;
    if (check.converged(kTolerance))
      line << " (converged to " << 100 * kTolerance << " %: the raises changed it by at most " << 100 * check.change
           << " %)";
    else if (check.change >= 0)
      line << " (an estimate: the raises changed it by up to " << 100 * check.change << " %)";
    else
      line << " (an estimate: a raised level's peak not found)";
    if (whole.optimum >= 0 && std::size_t(whole.optimum) < f.forceBeyond.size() && f.forceBeyond[std::size_t(whole.optimum)] >= 0)
      line << "; there the contact forces' harmonics above " << check.levels.front().maxHarmonic << " are "
           << 100 * f.forceBeyond[std::size_t(whole.optimum)] << " % of those kept";
  }
  // The value-list study's peaks (frequency curves) at the same values.
  if (const auto agreement = f.agreementWith(curvePeaks); agreement.compared > 0)
    line << "; against the frequency curves at " << agreement.compared
         << " values: " << agreement.largestRelativeDifference << " (relative)";
  if (!whole.complete) line << "; stopped (" << continuation::peakFollowingEndName(whole.end) << "): " << whole.stopReason;
  return line.str();
}

}  // namespace

std::vector<PeakStudySpec> readPeakStudies(SceneSection peakStudies, const DiscResponseSpec& spec, double lossFactor,
                                           double rpm) {
  std::vector<PeakStudySpec> out;
  for (const std::string name : {"preload", "mu", "contact_stiffness", "force", "loss_factor", "clearance", "speed"}) {
    if (!peakStudies.has(name)) continue;
    auto s = peakStudies.section(name);
    const auto range = s.getDoubleList("range", {});
    if (name == "clearance") {  // mm, of any sign (negative: interference)
      if (range.size() != 2 || !(std::isfinite(range[0]) && std::isfinite(range[1]) && range[1] > range[0]))
        throw InputError(s.where("range"), "needs [from, to] with from < to (mm; negative: interference)");
    } else if (name == "speed") {  // rpm; 0 is a speed (no prestress)
      if (range.size() != 2 || !(range[0] >= 0 && std::isfinite(range[1]) && range[1] > range[0]))
        throw InputError(s.where("range"), "needs [from, to] with 0 <= from < to (rpm)");
    } else if (range.size() != 2 || !(range[0] > 0 && range[1] > range[0])) {
      throw InputError(s.where("range"), "needs [from, to] with 0 < from < to");
    }
    const int values = s.getInt("values", 24);
    if (values < 3 || values > 400) throw InputError(s.where("values"), "must lie in 3..400");
    const bool byContinuation = s.getChoice<bool>(
        "method", "peak_search", {{"peak_search", false}, {"continuation", true}}, [](const std::string& word) {
          return "must be peak_search (a peak search per value) or continuation (one LOCA continuation of the "
                 "peak), not '" + word + "'";
        });
    if (byContinuation && s.has("values"))
      throw InputError(s.where("values"), "is not used by method continuation (LOCA's steps are the points): drop it");
    if (byContinuation && (name == "loss_factor" || name == "speed"))
      throw InputError(s.where("method"), "continuation follows the contact parameters, the clearance and the force; "
                                          "the " + name + " rebuilds the system per value: use peak_search");
    s.rejectUnknownKeys();
    // force: the excitation's scale (times disc_response/excitation/amplitude), as the studies';
    // contact_stiffness: kn = kt together, so the scene's two must be equal.
    // loss_factor: the reduced models' (reduced_model/loss_factor); speed: the speed they
    // are built at (reduced_model/speed_rpm).
    double refValue = name == "speed" ? rpm : lossFactor;
    if (name != "loss_factor" && name != "speed")
      refValue = s.underKey("range", [&] { return disc::discReferenceValue(spec, *disc::discStudyParameterFromName(name)); });
    if (!(refValue >= range[0] && refValue <= range[1]))
      throw InputError(s.where("range"), "must contain the scene's " + name + " (" + numberText(refValue) +
                                             "): the following starts at the reference curve's peak");
    out.push_back({name, range[0], range[1], values, byContinuation});
  }
  peakStudies.rejectUnknownKeys();
  return out;
}

void followDiscPeaks(const std::vector<PeakStudySpec>& studies, const mesh::Mesh& mesh, const DiscReducedModels& models,
                     const DiscPlan& plan, const ForcedResponseSetup& reference,
                     const ForcedResponseResult& referenceResult, double bandFromHz, double bandToHz,
                     const std::map<std::string, std::vector<continuation::KnownPeak>>& listed,
                     const std::string& outDir,
                     linalg::CommPtr comm, SceneSummary& summary) {
  for (const auto& study : studies) {
    const std::string& name = study.name;
    disc::DiscPeakFollowingSpec following;
    following.parameter = *disc::discStudyParameterFromName(name);
    following.from = study.from, following.to = study.to, following.values = study.values;
    if (study.continuation) following.method = disc::DiscPeakFollowingSpec::Method::Continuation;
    const auto listedHere = listed.count(name) ? listed.at(name) : std::vector<continuation::KnownPeak>{};
    for (const auto& p : listedHere) following.extraValues.push_back(p.parameter);
    following.knownPeaks = listedHere;
    // The speed: the scene's reduced models (same kind, nodal diameters and cache) at each speed.
    following.modelsAtSpeed = [&mesh, &plan, comm](double speed) {
      auto ms = plan.modelSpec;
      ms.rpm = speed;
      ms.checkNodalDiameter = -1;  // the check against the full FE model is the scene speed's
      // Only the diameters the followed harmonics live on (not the harmonics check's).
      const auto nds = disc::nodalDiametersFor(ms.sectors, plan.spec.engineOrder, plan.spec.harmonics);
      return disc::buildDiscReducedModels(mesh, ms, nds, plan.cacheDir, comm);
    };
    const disc::DiscPeakFollowing f =
        followDiscPeak(mesh, models, plan.spec, reference, referenceResult, bandFromHz, bandToHz, following);
    const std::string unit = name == "preload"             ? " / N"
                             : name == "contact_stiffness" ? " / (N/mm)"
                             : name == "clearance"         ? " / mm"
                             : name == "speed"             ? " / rpm"
                                                           : "";
    if (comm->getRank() == 0)
      for (const auto& path : post::writePeakFollowingFiles(outDir, name, unit, f, listedHere))
        summary.written.push_back(path);
    if (f.continued) summary.continuedPeakStudies.push_back(name);
    std::string line = peakStudyLine(name, {study.from, study.to}, f, listedHere);
    for (const auto& w : f.warnings) line += "; warning: " + w;
    summary.computed.push_back(line);
    log::info(line);
    summary.stages.push_back(
        {"peak following (" + name + ")", f.curve.seconds,
         std::string(study.continuation ? "the peak continued by LOCA on the peak condition (the frequency curve "
                                          "parametrised by the response's phase)"
                                        : "each peak by a peak search to 1e-7 of its frequency") +
             "; the harmonics are the reference curve's" +
             (name == "speed" ? "; the reduced models built again at each speed (no interpolation between speeds)"
                              : "")});
  }
}

}  // namespace cyclone::scenes
