// The scene stages of the disc chain: reduced models per nodal diameter
// (`analysis: reduced_model`), and the forced response with friction at the
// shroud with its parameter studies (`analysis: disc_response`). Keys in docs/scenes.md.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

#include "SceneStages.hpp"

#include <Teuchos_Comm.hpp>
#include "cyclone/core/AtomicFile.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/hbm/HarmonicBalanceSystem.hpp"
#include "cyclone/hbm/PeakMagnitude.hpp"
#include "cyclone/mesh/Mesh.hpp"
#include "cyclone/post/SvgPlot.hpp"
#include "cyclone/rom/HybridFrfModel.hpp"
#include "cyclone/disc/DiscHarmonicBalance.hpp"
#include "cyclone/disc/DiscForcedResponse.hpp"
#include "cyclone/hbm/ElementStates.hpp"
#include "cyclone/disc/DiscParameterStudy.hpp"
#include "cyclone/disc/DiscReducedModels.hpp"
#include "cyclone/scenes/SceneSection.hpp"

namespace cyclone::scenes {

namespace {

Eigen::Vector3d toEigen(const std::array<double, 3>& a) { return {a[0], a[1], a[2]}; }

DiscModelSpec readModelSpec(SceneSection& scene, SceneSection& r, int builtInSectors, std::string& cache) {
  DiscModelSpec spec;
  spec.material = readMaterial(scene.section("material"));
  {
    auto c = scene.section("constraints");
    spec.fixedNodeSets = c.getStringList("fixed_node_sets", {});
    c.rejectUnknownKeys();
    if (spec.fixedNodeSets.empty())
      throw InputError(scene.where("constraints/fixed_node_sets"), "a disc response needs the disc held (e.g. [bore])");
  }
  {
    auto cy = scene.section("cyclic");
    spec.sectors = cy.getInt("sectors", builtInSectors);
    if (spec.sectors < 2) throw InputError(cy.where("sectors"), "is required (>= 2) for a mesh read from a file");
    spec.axis = readRotationAxis(cy);
    // The reduced models are cantilevered: the disc's faces cyclic, the shroud's free
    // (configuration and the shroud's faces are the modal analysis's).
    const auto faces = readCyclicFaces(cy);
    spec.leftSets = faces.discLeft, spec.rightSets = faces.discRight;
    const auto analyses = scene.getStringList("analysis", {});
    if (std::find(analyses.begin(), analyses.end(), "modal") == analyses.end())
      for (const char* key : {"configuration", "shroud_left_node_sets", "shroud_right_node_sets"})
        if (cy.has(key))
          log::warn(cy.where(key) + " is the modal analysis's (the reduced models are cantilevered: the disc's "
                                    "faces cyclic, the shroud's free for the contacts); this scene has none, so it is "
                                    "not used");
    cy.rejectUnknownKeys();
  }
  double loadsRpm = 0;
  {
    auto l = scene.section("loads");
    loadsRpm = l.getDouble("speed_rpm", 0.0);
  }
  spec.kind = disc::reducedModelKindFromName(r.getString("kind", "hybrid"), r.where("kind"));
  spec.retainedNodeSets = r.getStringList("retained_node_sets", spec.retainedNodeSets);
  spec.modes = r.getInt("modes", spec.modes);
  spec.omega0 = r.getDouble("omega0", spec.omega0);
  spec.lossFactor = r.getDouble("loss_factor", spec.lossFactor);
  if (!(spec.lossFactor >= 0)) throw InputError(r.where("loss_factor"), "must be >= 0");
  spec.rpm = r.getDouble("speed_rpm", loadsRpm);
  if (!(spec.rpm >= 0)) throw InputError(r.where("speed_rpm"), "must be >= 0");
  spec.prestress = readPrestressKind(r, "nonlinear");
  cache = r.getString("cache", "reuse");
  if (cache != "reuse" && cache != "rebuild" && cache != "off")
    throw InputError(r.where("cache"), "use reuse (read a model whose inputs match), rebuild or off");
  return spec;
}

DiscResponseSpec readResponseSpec(SceneSection& d) {
  DiscResponseSpec spec;
  spec.engineOrder = d.getInt("engine_order", 0);
  if (!d.has("engine_order")) throw InputError(d.where("engine_order"), "is required (the excitation's engine order)");
  spec.harmonics = readHarmonicList(d, 3);
  spec.samples = d.getInt("samples", 0);
  if (spec.samples < 0 || spec.samples > kMaxSamples)
    throw InputError(d.where("samples"), std::to_string(spec.samples) + ": must lie in 1.." +
                                             std::to_string(kMaxSamples) + " time samples per period (leave it out "
                                             "for the automatic count)");
  auto c = d.section("contact");
  auto& ct = spec.contact;
  ct.leftSet = c.getString("left_node_set", ct.leftSet);
  ct.rightSet = c.getString("right_node_set", ct.rightSet);
  ct.kn = c.getDouble("kn", ct.kn);
  ct.kt = c.getDouble("kt", ct.kt);
  ct.mu = c.getDouble("mu", ct.mu);
  ct.preload = c.getDouble("preload", ct.preload);
  if (c.has("normal") != c.has("tangent"))
    throw InputError(c.location(), "give both normal and tangent (the contact frame), or neither");
  if (c.has("normal")) ct.normal = toEigen(c.getVector3("normal", {0, 0, 0}));
  if (c.has("tangent")) ct.tangent = toEigen(c.getVector3("tangent", {0, 0, 0}));
  c.rejectUnknownKeys();
  if (d.has("gap")) {
    auto g = d.section("gap");
    spec.gap.pairs = g.getIntList("pairs", {});
    if (spec.gap.pairs.empty()) throw InputError(g.where("pairs"), "needs the contact pairs that are gap elements");
    spec.gap.kn = g.getDouble("kn", spec.gap.kn);
    spec.gap.clearance = g.getDouble("clearance", spec.gap.clearance);
    g.rejectUnknownKeys();
  }
  auto e = d.section("excitation");
  spec.excitation.nodeSet = e.getString("node_set", spec.excitation.nodeSet);
  spec.excitation.direction = toEigen(e.getVector3("direction", {0, 0, 1}));
  spec.excitation.amplitude = e.getDouble("amplitude", spec.excitation.amplitude);
  e.rejectUnknownKeys();
  spec.responseNodeSets = d.getStringList("response_node_sets", spec.responseNodeSets);
  return spec;
}

// One curve of a study: frequency (Hz) and max |x(t)| of the first output DOF per point.
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

std::string shortNumber(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

// Per contact at the peak point (hbm::elementStates): the energy friction dissipates per
// cycle, the mean normal force and the first harmonic's slip amplitude. Returns the energies.
std::vector<double> writeContactEnergies(const hbm::HarmonicSet& H, const std::vector<hbm::ElementState>& states,
                                         double omega, const std::string& path) {
  AtomicFile file(path);
  std::ofstream csv(file.tempPath());
  csv.precision(10);
  csv << "contact,freq_hz,dissipated_energy_per_cycle,mean_normal_force,slip_amplitude\n";
  std::vector<double> energies;
  for (std::size_t e = 0; e < states.size(); ++e) {
    const Eigen::MatrixXd &W = states[e].W, &F = states[e].F;
    const double energy = hbm::dissipatedEnergyPerCycle(H, states[e]);
    double slip = 0;
    if (H.contains(1) && W.cols() == 3) {
      const int ic = H.cosIndex(1), is = H.sinIndex(1);
      slip = std::hypot(std::hypot(W(ic, 0), W(is, 0)), std::hypot(W(ic, 1), W(is, 1)));
    }
    const double normal = H.contains(0) ? F(H.cosIndex(0), W.cols() - 1) : 0.0;
    csv << e << "," << omega / (2 * M_PI) << "," << energy << "," << normal << "," << slip << "\n";
    energies.push_back(energy);
  }
  csv.close();
  if (!csv) throw Error("cannot write " + path);
  file.commit();
  return energies;
}

// Contact hysteresis loops at the peak point: the sampled contact law
// (not its truncated Fourier series, whose Gibbs ripples would blur the stick and
// slip corners) against the relative motion over one period, for the chosen
// contacts; and the response DOFs over that period.
void writePeakTimeResponse(const ForcedResponseSetup& setup, const PeakPoint& point,
                           const std::vector<hbm::ElementState>& states, const std::vector<int>& contacts,
                           const std::string& outDir, SceneSummary& summary) {
  const auto& hb = *point.system;
  const auto& aft = hb.aft();
  const int N = aft.numSamples();
  const double hz = point.omega / (2 * M_PI);
  std::vector<double> phase(std::size_t(N) + 1);
  for (int i = 0; i <= N; ++i) phase[std::size_t(i)] = double(i) / N;
  const char* tangential[] = {"t1", "t2"};
  {
    AtomicFile file(outDir + "/disc_hysteresis.csv");
    std::ofstream csv(file.tempPath());
    csv.precision(10);
    csv << "contact,freq_hz,t_over_T,slip_t1,slip_t2,approach,force_t1,force_t2,force_n\n";
    std::ostringstream title;
    title << "Contact hysteresis at " << point.what;
    // About each direction's mean: the static part differs between directions
    // and would push the loops apart.
    post::SvgPlot plot(title.str(), "relative tangential displacement about its mean (mm)",
                       "tangential contact force (N)");
    int line = 0;
    double xLow = 0, xHigh = 0;  // the loops' extent: a margin on both sides, none drawn on the frame
    for (int e : contacts) {
      const auto period = hbm::elementPeriod(hb, std::size_t(e), states[std::size_t(e)], point.omega);
      const Eigen::MatrixXd &w = period.w, &f = period.f;
      const int d = int(w.cols());
      for (int i = 0; i < N; ++i) {
        // Tangential columns: d - 1 of them (none for a gap element).
        auto t = [&](const Eigen::MatrixXd& m, int c) { return c < d - 1 ? m(i, c) : 0.0; };
        csv << e << "," << hz << "," << phase[std::size_t(i)] << "," << t(w, 0) << "," << t(w, 1) << ","
            << w(i, d - 1) << "," << t(f, 0) << "," << t(f, 1) << "," << f(i, d - 1) << "\n";
      }
      for (int c = 0; c + 1 < d; ++c) {  // closed loops: the first sample repeated at the end
        std::vector<double> x(std::size_t(N) + 1), y(std::size_t(N) + 1);
        const double mean = w.col(c).mean();
        for (int i = 0; i <= N; ++i) x[std::size_t(i)] = w(i % N, c) - mean, y[std::size_t(i)] = f(i % N, c);
        xLow = std::min(xLow, *std::min_element(x.begin(), x.end()));
        xHigh = std::max(xHigh, *std::max_element(x.begin(), x.end()));
        plot.addLine(x, y, post::SvgPlot::palette(line++),
                     "contact " + std::to_string(e) + ", " + tangential[c]);
      }
    }
    csv.close();
    file.commit();
    if (xHigh > xLow) plot.setXRange(xLow - 0.05 * (xHigh - xLow), xHigh + 0.05 * (xHigh - xLow));
    plot.write(outDir + "/disc_hysteresis.svg");
  }
  {
    AtomicFile file(outDir + "/disc_time_response.csv");
    std::ofstream csv(file.tempPath());
    csv.precision(10);
    csv << "freq_hz,t_over_T";
    for (int dof : setup.outputDofs) csv << "," << setup.dofNames[std::size_t(dof)];
    csv << "\n";
    std::ostringstream title;
    title << "Response over one period at " << point.what;
    post::SvgPlot plot(title.str(), "t / T", "displacement (mm)");
    const int nc = hb.numCoefficients();
    Eigen::MatrixXd x(N, setup.outputDofs.size());
    for (std::size_t k = 0; k < setup.outputDofs.size(); ++k) {
      aft.toTime(point.x.data() + std::ptrdiff_t(setup.outputDofs[k]) * nc, x.col(Eigen::Index(k)).data());
      std::vector<double> y(std::size_t(N) + 1);
      for (int i = 0; i <= N; ++i) y[std::size_t(i)] = x(i % N, Eigen::Index(k));
      plot.addLine(phase, y, post::SvgPlot::palette(int(k)), setup.dofNames[std::size_t(setup.outputDofs[k])]);
    }
    for (int i = 0; i < N; ++i) {
      csv << hz << "," << phase[std::size_t(i)];
      for (Eigen::Index k = 0; k < x.cols(); ++k) csv << "," << x(i, k);
      csv << "\n";
    }
    csv.close();
    file.commit();
    plot.write(outDir + "/disc_time_response.svg");
  }
  for (const char* f : {"disc_hysteresis.csv", "disc_hysteresis.svg", "disc_time_response.csv", "disc_time_response.svg"})
    summary.written.push_back(outDir + "/" + f);
}

// disc_response's keys for the curve: family, frequency_range_hz, stability and the
// continuation section (the disc's own defaults, discContinuationOptions, then the
// scene's keys; an engine the scene names is used alone, by default the other one
// retraces a curve the first leaves incomplete).
disc::DiscSweepOptions readSweepOptions(SceneSection& d, int harmonicsCheckTo,
                                        const std::shared_ptr<continuation::TraceCheckpoints>& checkpoints) {
  disc::DiscSweepOptions sweep;
  sweep.family = d.getInt("family", 1);
  const auto range = d.getDoubleList("frequency_range_hz", {});
  if (!range.empty() && (range.size() != 2 || !(range[0] > 0) || !(range[1] > range[0])))
    throw InputError(d.where("frequency_range_hz"), "needs two increasing positive frequencies [from, to] in Hz");
  if (!range.empty()) sweep.fromHz = range[0], sweep.toHz = range[1];
  sweep.stability = readStability(d);
  sweep.harmonicsCheckTo = harmonicsCheckTo;
  auto cs = d.section("continuation");
  using Engine = continuation::ContinuationOptions::Engine;
  sweep.continuation = disc::discContinuationOptions(
      cs.getString("engine", "predictor_corrector") == "loca" ? Engine::Loca : Engine::PredictorCorrector);
  if (cs.has("engine")) sweep.fallback.reset();
  readContinuationSteps(cs, sweep.continuation, "predictor_corrector");
  sweep.continuation.tolerance = cs.getDouble("tolerance", sweep.continuation.tolerance);
  cs.rejectUnknownKeys();
  sweep.continuation.checkpoints = checkpoints;
  if (sweep.fallback) sweep.fallback->checkpoints = checkpoints;
  return sweep;
}

// What a disc scene asks for, read and checked before any FE work.
struct DiscPlan {
  DiscModelSpec modelSpec;   ///< with the check of the engine order's nodal diameter
  std::string cacheDir;      ///< empty: nothing cached
  std::vector<int> nds;      ///< the nodal diameters the models are built for
  DiscResponseSpec spec;
  int harmonicsCheckTo = 0;
  PeakStressSpec peakStress;
  std::vector<PeakStudySpec> peakStudies;
};

DiscPlan readDiscPlan(SceneSection& scene, SceneSection& r, SceneSection& d, const mesh::Mesh& mesh,
                      int builtInSectors, bool forcedResponse, const std::string& outDir, linalg::CommPtr comm) {
  DiscPlan plan;
  std::string cache;
  plan.modelSpec = readModelSpec(scene, r, builtInSectors, cache);
  const int sectors = plan.modelSpec.sectors;
  auto& spec = plan.spec;
  if (forcedResponse) {
    spec = readResponseSpec(d);
    plan.peakStudies = readPeakStudies(d.section("peak_studies"), spec);
    plan.peakStress = readPeakStressSpec(d, scene.section("material"), plan.modelSpec.material);
    const int maxHarmonic = *std::max_element(spec.harmonics.begin(), spec.harmonics.end());
    plan.harmonicsCheckTo = readHarmonicsCheckTo(d, maxHarmonic);
    if (spec.engineOrder >= 1 && spec.engineOrder < sectors) {
      // Also the nodal diameters of the harmonics the curve's harmonics check adds.
      auto checked = spec.harmonics;
      for (int h = maxHarmonic + 1; h <= std::max(maxHarmonic + 1, plan.harmonicsCheckTo); ++h) checked.push_back(h);
      plan.nds = disc::nodalDiametersFor(sectors, spec.engineOrder, checked);
      plan.modelSpec.checkNodalDiameter = disc::nodalDiametersFor(sectors, spec.engineOrder, {1}).front();
    } else {  // engine-order errors before any FE work
      DiscReducedModels none;
      none.sectors = sectors;
      disc::makeDiscForcedResponse(mesh, none, spec);  // throws the explained InputError
    }
    if (r.has("nodal_diameters"))
      throw InputError(r.where("nodal_diameters"), "is chosen by disc_response (engine order and harmonics)");
  } else {
    plan.nds = r.getIntList("nodal_diameters", {});
    if (plan.nds.empty())
      throw InputError(r.where("nodal_diameters"), "is required when the scene builds reduced models alone");
  }
  plan.cacheDir = cache == "off" ? std::string() : outDir + "/reduced_models";
  plan.modelSpec.checkFrequencies = r.getInt("check_frequencies", 12);
  if (cache == "rebuild" && comm->getRank() == 0) std::filesystem::remove_all(plan.cacheDir);
  r.rejectUnknownKeys();
  return plan;
}

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
  } else {
    estimate << "not checked (a reused model built before the check, or check_frequencies: 0)";
  }
  summary.stages.push_back({"reduced models (" + kind + ")", timer.seconds(), estimate.str()});
  std::ostringstream line;
  line << "reduced models (" << kind << ", " << ms.modes << " natural frequencies per ND, "
       << models.retainedNodes.size() << " retained nodes) for ND";
  for (const auto& [k, m] : models.models) line << " " << k;
  line << " at " << ms.rpm << " rpm: " << models.built << " built, " << models.reused << " reused, "
       << models.seconds << " s";
  summary.computed.push_back(line.str());
  for (const auto& [k, f] : models.files) summary.written.push_back(f);
  return models;
}

// Writes a disc curve with its summary lines (a range-end warning says where to widen it).
void writeDiscCurve(const disc::DiscForcedResponse& solved, const ForcedResponseSetup& setup,
                    const ForcedResponseResult& result, const std::string& name, const std::vector<std::string>& warnings,
                    const std::string& outDir, linalg::CommPtr comm, SceneSummary& summary) {
  writeForcedResponse(setup, result, outDir, name, comm, summary);
  for (const auto& w : warnings)
    summary.computed.push_back("warning: " + name + ": " + w + " (" + solved.estimateText +
                               "); widen disc_response/frequency_range_hz");
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
  log::info(line.str());
  const auto& reference = solved.curve;
  if (reference.branch.points.empty())
    throw SolverError("disc_frc: no point of the curve was computed, so nothing was written: " +
                      reference.branch.stopReason);
  writeDiscCurve(solved, solved.setup, reference, "disc_frc", solved.warnings, outDir, comm, summary);
  summary.stages.push_back(
      {"forced response (H = " + std::to_string(solved.setup.system->aft().harmonics().maxHarmonic()) + ", " +
           std::to_string(reference.branch.points.size()) + " points)",
       timer.seconds(),
       "Newton tolerance " + shortNumber(sweep.continuation.tolerance) + " (residual relative to the forces); " +
           reference.samplesCheck.text + "; " + reference.harmonicsCheck.text});
  // The headline: the peak at the highest harmonic count reached, converged or labelled
  // an estimate with the last change next to it.
  if (solved.headline.found) summary.computed.insert(summary.computed.begin(), solved.headline.text);
  return solved;
}

// Contacts, loops, the period and the sector's stresses at one point: the converged
// peak (or peak_stress/at_hz for the stresses).
void peakOutputsStage(const mesh::Mesh& mesh, const DiscReducedModels& models, const DiscPlan& plan,
                      disc::DiscForcedResponse& solved, const std::vector<int>& hysteresisContacts,
                      const std::string& outDir, linalg::CommPtr comm, SceneSummary& summary) {
  auto& setup = solved.setup;
  const PeakPoint point = disc::referencePeakPoint(setup, solved.curve);
  if (comm->getRank() == 0) {
    const auto states = hbm::elementStates(*point.system, point.x, point.omega);
    const auto energies =
        writeContactEnergies(point.system->aft().harmonics(), states, point.omega, outDir + "/disc_frc_contacts.csv");
    summary.written.push_back(outDir + "/disc_frc_contacts.csv");
    // Default: the contact that dissipates most at the peak.
    std::vector<int> loops = hysteresisContacts;
    if (loops.empty()) loops.push_back(int(std::max_element(energies.begin(), energies.end()) - energies.begin()));
    writePeakTimeResponse(setup, point, states, loops, outDir, summary);
  }
  const auto& ps = plan.peakStress;
  if (ps.atHz > 0)
    writePeakStress(ps, mesh, models, plan.modelSpec, disc::referencePointAt(setup, solved.curve, ps.atHz),
                    setup.excitationScale, outDir, comm, summary);
  else
    writePeakStress(ps, mesh, models, plan.modelSpec, point, setup.excitationScale, outDir, comm, summary);
}

// One parameter study of disc_response/studies: a curve per value (each written as it
// comes, a reference value's files copied from disc_frc's), study_<name>.svg with every
// curve and study_<name>.csv with their peaks. Returns the curves traced.
int studyStage(SceneSection& studies, const char* name, const mesh::Mesh& mesh, const DiscReducedModels& models,
               const DiscPlan& plan, const disc::DiscForcedResponse& solved, const disc::DiscSweepOptions& sweep,
               const std::string& outDir, linalg::CommPtr comm, SceneSummary& summary,
               std::vector<StudyPeak>& peaks) {
  const auto values = studies.getDoubleList(name, {});
  if (values.empty()) throw InputError(studies.where(name), "needs a list of values");
  const auto& setup = solved.setup;
  post::SvgPlot plot(std::string("Study: ") + name + " (engine order " + std::to_string(plan.spec.engineOrder) + ")",
                     "frequency (Hz)", "max |x(t)| of " + setup.dofNames[setup.outputDofs.front()]);
  std::ostringstream table;
  table.precision(10);
  table << name << ",peak_hz,peak_max_abs,points,finished,seconds\n";
  int index = 0;
  const auto writeCurve = [&](const disc::DiscStudyCurve& c, const ForcedResponseSetup& traced) {
    const std::string tag = "study_" + std::string(name) + "_" + std::to_string(index);
    std::ostringstream label;
    label << name << " = " << c.value;
    if (c.isReference) copyReferenceCurve(outDir, tag, label.str(), comm, summary);
    else writeDiscCurve(solved, traced, c.curve, tag, c.warnings, outDir, comm, summary);
    const auto& r = c.curve;
    const auto bounds = response::segmentBounds(r.branch);
    for (std::size_t k = 0; k + 1 < bounds.size(); ++k) {  // one line per sweep, labelled once
      std::vector<double> hz;
      for (std::size_t i = bounds[k]; i < bounds[k + 1]; ++i) hz.push_back(r.omega[i] / (2 * M_PI));
      plot.addLine(hz, std::vector<double>(r.measure.begin() + long(bounds[k]), r.measure.begin() + long(bounds[k + 1])),
                   post::SvgPlot::palette(index), k == 0 ? label.str() : std::string());
    }
    if (r.peak > 0) peaks.push_back({c.value, r.peak, r.peakOmega});
    table << c.value << "," << r.peakOmega / (2 * M_PI) << "," << r.peak << "," << r.branch.points.size() << ","
          << (r.branch.finished ? 1 : 0) << "," << c.seconds << "\n";
    ++index;
  };
  try {
    disc::studyDisc(mesh, models, plan.spec, solved, *disc::discStudyParameterFromName(name), values, sweep,
                    writeCurve);
  } catch (const InputError& e) {
    throw InputError(studies.where(name), e.problem());
  }
  if (comm->getRank() == 0) {
    plot.write(outDir + "/study_" + name + ".svg");
    AtomicFile file(outDir + "/study_" + name + ".csv");
    std::ofstream out(file.tempPath());
    out << table.str();
    out.close();
    if (!out) throw Error("cannot write " + outDir + "/study_" + name + ".csv");
    file.commit();
  }
  summary.written.push_back(outDir + "/study_" + name + ".svg");
  summary.written.push_back(outDir + "/study_" + name + ".csv");
  return index;
}

// disc_response/hysteresis_contacts, checked against the contact pairs (one element per pair).
std::vector<int> readHysteresisContacts(SceneSection& d, const mesh::Mesh& mesh, const DiscResponseSpec& spec) {
  const std::vector<int> contacts = d.getIntList("hysteresis_contacts", {});
  const int count = int(mesh.nodeSet(spec.contact.rightSet).size());
  for (int e : contacts)
    if (e < 0 || e >= count)
      throw InputError(d.where("hysteresis_contacts"), "contact " + std::to_string(e) + " is not one of the " +
                                                           std::to_string(count) +
                                                           " shroud contact pairs (0-based, as in disc_frc_contacts.csv)");
  return contacts;
}

}  // namespace

void discStages(SceneSection& scene, const mesh::Mesh& mesh, int builtInSectors, bool forcedResponse,
                const std::string& outDir, const std::shared_ptr<continuation::TraceCheckpoints>& checkpoints,
                linalg::CommPtr comm, SceneSummary& summary) {
  auto r = scene.section("reduced_model");
  auto d = scene.section("disc_response");
  const DiscPlan plan = readDiscPlan(scene, r, d, mesh, builtInSectors, forcedResponse, outDir, comm);
  const auto models = reducedModelsStage(mesh, plan, outDir, comm, summary);
  if (!forcedResponse) return;

  const auto sweep = readSweepOptions(d, plan.harmonicsCheckTo, checkpoints);
  const auto hysteresisContacts = readHysteresisContacts(d, mesh, plan.spec);
  auto solved = referenceStage(mesh, models, plan, sweep, outDir, comm, summary);
  peakOutputsStage(mesh, models, plan, solved, hysteresisContacts, outDir, comm, summary);

  // Parameter studies: one curve per value, one plot per study, peaks in a table.
  auto studies = d.section("studies");
  Timer studiesTimer;
  int studyCurves = 0;
  std::map<std::string, std::vector<StudyPeak>> studyPeaks;  // for the peak studies' comparison
  for (const char* name : {"preload", "mu", "contact_stiffness", "force", "loss_factor", "harmonics", "modes",
                           "clearance"})
    if (studies.has(name)) {
      std::vector<StudyPeak> peaks;
      studyCurves += studyStage(studies, name, mesh, models, plan, solved, sweep, outDir, comm, summary, peaks);
      if (!peaks.empty()) studyPeaks[name] = peaks;
    }
  studies.rejectUnknownKeys();
  followDiscPeaks(plan.peakStudies, mesh, models, plan.spec, solved.setup, solved.curve, solved.fromHz, solved.toHz,
                  studyPeaks, outDir, comm, summary);
  d.rejectUnknownKeys();
  if (studyCurves > 0)
    summary.stages.push_back({"parameter studies (" + std::to_string(studyCurves) + " curves)", studiesTimer.seconds(),
                              "the samples check per curve (summary); the harmonic truncation: the reference curve's check"});
}

}  // namespace cyclone::scenes
