// disc_response/peak_studies: the disc's largest resonance peak followed over a contact
// parameter (the preload or the friction coefficient) by a peak search at each value
// (continuation::followPeak), from the reference curve's peak, instead of a frequency
// curve per value. The shroud contacts' Jacobian jumps where a stick-slip instant
// crosses a time sample, and the peak condition's arclength tracking creeps there
// (docs/decisions.md): a fixed-frequency Newton passes those corners.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include <Teuchos_Comm.hpp>

#include "SceneStages.hpp"
#include "cyclone/continuation/PeakFollowing.hpp"
#include "cyclone/core/AtomicFile.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/io/ResponseCurveFile.hpp"
#include "cyclone/post/SvgPlot.hpp"
#include "cyclone/scenes/SceneSection.hpp"

namespace cyclone::scenes {

namespace {

// The grid: n values evenly in log over the range, with the reference value and the
// value-list study's values (so the two can be compared), sorted, without repeats.
std::vector<double> followedValues(double from, double to, int n, double reference, const std::vector<double>& listed) {
  auto v = continuation::logarithmicValues(from, to, n);
  v.push_back(reference);
  for (double x : listed)
    if (x >= from && x <= to) v.push_back(x);
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end(), [](double a, double b) { return std::abs(a - b) <= 1e-12 * std::abs(b); }),
          v.end());
  return v;
}

void writePeakStudy(const std::string& name, const std::string& unit, const continuation::FollowedPeakCurve& curve,
                    const hbm::HarmonicBalanceSystem& hb, const std::vector<StudyPeak>& listed,
                    const std::string& outDir, SceneSummary& summary) {
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
    out << name << ",peak_hz,peak_max_abs,jump,optimum\n";
    for (std::size_t i = 0; i < curve.points.size(); ++i) {
      const auto& p = curve.points[i];
      out << p.parameter << "," << p.frequency / (2 * M_PI) << "," << p.measure << "," << (p.jump ? 1 : 0) << ","
          << (int(i) == curve.optimum ? 1 : 0) << "\n";
    }
    out.close();
    if (!out) throw Error("cannot write " + file.finalPath());
    file.commit();
  }
  post::SvgPlot plot("Resonance peak against the " + name + " (followed)", "log10(" + name + unit + ")",
                     "peak max |x(t)|");
  std::vector<double> x, y;
  for (const auto& p : curve.points) x.push_back(std::log10(p.parameter)), y.push_back(p.measure);
  plot.addLine(x, y, post::SvgPlot::palette(0), "followed peak");
  if (!listed.empty()) {
    std::vector<double> lx, ly;
    for (const auto& s : listed) lx.push_back(std::log10(s.value)), ly.push_back(s.peak);
    plot.addMarkers(lx, ly, post::SvgPlot::palette(2), "frequency curves (studies)");
  }
  if (curve.optimum >= 0) {
    const auto& o = curve.points[std::size_t(curve.optimum)];
    plot.addMarkers({std::log10(o.parameter)}, {o.measure}, "#000000", "optimum", 5.0);
    std::ostringstream text;
    text.precision(4);
    text << "optimum " << o.parameter;
    plot.addText(std::log10(o.parameter), o.measure, text.str());
  }
  plot.write(outDir + "/peak_" + name + ".svg");
  summary.written.push_back(outDir + "/peak_" + name + ".csv");
  summary.written.push_back(outDir + "/peak_" + name + ".svg");
}

// From the reference value down and up the grid, joined in parameter order; the
// optimum by `merit` over the whole.
template <class Merit>
continuation::FollowedPeakCurve followBothWays(const continuation::PeakTrackingProblem& problem,
                                               const std::vector<continuation::PeakStart>& starts,
                                               continuation::PeakFollowingOptions o,
                                               const std::vector<double>& grid, double refValue, Merit merit) {
  Timer timer;
  continuation::FollowedPeakCurve whole;
  std::vector<double> up, down;
  for (double v : grid) (v >= refValue ? up : down).push_back(v);
  std::reverse(down.begin(), down.end());
  if (up.front() != refValue) up.insert(up.begin(), refValue);
  down.insert(down.begin(), refValue);
  for (const auto* part : {&down, &up}) {
    if (part->size() < 2) continue;
    o.parameters = *part;
    const auto c = continuation::followPeaks(problem, starts, o);
    whole.sweeps += c.sweeps, whole.searches += c.searches, whole.solves += c.solves;
    if (!c.complete) whole.stopReason += (whole.stopReason.empty() ? "" : "; ") + c.stopReason;
    auto points = c.points;
    if (part == &down) std::reverse(points.begin(), points.end());
    if (part == &up && !whole.points.empty()) points.erase(points.begin());  // the reference, already there
    whole.points.insert(whole.points.end(), points.begin(), points.end());
    if (c.optimumLocated) whole.optimumLocated = true;
  }
  whole.seconds = timer.seconds();
  whole.complete = whole.stopReason.empty();
  for (std::size_t i = 0; i < whole.points.size(); ++i)
    if (whole.optimum < 0 || merit(whole.points[i]) < merit(whole.points[std::size_t(whole.optimum)]))
      whole.optimum = int(i);
  return whole;
}

// The summary's line: the work, the optimum and where it lies, the difference from the
// value-list study's frequency curves at shared values.
template <class Merit>
std::string peakStudyLine(const std::string& name, const std::vector<double>& range,
                          const continuation::FollowedPeakCurve& whole, const std::vector<double>& grid, bool byForce,
                          Merit merit, const std::map<std::string, std::vector<StudyPeak>>& listed) {
  const auto& best = whole.points[std::size_t(whole.optimum)];
  int jumps = 0;
  for (const auto& p : whole.points) jumps += p.jump;
  std::ostringstream line;
  line.precision(6);
  line << "peak following over the " << name << " " << range[0] << ".." << range[1] << ": " << whole.points.size()
       << " values in " << whole.seconds << " s (" << whole.searches << " peak searches, " << whole.solves
       << " Newton solves, " << whole.sweeps << " band sweeps, " << jumps << " jumps to another peak); smallest peak"
       << (byForce ? " per unit force " : " ") << merit(best) << " at " << name << " " << best.parameter << " ("
       << best.frequency / (2 * M_PI) << " Hz, "
       << (best.parameter == grid.front() || best.parameter == grid.back()
               ? "at the range's end: the optimum may lie beyond it"
               : whole.optimumLocated ? "located between its neighbours" : "the grid's") << ")";
  // The value-list study's peaks (frequency curves) at the same values.
  if (const auto it = listed.find(name); it != listed.end()) {
    double worst = 0;
    int compared = 0;
    for (const auto& sp : it->second)
      for (const auto& p : whole.points)
        if (std::abs(p.parameter - sp.value) <= 1e-12 * std::abs(sp.value) && sp.peak > 0) {
          worst = std::max(worst, std::abs(p.measure / sp.peak - 1));
          ++compared;
        }
    if (compared > 0) line << "; against the frequency curves at " << compared << " values: " << worst << " (relative)";
  }
  if (!whole.complete) line << "; stopped: " << whole.stopReason;
  return line.str();
}

}  // namespace

std::vector<PeakStudySpec> readPeakStudies(SceneSection peakStudies, const DiscResponseSpec& spec) {
  std::vector<PeakStudySpec> out;
  for (const std::string name : {"preload", "mu", "force"}) {
    if (!peakStudies.has(name)) continue;
    auto s = peakStudies.section(name);
    const auto range = s.getDoubleList("range", {});
    if (range.size() != 2 || !(range[0] > 0 && range[1] > range[0]))
      throw InputError(s.where("range"), "needs [from, to] with 0 < from < to");
    const int values = s.getInt("values", 24);
    if (values < 3 || values > 400) throw InputError(s.where("values"), "must lie in 3..400");
    s.rejectUnknownKeys();
    // force: the excitation's scale (times disc_response/excitation/amplitude), as the studies'.
    const double refValue = name == "preload" ? spec.contact.preload : name == "mu" ? spec.contact.mu : 1.0;
    if (!(refValue >= range[0] && refValue <= range[1]))
      throw InputError(s.where("range"), "must contain the scene's " + name + " (" + std::to_string(refValue) +
                                             "): the following starts at the reference curve's peak");
    out.push_back({name, range[0], range[1], values});
  }
  peakStudies.rejectUnknownKeys();
  return out;
}

void followDiscPeaks(const std::vector<PeakStudySpec>& studies, const mesh::Mesh& mesh, const DiscReducedModels& models,
                     const DiscResponseSpec& spec, const ForcedResponseSetup& reference,
                     const ForcedResponseResult& referenceResult, double bandFromHz, double bandToHz,
                     const std::map<std::string, std::vector<StudyPeak>>& listed, const std::string& outDir,
                     linalg::CommPtr comm, SceneSummary& summary) {
  for (const auto& study : studies) {
    const std::string& name = study.name;
    const std::vector<double> range{study.from, study.to};
    const int values = study.values;
    if (referenceResult.branch.points.empty())
      throw SolverError("disc_response/peak_studies/" + name + ": the reference curve has no point to start from");
    const double refValue = name == "preload" ? spec.contact.preload : name == "mu" ? spec.contact.mu : 1.0;

    ForcedResponseSetup setup = makeDiscForcedResponse(mesh, models, spec);
    setup.outputDofs = reference.outputDofs;
    if (name == "force")
      setup.parameter = ForcedResponseSetup::Parameter::ForceScale;
    else
      selectElementParameter(setup, "contact", name, refValue);
    const auto problem = peakFollowingProblem(setup);
    // Every peak of the reference curve that stands out (5 %), so one that overtakes the
    // largest is seen; its frequencies from the curve's parameter (omega / omegaUnit).
    auto starts = continuation::prominentPeaks(referenceResult.branch, problem.measure);
    if (starts.empty()) throw SolverError("disc_response/peak_studies/" + name + ": the reference curve has no peak");
    for (auto& st : starts) st.frequency *= reference.omegaUnit;
    const double w0 = starts.front().frequency;
    continuation::PeakFollowingOptions o;
    o.search.step = 5e-4 * w0, o.search.maxStep = 5e-3 * w0, o.search.window = 0.15 * w0;
    o.search.parameterTolerance = 1e-7 * w0, o.search.tolerance = reference.continuation.tolerance;
    o.bandFrom = 2 * M_PI * bandFromHz, o.bandTo = 2 * M_PI * bandToHz;
    o.sweep = reference.continuation;
    o.sweep.checkpoints = nullptr;
    // Over the force the peak grows with it: the optimum is the smallest peak per unit
    // force (the most friction damping), on the grid.
    const bool byForce = name == "force";
    o.locateOptimum = !byForce;
    auto merit = [byForce](const continuation::FollowedPeak& p) { return byForce ? p.measure / p.parameter : p.measure; };

    std::vector<double> studyValues;
    if (const auto it = listed.find(name); it != listed.end())
      for (const auto& p : it->second) studyValues.push_back(p.value);
    const auto grid = followedValues(range[0], range[1], values, refValue, studyValues);
    log::info("peak following over the " + name + ": " + std::to_string(grid.size()) + " values, from the reference "
              "curve's " + std::to_string(starts.size()) + " peak(s), the largest at " + std::to_string(w0 / (2 * M_PI)) +
              " Hz");
    continuation::FollowedPeakCurve whole = followBothWays(problem, starts, o, grid, refValue, merit);
    if (whole.points.empty()) throw SolverError("disc_response/peak_studies/" + name + ": " + whole.stopReason);

    const std::string unit = name == "preload" ? " / N" : "";
    if (comm->getRank() == 0)
      writePeakStudy(name, unit, whole, *setup.system, listed.count(name) ? listed.at(name) : std::vector<StudyPeak>{},
                     outDir, summary);
    const std::string line = peakStudyLine(name, range, whole, grid, byForce, merit, listed);
    summary.computed.push_back(line);
    log::info(line);
    summary.stages.push_back({"peak following (" + name + ")", whole.seconds,
                              "each peak by a peak search to 1e-7 of its frequency; the harmonics are the reference curve's"});
  }
}

}  // namespace cyclone::scenes
