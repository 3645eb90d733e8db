// disc_response/peak_studies: the scene's keys onto disc::followDiscPeak (the library
// follows the peak) and its outputs: peak_<name>.csv/.svg/.h5 and the summary's line.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <filesystem>

#include <Teuchos_Comm.hpp>

#include "SceneStages.hpp"
#include "cyclone/disc/DiscPeakFollowing.hpp"
#include "cyclone/core/AtomicFile.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/io/ResponseCurveFile.hpp"
#include "cyclone/post/SvgPlot.hpp"
#include "cyclone/scenes/SceneSection.hpp"

namespace cyclone::scenes {

namespace {

void writePeakStudy(const std::string& name, const std::string& unit, const disc::DiscPeakFollowing& following,
                    const hbm::HarmonicBalanceSystem& hb, const std::vector<StudyPeak>& listed,
                    const std::string& outDir, SceneSummary& summary) {
  const auto& curve = following.curve;
  const bool continued = following.continued;
  {
    // Every peak's whole solution (the response-curve schema: /parameter, /omega at
    // the peak, /coefficients; no stability computed), for post-processing.
    io::ResponseCurve h5;
    h5.numDofs = hb.numDofs();
    h5.numCoefficients = hb.numCoefficients();
    h5.samples = hb.aft().numSamples();
    h5.harmonics = hb.aft().harmonics().harmonics();
    for (const auto& p : curve.points) {
      h5.omega.push_back(p.frequency);
      h5.parameter.push_back(p.parameter);
      h5.coefficients.push_back(p.x);
      h5.stable.push_back(-1);
    }
    io::writeResponseCurveHdf5(outDir + "/peak_" + name + ".h5", h5);
    summary.written.push_back(outDir + "/peak_" + name + ".h5");
  }
  {
    AtomicFile file(outDir + "/peak_" + name + ".csv");
    std::ofstream out(file.tempPath());
    out.precision(10);
    // force_beyond_h: the contact forces' harmonics above the study's H over those kept at
    // each peak (empty: not known), what the truncation leaves out there.
    out << name << ",peak_hz,peak_max_abs,jump,optimum,force_beyond_h\n";
    for (std::size_t i = 0; i < curve.points.size(); ++i) {
      const auto& p = curve.points[i];
      out << p.parameter << "," << p.frequency / (2 * M_PI) << "," << p.measure << "," << (p.jump ? 1 : 0) << ","
          << (int(i) == curve.optimum ? 1 : 0) << ",";
      if (i < following.forceBeyond.size() && following.forceBeyond[i] >= 0) out << following.forceBeyond[i];
      out << "\n";
    }
    file.check(out);
    file.commit();
  }
  // The clearance on a linear axis (zero and interference are values of it), the others in log.
  const bool linear = name == "clearance" || name == "speed";
  auto axis = [linear](double v) { return linear ? v : std::log10(v); };
  post::SvgPlot plot("Resonance peak against the " + name + (continued ? " (one LOCA continuation)" : " (followed)"),
                     linear ? name + unit : "log10(" + name + unit + ")", "peak max |x(t)|");
  std::vector<double> x, y;
  for (const auto& p : curve.points) x.push_back(axis(p.parameter)), y.push_back(p.measure);
  plot.addLine(x, y, post::SvgPlot::palette(0), continued ? "continued peak" : "followed peak");
  if (!listed.empty()) {
    std::vector<double> lx, ly;
    for (const auto& s : listed) lx.push_back(axis(s.value)), ly.push_back(s.peak);
    plot.addMarkers(lx, ly, post::SvgPlot::palette(2), "frequency curves (studies)");
  }
  if (curve.optimum >= 0) {
    const auto& o = curve.points[std::size_t(curve.optimum)];
    plot.addMarkers({axis(o.parameter)}, {o.measure}, "#000000", "optimum", 5.0);
    std::ostringstream text;
    text.precision(4);
    text << "optimum " << o.parameter;
    plot.addText(axis(o.parameter), o.measure, text.str());
  }
  plot.write(outDir + "/peak_" + name + ".svg");
  summary.written.push_back(outDir + "/peak_" + name + ".csv");
  summary.written.push_back(outDir + "/peak_" + name + ".svg");
}

// The summary's line: the work, the optimum and where it lies, the difference from the
// value-list study's frequency curves at shared values.
std::string peakStudyLine(const std::string& name, const std::vector<double>& range, const disc::DiscPeakFollowing& f,
                          const std::map<std::string, std::vector<StudyPeak>>& listed) {
  const auto& whole = f.curve;
  const auto& grid = f.grid;
  const bool byForce = f.byForce;
  const auto merit = [&f](const continuation::FollowedPeak& p) { return f.merit(p); };
  int jumps = 0;
  for (const auto& p : whole.points) jumps += p.jump;
  std::ostringstream line;
  line.precision(6);
  if (f.continued)
    line << "peak continued over the " << name << " " << range[0] << ".." << range[1] << " by LOCA: "
         << whole.points.size() << " points in " << whole.seconds << " s (" << whole.searches << " LOCA steps, "
         << whole.solves << " Newton solves); ";
  else
    line << "peak following over the " << name << " " << range[0] << ".." << range[1] << ": " << whole.points.size()
         << " values in " << whole.seconds << " s (" << whole.searches << " peak searches, " << whole.solves
         << " Newton solves, " << whole.sweeps << " band sweeps, " << jumps << " jumps to another peak); ";
  if (whole.optimum < 0) {  // the speed: an operating condition, its largest peak
    std::size_t top = 0;
    for (std::size_t i = 0; i < whole.points.size(); ++i)
      if (whole.points[i].measure > whole.points[top].measure) top = i;
    const auto& p = whole.points[top];
    line << "largest peak " << p.measure << " at " << name << " " << p.parameter << " (" << p.frequency / (2 * M_PI)
         << " Hz; the reduced models built at each " << name << ")";
  } else {
    const auto& best = whole.points[std::size_t(whole.optimum)];
    line << "smallest peak" << (byForce ? " per unit force " : " ") << merit(best) << " at " << name << " "
         << best.parameter << " (" << best.frequency / (2 * M_PI) << " Hz, "
         << (best.parameter == grid.front() || best.parameter == grid.back()
                 ? "at the range's end: the optimum may lie beyond it"
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
  if (const auto it = listed.find(name); it != listed.end()) {
    double worst = 0;
    int compared = 0;
    for (const auto& sp : it->second)
      for (const auto& p : whole.points)
        if (std::abs(p.parameter - sp.value) <= 1e-12 * std::max(std::abs(sp.value), 1e-6) && sp.peak > 0) {
          worst = std::max(worst, std::abs(p.measure / sp.peak - 1));
          ++compared;
        }
    if (compared > 0) line << "; against the frequency curves at " << compared << " values: " << worst << " (relative)";
  }
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
    const std::string method = s.getString("method", "peak_search");
    if (method != "peak_search" && method != "continuation")
      throw InputError(s.where("method"), "must be peak_search (a peak search per value) or continuation (one LOCA "
                                          "continuation of the peak), not '" + method + "'");
    if (method == "continuation" && s.has("values"))
      throw InputError(s.where("values"), "is not used by method continuation (LOCA's steps are the points): drop it");
    if (method == "continuation" && (name == "loss_factor" || name == "speed"))
      throw InputError(s.where("method"), "continuation follows the contact parameters, the clearance and the force; "
                                          "the " + name + " rebuilds the system per value: use peak_search");
    s.rejectUnknownKeys();
    // force: the excitation's scale (times disc_response/excitation/amplitude), as the studies';
    // contact_stiffness: kn = kt together, so the scene's two must be equal.
    // loss_factor: the reduced models' (reduced_model/loss_factor); speed: the speed they
    // are built at (reduced_model/speed_rpm).
    double refValue = name == "speed" ? rpm : lossFactor;
    try {
      if (name != "loss_factor" && name != "speed") refValue = disc::discReferenceValue(spec, *disc::discStudyParameterFromName(name));
    } catch (const InputError& e) {
      throw InputError(s.where("range"), e.problem());
    }
    if (!(refValue >= range[0] && refValue <= range[1]))
      throw InputError(s.where("range"), "must contain the scene's " + name + " (" + std::to_string(refValue) +
                                             "): the following starts at the reference curve's peak");
    out.push_back({name, range[0], range[1], values, method == "continuation"});
  }
  peakStudies.rejectUnknownKeys();
  return out;
}

void followDiscPeaks(const std::vector<PeakStudySpec>& studies, const mesh::Mesh& mesh, const DiscReducedModels& models,
                     const DiscPlan& plan, const ForcedResponseSetup& reference,
                     const ForcedResponseResult& referenceResult, double bandFromHz, double bandToHz,
                     const std::map<std::string, std::vector<StudyPeak>>& listed, const std::string& outDir,
                     linalg::CommPtr comm, SceneSummary& summary) {
  for (const auto& study : studies) {
    const std::string& name = study.name;
    disc::DiscPeakFollowingSpec following;
    following.parameter = *disc::discStudyParameterFromName(name);
    following.from = study.from, following.to = study.to, following.values = study.values;
    if (study.continuation) following.method = disc::DiscPeakFollowingSpec::Method::Continuation;
    const auto listedHere = listed.count(name) ? listed.at(name) : std::vector<StudyPeak>{};
    for (const auto& p : listedHere) {
      following.extraValues.push_back(p.value);
      following.knownPeaks.push_back({p.value, {p.x, p.omega, p.peak, 0}});
    }
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
      writePeakStudy(name, unit, f, *f.setup.system, listedHere, outDir, summary);
    std::string line = peakStudyLine(name, {study.from, study.to}, f, listed);
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

// A study value that reproduces the reference scene: disc_frc's files under the study's name.
void copyReferenceCurve(const std::string& outDir, const std::string& tag, const std::string& what,
                        linalg::CommPtr comm, SceneSummary& summary) {
  if (comm->getRank() == 0)
    for (const std::string ext : {".csv", ".h5", ".svg"}) {
      if (!std::filesystem::exists(outDir + "/disc_frc" + ext)) continue;
      AtomicFile copy(outDir + "/" + tag + ext);
      std::filesystem::copy_file(outDir + "/disc_frc" + ext, copy.tempPath(),
                                 std::filesystem::copy_options::overwrite_existing);
      copy.commit();
    }
  for (const std::string ext : {".h5", ".csv", ".svg"}) summary.written.push_back(outDir + "/" + tag + ext);
  const std::string line = tag + ": " + what + " is the reference scene: disc_frc's curve, not traced again";
  summary.computed.push_back(line);
  log::info(line);
}

}  // namespace cyclone::scenes
