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
#include "cyclone/scenes/DiscForcedResponse.hpp"
#include "cyclone/scenes/DiscReducedModels.hpp"
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
    spec.axis.point = cy.getVector3("axis_point", {0, 0, 0});
    spec.axis.direction = cy.getVector3("axis_direction", {0, 0, 1});
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
  spec.kind = r.getString("kind", spec.kind);
  spec.retainedNodeSets = r.getStringList("retained_node_sets", spec.retainedNodeSets);
  spec.modes = r.getInt("modes", spec.modes);
  spec.omega0 = r.getDouble("omega0", spec.omega0);
  spec.lossFactor = r.getDouble("loss_factor", spec.lossFactor);
  if (!(spec.lossFactor >= 0)) throw InputError(r.where("loss_factor"), "must be >= 0");
  spec.rpm = r.getDouble("speed_rpm", loadsRpm);
  if (!(spec.rpm >= 0)) throw InputError(r.where("speed_rpm"), "must be >= 0");
  spec.prestress = r.getString("prestress", spec.prestress);
  cache = r.getString("cache", "reuse");
  if (cache != "reuse" && cache != "rebuild" && cache != "off")
    throw InputError(r.where("cache"), "use reuse (read a model whose inputs match), rebuild or off");
  return spec;
}

std::vector<int> readHarmonics(SceneSection& s) {
  auto list = s.getIntList("harmonics", {3});
  if (list.size() == 1) {
    const int H = list[0];
    if (H < 1) throw InputError(s.where("harmonics"), "needs at least harmonic 1");
    list.clear();
    for (int h = 0; h <= H; ++h) list.push_back(h);
  }
  return list;
}

DiscResponseSpec readResponseSpec(SceneSection& d) {
  DiscResponseSpec spec;
  spec.engineOrder = d.getInt("engine_order", 0);
  if (!d.has("engine_order")) throw InputError(d.where("engine_order"), "is required (the excitation's engine order)");
  spec.harmonics = readHarmonics(d);
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
struct Curve {
  std::vector<double> hz, peak;
  std::vector<std::size_t> starts{0};  ///< where each sweep starts (continuation::Branch::segmentStarts)
};

Curve curveOf(ForcedResponseSetup& setup, const continuation::Branch& branch) {
  Curve c;
  const auto& hb = *setup.system;
  const int nc = hb.numCoefficients(), dof = setup.outputDofs.front();
  for (const auto& pt : branch.points) {
    c.hz.push_back(setup.apply(pt.parameter).first / (2 * M_PI));
    c.peak.push_back(hbm::peakMagnitude(hb.aft().harmonics(), Eigen::VectorXd(pt.x.segment(dof * nc, nc))));
  }
  c.starts.insert(c.starts.end(), branch.segmentStarts.begin(), branch.segmentStarts.end());
  return c;
}

// The models with another loss factor or fewer modes (hybrid and truncation models only).
DiscReducedModels variedModels(const DiscReducedModels& base, double lossFactor, int modes) {
  DiscReducedModels out = base;
  for (auto& [k, m] : out.models) {
    const auto* h = dynamic_cast<const rom::HybridFrfModel*>(m.get());
    if (!h) throw InputError("disc_response/studies", "loss_factor and modes studies need hybrid or truncation models");
    const double eta = lossFactor >= 0 ? lossFactor : h->lossFactor();
    const auto kept = modes > 0 ? h->modes().first(std::min(modes, h->modes().numModes() / h->modes().copies))
                                : h->modes();
    m = h->hasStaticCorrection() ? std::make_shared<rom::HybridFrfModel>(kept, h->staticCompliance(), eta)
                                 : std::make_shared<rom::HybridFrfModel>(rom::HybridFrfModel::modalTruncation(kept, eta));
  }
  return out;
}

std::string shortNumber(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

// The relative motion W and force F (coefficients) of every contact at the peak point.
struct PeakContactStates {
  double omega = 0;
  Eigen::MatrixXd X;                            // nc x dofs
  std::vector<Eigen::MatrixXd> W, F;            // per element: nc x d
};

PeakContactStates peakContactStates(const PeakPoint& point) {
  const auto& hb = *point.system;
  const int nc = hb.numCoefficients();
  PeakContactStates out;
  out.omega = point.omega;
  out.X = Eigen::Map<const Eigen::MatrixXd>(point.x.data(), nc, hb.numDofs());
  for (const auto& c : hb.elements()) {
    Eigen::MatrixXd W = out.X * c.W;
    if (c.Wnext.size() != 0) W += hb.nextSectorMap() * (out.X * c.Wnext);
    Eigen::MatrixXd F;
    c.element->harmonicForce(hb.aft(), W, out.omega, F, nullptr);
    out.W.push_back(W), out.F.push_back(F);
  }
  return out;
}

// Per contact at the peak point: the energy friction dissipates per cycle,
// E = sum_h pi h (F_ch . W_sh - F_sh . W_ch) from the coefficients of the relative
// motion w and of the contact force f (exact for the harmonics kept), and the
// mean normal force. Returns the energies.
std::vector<double> writeContactEnergies(const hbm::HarmonicSet& H, const PeakContactStates& peak,
                                         const std::string& path) {
  AtomicFile file(path);
  std::ofstream csv(file.tempPath());
  csv.precision(10);
  csv << "contact,freq_hz,dissipated_energy_per_cycle,mean_normal_force,slip_amplitude\n";
  std::vector<double> energies;
  for (std::size_t e = 0; e < peak.W.size(); ++e) {
    const Eigen::MatrixXd &W = peak.W[e], &F = peak.F[e];
    double energy = 0, slip = 0;
    for (int h : H.harmonics()) {
      if (h == 0) continue;
      const int ic = H.cosIndex(h), is = H.sinIndex(h);
      for (int k = 0; k < W.cols(); ++k) energy += M_PI * h * (F(ic, k) * W(is, k) - F(is, k) * W(ic, k));
      if (h == 1 && W.cols() == 3) slip = std::hypot(std::hypot(W(ic, 0), W(is, 0)), std::hypot(W(ic, 1), W(is, 1)));
    }
    const double normal = H.contains(0) ? F(H.cosIndex(0), W.cols() - 1) : 0.0;
    csv << e << "," << peak.omega / (2 * M_PI) << "," << energy << "," << normal << "," << slip << "\n";
    energies.push_back(energy);
  }
  csv.close();
  file.commit();
  return energies;
}

// Contact hysteresis loops at the peak point: the sampled contact law
// (not its truncated Fourier series, whose Gibbs ripples would blur the stick and
// slip corners) against the relative motion over one period, for the chosen
// contacts; and the response DOFs over that period.
void writePeakTimeResponse(const ForcedResponseSetup& setup, const PeakPoint& point, const PeakContactStates& peak,
                           const std::vector<int>& contacts, const std::string& outDir, SceneSummary& summary) {
  const auto& hb = *point.system;
  const auto& aft = hb.aft();
  const int N = aft.numSamples();
  const double hz = peak.omega / (2 * M_PI);
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
      const Eigen::MatrixXd& W = peak.W[std::size_t(e)];
      const int d = int(W.cols());
      Eigen::MatrixXd w(N, d);
      for (int c = 0; c < d; ++c) aft.toTime(W.col(c).data(), w.col(c).data());
      const Eigen::MatrixXd f = hb.elements()[std::size_t(e)].element->forceSamples(aft, W, peak.omega);
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
    Eigen::MatrixXd x(N, setup.outputDofs.size());
    for (std::size_t k = 0; k < setup.outputDofs.size(); ++k) {
      aft.toTime(peak.X.col(setup.outputDofs[k]).data(), x.col(Eigen::Index(k)).data());
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

}  // namespace

void discStages(SceneSection& scene, const mesh::Mesh& mesh, int builtInSectors, bool forcedResponse,
                const std::string& outDir, const std::shared_ptr<continuation::TraceCheckpoints>& checkpoints,
                linalg::CommPtr comm, SceneSummary& summary) {
  std::string cache;
  auto r = scene.section("reduced_model");
  auto d = scene.section("disc_response");
  const DiscModelSpec modelSpec = readModelSpec(scene, r, builtInSectors, cache);
  std::vector<int> nds;
  DiscResponseSpec spec;
  int harmonicsCheckTo = 0;
  PeakStressSpec peakStress;
  std::vector<PeakStudySpec> peakStudies;
  if (forcedResponse) {
    spec = readResponseSpec(d);
    peakStudies = readPeakStudies(d.section("peak_studies"), spec);
    peakStress = readPeakStressSpec(d, scene.section("material"), modelSpec.material);
    const int maxHarmonic = *std::max_element(spec.harmonics.begin(), spec.harmonics.end());
    harmonicsCheckTo = readHarmonicsCheckTo(d, maxHarmonic);
    if (spec.engineOrder >= 1 && spec.engineOrder < modelSpec.sectors) {
      // Also the nodal diameters of the harmonics the curve's harmonics check adds.
      auto checked = spec.harmonics;
      for (int h = maxHarmonic + 1; h <= std::max(maxHarmonic + 1, harmonicsCheckTo); ++h) checked.push_back(h);
      nds = nodalDiametersFor(modelSpec.sectors, spec.engineOrder, checked);
    }
    if (r.has("nodal_diameters"))
      throw InputError(r.where("nodal_diameters"), "is chosen by disc_response (engine order and harmonics)");
  } else {
    nds = r.getIntList("nodal_diameters", {});
    if (nds.empty())
      throw InputError(r.where("nodal_diameters"), "is required when the scene builds reduced models alone");
  }
  const std::string cacheDir = cache == "off" ? std::string() : outDir + "/reduced_models";
  DiscModelSpec checkedSpec = modelSpec;
  checkedSpec.checkFrequencies = r.getInt("check_frequencies", 12);
  if (forcedResponse && spec.engineOrder >= 1 && spec.engineOrder < modelSpec.sectors)
    checkedSpec.checkNodalDiameter = nodalDiametersFor(modelSpec.sectors, spec.engineOrder, {1}).front();
  if (cache == "rebuild" && comm->getRank() == 0) std::filesystem::remove_all(cacheDir);
  // Engine-order errors before any FE work.
  if (forcedResponse && (spec.engineOrder < 1 || spec.engineOrder >= modelSpec.sectors)) {
    DiscReducedModels none;
    none.sectors = modelSpec.sectors;
    makeDiscForcedResponse(mesh, none, spec);  // throws the explained InputError
  }
  r.rejectUnknownKeys();
  Timer romTimer;
  const auto models = buildDiscReducedModels(mesh, checkedSpec, nds, cacheDir, comm);
  {
    const auto& c = models.check;
    std::ostringstream estimate;
    if (c.nodalDiameter >= 0) {
      estimate << "largest relative error " << c.maxError() << " against the full FE compliance at ND "
               << c.nodalDiameter << " over " << c.hz.size() << " frequencies (" << c.hz.front() << ".." << c.hz.back()
               << " Hz)";
      if (comm->getRank() == 0) {
        post::SvgPlot plot("Reduced model (" + modelSpec.kind + ", " + std::to_string(modelSpec.modes) +
                               " modes) against the full FE model, ND " + std::to_string(c.nodalDiameter),
                           "frequency (Hz)", "|A| at the mid-blade node (mm/N)");
        plot.addLine(c.hz, c.full, post::SvgPlot::palette(0), "full FE (complex solve)");
        plot.addMarkers(c.hz, c.reduced, post::SvgPlot::palette(1), "reduced model");
        plot.write(outDir + "/rom_check.svg");
        writeReducedModelCheckCsv(outDir + "/rom_check.csv", c);
      }
      summary.written.push_back(outDir + "/rom_check.svg");
      summary.written.push_back(outDir + "/rom_check.csv");
      summary.computed.push_back("reduced model check: " + estimate.str());
    } else {
      estimate << "not checked (a reused model built before the check, or check_frequencies: 0)";
    }
    summary.stages.push_back({"reduced models (" + modelSpec.kind + ")", romTimer.seconds(), estimate.str()});
  }
  {
    std::ostringstream line;
    line << "reduced models (" << modelSpec.kind << ", " << modelSpec.modes << " natural frequencies per ND, "
         << models.retainedNodes.size() << " retained nodes) for ND";
    for (const auto& [k, m] : models.models) line << " " << k;
    line << " at " << modelSpec.rpm << " rpm: " << models.built << " built, " << models.reused << " reused, "
         << models.seconds << " s";
    summary.computed.push_back(line.str());
    for (const auto& [k, f] : models.files) summary.written.push_back(f);
  }
  if (!forcedResponse) return;

  const int family = d.getInt("family", 1);
  const auto range = d.getDoubleList("frequency_range_hz", {});
  if (!range.empty() && (range.size() != 2 || !(range[0] > 0) || !(range[1] > range[0])))
    throw InputError(d.where("frequency_range_hz"), "needs two increasing positive frequencies [from, to] in Hz");
  const std::vector<int> hysteresisContacts = d.getIntList("hysteresis_contacts", {});
  const std::string stability = d.getString("stability", "auto");
  if (stability != "auto" && stability != "true" && stability != "false")
    throw InputError(d.where("stability"), "must be auto, true or false");
  auto cs = d.section("continuation");
  // The engine's own defaults for the disc (discContinuationOptions), then the scene's keys.
  using Engine = continuation::ContinuationOptions::Engine;
  continuation::ContinuationOptions opt =
      discContinuationOptions(cs.getString("engine", "predictor_corrector") == "loca" ? Engine::Loca
                                                                                    : Engine::PredictorCorrector);
  // An engine the scene names is used alone; by default the other one retraces a curve
  // the first leaves incomplete.
  std::optional<continuation::ContinuationOptions> fallback;
  if (!cs.has("engine")) fallback = discContinuationOptions(Engine::Loca);
  readContinuationSteps(cs, opt, "predictor_corrector");
  opt.tolerance = cs.getDouble("tolerance", opt.tolerance);
  cs.rejectUnknownKeys();
  opt.checkpoints = checkpoints;
  if (fallback) fallback->checkpoints = checkpoints;

  // The reference system: the range from its resonance estimate unless given.
  auto setup = makeDiscForcedResponse(mesh, models, spec);
  const int contactCount = int(setup.system->elements().size());
  for (int e : hysteresisContacts)
    if (e < 0 || e >= contactCount)
      throw InputError(d.where("hysteresis_contacts"), "contact " + std::to_string(e) + " is not one of the " +
                                                           std::to_string(contactCount) +
                                                           " shroud contact pairs (0-based, as in disc_frc_contacts.csv)");
  // The estimate sets the range unless the scene gives one; then it only informs,
  // and a failed estimate (no stuck peak on its scan) is reported, not fatal.
  ResonanceEstimate estimate = ResonanceEstimate{};
  std::string estimateText;
  try {
    estimate = estimateResonance(setup, models, family);
    std::ostringstream text;
    text << "family " << family << " at " << estimate.freeHz << " Hz with the shroud free, " << estimate.stuckHz
         << " Hz with the contacts stuck";
    estimateText = text.str();
  } catch (const InputError& e) {
    if (range.empty()) throw;
    estimateText = std::string("no resonance estimate (") + e.what() + ")";
  }
  double fromHz = 0, toHz = 0;
  if (range.empty()) {
    fromHz = 0.9 * std::min(estimate.freeHz, estimate.stuckHz);
    toHz = 1.1 * std::max(estimate.freeHz, estimate.stuckHz);
  } else {
    fromHz = range[0], toHz = range[1];
  }
  {
    std::ostringstream line;
    line << "engine order " << spec.engineOrder << " on ND "
         << nodalDiametersFor(modelSpec.sectors, spec.engineOrder, {1}).front() << ": " << estimateText << "; sweep "
         << fromHz << " -> " << toHz << " Hz";
    summary.computed.push_back(line.str());
    log::info(line.str());
  }
  auto traceOne = [&](ForcedResponseSetup& s, const std::string& name) {
    s.omegaUnit = 2 * M_PI * fromHz;
    s.stability = stability;
    s.harmonicsKey = "disc_response/harmonics";
    // The reference curve's peak is checked up to harmonics_check_to; a study's curves
    // are not (each level costs peak searches; the stage's error is the reference's).
    s.harmonicsCheckTo = name == "disc_frc" ? harmonicsCheckTo : -1;
    s.continuation = opt;
    s.continuation.from = 1.0, s.continuation.to = toHz / fromHz;
    s.fallback = fallback;
    const auto result = traceAndWriteForcedResponse(s, outDir, name, comm, summary);
    if (!result.branch.points.empty()) {
      const double peakHz = result.peakOmega / (2 * M_PI);
      const double span = toHz - fromHz;
      if (peakHz < fromHz + 1e-3 * span || peakHz > toHz - 1e-3 * span) {
        std::ostringstream msg;
        msg << name << ": the largest response is at the end of the sweep (" << peakHz << " Hz): the resonance lies "
            << "outside " << fromHz << ".." << toHz << " Hz (" << estimateText
            << "); widen disc_response/frequency_range_hz";
        log::warn(msg.str());
        summary.computed.push_back("warning: " + msg.str());
      }
    }
    return result;
  };
  Timer responseTimer;
  auto reference = traceOne(setup, "disc_frc");
  summary.stages.push_back({"forced response (H = " + std::to_string(setup.system->aft().harmonics().maxHarmonic()) +
                                ", " + std::to_string(reference.branch.points.size()) + " points)",
                            responseTimer.seconds(),
                            "Newton tolerance " + shortNumber(opt.tolerance) +
                                " (residual relative to the forces); " + reference.samplesCheck + "; " +
                                reference.harmonicsCheck});
  if (const auto& best = reference.harmonicsPeak; best.found) {
    // The headline: the peak at the highest harmonic count reached, converged or
    // labelled an estimate with the last change next to it.
    constexpr double kConverged = 1e-2;
    std::ostringstream line;
    line.precision(6);
    line << "friction-damped peak: max|x(t)| " << best.value << " at " << best.hz << " Hz with harmonics 0.."
         << best.maxHarmonic;
    if (best.change < 0)
      line << "; an estimate: its convergence in the harmonics is not known (no level below it to compare)";
    else if (best.change <= kConverged)
      line << "; converged in the harmonics to " << 100 * kConverged << " % (H " << best.belowHarmonic << " -> "
           << best.maxHarmonic << " changed it by " << 100 * best.change << " %)";
    else
      line << "; an estimate, not converged in the harmonics: H " << best.belowHarmonic << " -> " << best.maxHarmonic
           << " changed it by " << 100 * best.change << " % (disc_frc_harmonics.csv)";
    // A level above that was tried and not found leaves the error unbounded by the
    // last change (the default disc at H = 5: docs/scenes.md).
    if (best.notFoundHarmonic >= 0)
      line << "; H = " << best.notFoundHarmonic << " was tried and its peak not found, so the error may exceed "
           << "the last change";
    summary.computed.insert(summary.computed.begin(), line.str());
    log::info(line.str());
  }
  if (!reference.branch.points.empty()) {
    // Contacts, loops, the period and the sector's stresses at one point: the converged peak.
    const PeakPoint point = referencePeakPoint(setup, reference);
    if (comm->getRank() == 0) {
      const PeakContactStates peak = peakContactStates(point);
      const auto energies =
          writeContactEnergies(point.system->aft().harmonics(), peak, outDir + "/disc_frc_contacts.csv");
      summary.written.push_back(outDir + "/disc_frc_contacts.csv");
      // Default: the contact that dissipates most at the peak.
      std::vector<int> loops = hysteresisContacts;
      if (loops.empty()) loops.push_back(int(std::max_element(energies.begin(), energies.end()) - energies.begin()));
      writePeakTimeResponse(setup, point, peak, loops, outDir, summary);
    }
    if (peakStress.atHz > 0)
      writePeakStress(peakStress, mesh, models, modelSpec, referencePointAt(setup, reference, peakStress.atHz),
                      setup.excitationScale, outDir, comm, summary);
    else
      writePeakStress(peakStress, mesh, models, modelSpec, point, setup.excitationScale, outDir, comm, summary);
  }

  // Parameter studies: one curve per value, one plot per study, peaks in a table.
  auto studies = d.section("studies");
  const std::vector<std::string> known{"preload", "mu", "contact_stiffness", "force", "loss_factor", "harmonics",
                                       "modes", "clearance"};
  Timer studiesTimer;
  int studyCurves = 0;
  std::map<std::string, std::vector<StudyPeak>> studyPeaks;  // for the peak studies' comparison
  for (const auto& name : known) {
    if (!studies.has(name)) continue;
    const auto values = studies.getDoubleList(name, {});
    if (values.empty()) throw InputError(studies.where(name), "needs a list of values");
    post::SvgPlot plot("Study: " + name + " (engine order " + std::to_string(spec.engineOrder) + ")", "frequency (Hz)",
                       "max |x(t)| of " + setup.dofNames[setup.outputDofs.front()]);
    std::ostringstream table;
    table.precision(10);
    table << name << ",peak_hz,peak_max_abs,points,finished,seconds\n";
    for (std::size_t i = 0; i < values.size(); ++i) {
      const double v = values[i];
      DiscResponseSpec sv = spec;
      const DiscReducedModels* m = &models;
      DiscReducedModels varied;
      if (name == "preload") sv.contact.preload = v;
      else if (name == "mu") sv.contact.mu = v;
      else if (name == "contact_stiffness") sv.contact.kn = v, sv.contact.kt = v;
      else if (name == "force") sv.excitation.amplitude = spec.excitation.amplitude * v;
      else if (name == "clearance") {
        if (spec.gap.pairs.empty())
          throw InputError(studies.where(name), "needs gap elements (disc_response/gap/pairs)");
        sv.gap.clearance = v;
      }
      else if (name == "harmonics") {
        sv.harmonics.clear();
        for (int h = 0; h <= int(v); ++h) sv.harmonics.push_back(h);
        for (int k : nodalDiametersFor(modelSpec.sectors, spec.engineOrder, sv.harmonics))
          if (!models.models.count(k))
            throw InputError(studies.where(name), "harmonic " + std::to_string(int(v)) + " needs nodal diameter " +
                                                      std::to_string(k) + ": raise disc_response/harmonics to the "
                                                      "study's largest value");
      } else if (name == "loss_factor") varied = variedModels(models, v, 0), m = &varied;
      else if (name == "modes") varied = variedModels(models, -1, int(v)), m = &varied;
      std::ostringstream tag;
      tag << "study_" << name << "_" << i;
      Timer t;
      // A value that reproduces the reference scene is the reference curve: its files are
      // copied, not traced again (the loss factor and modes change the models: always traced).
      const bool isReference = (name == "preload" && v == spec.contact.preload) ||
                               (name == "mu" && v == spec.contact.mu) ||
                               (name == "contact_stiffness" && v == spec.contact.kn && v == spec.contact.kt) ||
                               (name == "force" && v == 1.0) ||
                               (name == "clearance" && v == spec.gap.clearance) ||
                               (name == "harmonics" && sv.harmonics == spec.harmonics);
      std::optional<ForcedResponseSetup> traced;
      if (!isReference) {
        traced.emplace(makeDiscForcedResponse(mesh, *m, sv));
        traced->whenNothingTraced = ForcedResponseSetup::WhenNothingTraced::Report;  // the table says so
      }
      const auto result = isReference ? reference : traceOne(*traced, tag.str());
      if (isReference) {
        if (comm->getRank() == 0)
          for (const std::string ext : {".csv", ".h5", ".svg"}) {
            if (!std::filesystem::exists(outDir + "/disc_frc" + ext)) continue;
            AtomicFile copy(outDir + "/" + tag.str() + ext);
            std::filesystem::copy_file(outDir + "/disc_frc" + ext, copy.tempPath(),
                                       std::filesystem::copy_options::overwrite_existing);
            copy.commit();
          }
        for (const std::string ext : {".h5", ".csv", ".svg"}) summary.written.push_back(outDir + "/" + tag.str() + ext);
        std::ostringstream line;
        line << tag.str() << ": " << name << " = " << v << " is the reference scene: disc_frc's curve, not traced again";
        summary.computed.push_back(line.str());
        log::info(line.str());
      }
      const Curve c = curveOf(isReference ? setup : *traced, result.branch);
      std::ostringstream label;
      label << name << " = " << v;
      for (std::size_t k = 0; k < c.starts.size(); ++k) {  // one line per sweep, labelled once
        const auto a = long(std::min(c.starts[k], c.hz.size()));
        const auto b = long(k + 1 < c.starts.size() ? std::min(c.starts[k + 1], c.hz.size()) : c.hz.size());
        if (b - a < 1) continue;
        plot.addLine(std::vector<double>(c.hz.begin() + a, c.hz.begin() + b),
                     std::vector<double>(c.peak.begin() + a, c.peak.begin() + b), post::SvgPlot::palette(int(i)),
                     k == 0 ? label.str() : std::string());
      }
      ++studyCurves;
      if (result.peak > 0) studyPeaks[name].push_back({v, result.peak, result.peakOmega});
      table << v << "," << result.peakOmega / (2 * M_PI) << "," << result.peak << "," << result.branch.points.size()
            << "," << (result.branch.finished ? 1 : 0) << "," << t.seconds() << "\n";
    }
    if (comm->getRank() == 0) {
      plot.write(outDir + "/study_" + name + ".svg");
      AtomicFile file(outDir + "/study_" + name + ".csv");
      std::ofstream out(file.tempPath());
      out << table.str();
      out.close();
      file.commit();
    }
    summary.written.push_back(outDir + "/study_" + name + ".svg");
    summary.written.push_back(outDir + "/study_" + name + ".csv");
  }
  studies.rejectUnknownKeys();
  followDiscPeaks(peakStudies, mesh, models, spec, setup, reference, fromHz, toHz, studyPeaks, outDir, comm, summary);
  d.rejectUnknownKeys();
  if (studyCurves > 0)
    summary.stages.push_back({"parameter studies (" + std::to_string(studyCurves) + " curves)", studiesTimer.seconds(),
                              "the samples check per curve (summary); the harmonic truncation: the reference curve's check"});
}

}  // namespace cyclone::scenes
