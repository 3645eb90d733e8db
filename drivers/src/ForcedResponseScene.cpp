// A matrix-defined forced-response scene (analysis: forced_response) read into a
// response::ForcedResponseSetup: system matrices, nonlinear elements, engine order,
// forces and the continuation section (its engine and steps: ContinuationReaders.cpp).
#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include <Teuchos_YamlParameterListCoreHelpers.hpp>
#include <Eigen/Eigenvalues>

#include "SceneStages.hpp"
#include "cyclone/continuation/ArclengthContinuation.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/core/NumberText.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/hbm/CubicSpring.hpp"
#include "cyclone/hbm/FrictionContact.hpp"
#include "cyclone/hbm/HarmonicBalanceSystem.hpp"
#include "cyclone/hbm/JenkinsElement.hpp"
#include "cyclone/hbm/QuadraticDamper.hpp"
#include "cyclone/hbm/ScalarElementAdapter.hpp"
#include "cyclone/hbm/UnilateralSpring.hpp"
#include "cyclone/response/ForcedResponseChecks.hpp"
#include "cyclone/scenes/ForcedResponseScene.hpp"
#include "cyclone/scenes/SceneSection.hpp"
#include "MatrixSystemReaders.hpp"

namespace cyclone::scenes {

namespace {
// The engine order of the excitation's forces (one travelling wave), into the coupling.
void readEngineOrder(SceneSection& ex, MatrixSystemInput& in) {
  bool haveOrder = false;
  for (const auto& name : ex.sectionNames()) {
    auto f = ex.section(name);
    if (!f.has("engine_order")) continue;
    if (!in.cyclic()) throw InputError(f.where("engine_order"), "is for cyclic systems (system: sectors >= 2)");
    const int eo = f.getInt("engine_order", 0);
    if (haveOrder && eo != in.coupling.engineOrder)
      throw InputError(f.where("engine_order"), "differs from another force's (" +
                                                    std::to_string(in.coupling.engineOrder) +
                                                    "): the cyclic reduction needs one travelling wave");
    in.coupling.engineOrder = eo, haveOrder = true;
  }
  if (in.cyclic() && !haveOrder)
    throw InputError(ex.location(), "a cyclic system needs the travelling wave's engine_order on its forces");
}

// The excitation's forces (cos/sin coefficients, or amplitude A and phase phi: A cos(h w t
// + phi)), its scale, and the static loads.
void readForces(SceneSection& scene, SceneSection& ex, ForcedResponseSetup& setup) {
  auto& hb = *setup.system;
  bool vibrating = false;  // some force at a harmonic >= 1
  for (const auto& name : ex.sectionNames()) {
    auto f = ex.section(name);
    if (f.has("engine_order")) f.getInt("engine_order", 0);  // read with the system
    double c = f.getDouble("cos", 0.0), sn = f.getDouble("sin", 0.0);
    if (f.has("amplitude")) {
      if (f.has("cos") || f.has("sin"))
        throw InputError(f.location(), "give either cos/sin or amplitude/phase, not both");
      const double A = f.getDouble("amplitude", 0.0), phi = f.getDouble("phase", 0.0);
      c = A * std::cos(phi), sn = -A * std::sin(phi);
    } else if (f.has("phase")) {
      throw InputError(f.where("phase"), "goes with amplitude (A cos(h w t + phase))");
    }
    const int harmonic = f.getInt("harmonic", 1);
    hb.addExcitation(f.getInt("dof", 0), harmonic, c, sn);
    vibrating = vibrating || harmonic >= 1;
    f.rejectUnknownKeys();
  }
  // Only harmonic 0: a static load swept in frequency, whose "peak" was the range's start,
  // exit 0 (issue 49 probe).
  if (!vibrating && !ex.sectionNames().empty())
    throw InputError(ex.location(), "has forces at harmonic 0 only: a static load, nothing vibrates (give the "
                                    "vibrating forces harmonic >= 1; a constant load belongs in static_loads)");
  setup.excitationScale = ex.getDouble("scale", 1.0);
  if (!std::isfinite(setup.excitationScale)) throw InputError(ex.where("scale"), "must be a finite number");
  ex.rejectUnknownKeys();
  auto statics = scene.section("static_loads");
  for (const auto& name : statics.sectionNames()) {
    auto l = statics.section(name);
    try {
      hb.addStaticLoad(l.getInt("dof", 0), l.requireDouble("value"));
    } catch (const InputError& err) {
      throw InputError(l.location(), err.what());
    }
    l.rejectUnknownKeys();
  }
  statics.rejectUnknownKeys();
}

// The continuation section: the parameter (and the fixed frequency where it is not the
// frequency), the range, the engine and its steps.
void readContinuation(SceneSection& cs, ForcedResponseSetup& setup) {
  auto& opt = setup.continuation;
  const std::string parameter = cs.getString("parameter", "omega");
  if (parameter == "omega") {
    setup.parameter = ForcedResponseSetup::Parameter::Omega;
  } else if (parameter == "force_scale") {
    setup.parameter = ForcedResponseSetup::Parameter::ForceScale;
    setup.omega = cs.requireDouble("omega");
    if (!(setup.omega > 0)) throw InputError(cs.where("omega"), "must be positive (rad/s)");
  } else if (parameter == "damping_scale") {
    setup.parameter = ForcedResponseSetup::Parameter::DampingScale;
  } else if (parameter.find('/') != std::string::npos) {
    setup.parameter = ForcedResponseSetup::Parameter::ElementParameter;
    const std::string element = parameter.substr(0, parameter.find('/'));
    setup.elementParameter = parameter.substr(parameter.find('/') + 1);
    try {
      selectElementParameter(setup, element, setup.elementParameter, cs.requireDouble("from"));
    } catch (const InputError& e) {
      throw InputError(cs.where("parameter"), e.what());
    }
  } else {
    throw InputError(cs.where("parameter"),
                     "unknown parameter '" + parameter +
                         "' (omega: excitation frequency; force_scale: f = s f_ex; <element>/<parameter>, e.g. "
                         "contact/preload; damping_scale)");
  }
  if (setup.parameter != ForcedResponseSetup::Parameter::Omega &&
      setup.parameter != ForcedResponseSetup::Parameter::ForceScale) {
    setup.omega = cs.requireDouble("omega");
    if (!(setup.omega > 0)) throw InputError(cs.where("omega"), "must be positive (rad/s)");
  }
  opt.from = cs.requireDouble("from");
  opt.to = cs.requireDouble("to");
  // to < from is a downward sweep; to = from is no range (issue 20).
  if (!(opt.from != opt.to))
    throw InputError(cs.where("to"), "equals from (" + std::to_string(opt.from) +
                                         "): a range needs two different ends (to < from sweeps downwards)");
  // Cyclone's predictor-corrector by default, LOCA retracing a curve it leaves
  // incomplete; an engine the scene names is used alone, as for the disc.
  if (!cs.has("engine")) {
    setup.fallback = continuation::locaOptions();
  }
  readContinuationSteps(cs, opt, continuation::engineKey(continuation::ContinuationOptions::Engine::PredictorCorrector));
  opt.tolerance = readContinuationTolerance(cs, opt.tolerance);
  cs.rejectUnknownKeys();
  if (setup.parameter == ForcedResponseSetup::Parameter::Omega && (!(opt.from > 0) || !(opt.to > 0)))
    throw InputError(cs.location(), "the frequency range must be positive");
  // As the forces are (response::kLargestTraceable): to = 1e300 rad/s failed at once with
  // "the residual or Jacobian failed at the start of the range" (a fifth probe).
  if (setup.parameter == ForcedResponseSetup::Parameter::Omega)
    for (const auto& [key, w] : {std::pair<const char*, double>{"from", opt.from}, {"to", opt.to}})
      if (!(w < response::kLargestTraceable))
        throw InputError(cs.where(key), numberText(w) + " rad/s is beyond " + numberText(response::kLargestTraceable) +
                                            ": the trace's products of its square (the inertia forces) overflow "
                                            "double precision");
  // The residual is relative to the forces at scale 1, so a point at scale s is solved to
  // tolerance / s of its own forces: at 1e-10 the solution 0 passed (issue 49 probe).
  if (setup.parameter == ForcedResponseSetup::Parameter::ForceScale)
    for (const auto& [key, s] : {std::pair<const char*, double>{"from", opt.from}, {"to", opt.to}})
      if (s != 0 && std::abs(s) < 1e4 * opt.tolerance)
        throw InputError(cs.where(key), "a force scale of " + numberText(s) +
                                            " is solved to the tolerance over it of its own forces (" +
                                            numberText(opt.tolerance / std::abs(s)) +
                                            "; the residual is relative to the forces at scale 1): start at " +
                                            numberText(1e4 * opt.tolerance) + " or above, or at 0");
}

}  // namespace

ForcedResponseSetup readForcedResponseSetup(SceneSection& scene) {
  MatrixSystemInput in = readMatrixSystem(scene);
  const hbm::HarmonicSet harmonics(readHarmonicList(scene, 7));
  const HarmonicsTargetKeys harmonicsTarget = readHarmonicsTarget(scene, 7);
  // Elements first: the default sample count depends on them (friction and gaps need
  // many samples per period to place their events).
  ForcedResponseSetup setup;
  const auto placed = readNonlinearElements(scene, in, setup.elementNames);
  std::vector<std::shared_ptr<const hbm::NonlinearElement>> elements;
  for (const auto& p : placed) elements.push_back(p.element);
  const int recommended = response::recommendedSamples(harmonics, elements);
  const int samples = scene.getInt("samples", recommended);
  if (samples < harmonics.minimumSamples() || samples > kMaxSamples)
    throw InputError(scene.where("samples"), std::to_string(samples) + ": must lie in " +
                                                 std::to_string(harmonics.minimumSamples()) + ".." +
                                                 std::to_string(kMaxSamples) + " time samples per period (2 H + 1 "
                                                 "resolve harmonic H = " + std::to_string(harmonics.maxHarmonic()) +
                                                 "; every residual costs in proportion; the default here is " +
                                                 std::to_string(recommended) + ")");
  // Before the system: its transform alone held 4.8 GB for harmonics [5000] on one DOF
  // before the same cost check refused it (issue 49 probe).
  {
    std::vector<int> dimensions;
    for (const auto& p : placed) dimensions.push_back(p.element->dimension());
    std::ostringstream what;
    what << harmonics.size() << " harmonics (up to " << harmonics.maxHarmonic() << ") on " << in.n << " DOFs make "
         << in.n * harmonics.numCoefficients() << " unknowns";
    response::checkElementJacobianCost(samples, harmonics.numCoefficients(), dimensions, what.str(),
                                       scene.where("harmonics"));
    // Far above the default (what the harmonics and the elements need): said with its cost.
    response::checkSamplesCost(samples, recommended,
                               "that harmonics up to " + std::to_string(harmonics.maxHarmonic()) +
                                   " and these elements need (the default here)",
                               harmonics, dimensions, scene.where("samples"));
  }
  setup.dofNames = in.dofNames;
  for (int d = int(setup.dofNames.size()); d < in.n; ++d) setup.dofNames.push_back("dof" + std::to_string(d));
  setup.system = std::make_unique<hbm::HarmonicBalanceSystem>(in.M, in.C, in.K, harmonics, samples);
  auto& hb = *setup.system;
  auto ex = scene.section("excitation");
  if (ex.sectionNames().empty())
    throw InputError(ex.location(), "needs at least one named force, e.g. f: {dof: 0, cos: 1.0}");
  readEngineOrder(ex, in);
  if (in.cyclic()) {
    hb.setCyclic(in.coupling);
    // An engine order outside 0..N/2 excites the nodal diameter it folds to (issue 20:
    // 100 on 24 sectors was accepted without a word; the disc scenes say it).
    const int N = in.coupling.sectors, eo = in.coupling.engineOrder;
    if (eo < 0 || eo > N / 2) {
      std::ostringstream msg;
      msg << "engine order " << eo << " on " << N << " sectors excites nodal diameter " << hb.nodalDiameter(1)
          << " (the engine order folds: " << eo << " mod " << N << " = " << ((eo % N) + N) % N
          << ", and k and N - k are the same nodal diameter travelling the other way)";
      setup.notes.push_back(msg.str());
    }
  }
  for (auto& p : placed) hb.addElement(p.element, p.W, p.Wnext);
  readForces(scene, ex, setup);
  auto cs = scene.section("continuation");
  readContinuation(cs, setup);
  if (harmonicsTarget.tolerance > 0 && setup.parameter != ForcedResponseSetup::Parameter::Omega)
    throw InputError(scene.where("harmonics"), "auto compares the peaks of frequency curves: it needs the "
                                               "continuation parameter omega");
  auto out = scene.section("output");
  setup.outputDofs = out.getIntList("dofs", {0});
  // None left a curve of frequencies alone, its samples and harmonics checks skipped
  // without a word, exit 0 (a fifth probe).
  if (setup.outputDofs.empty())
    throw InputError(out.where("dofs"), "is empty: the curve's response, its peak and its samples and harmonics "
                                        "checks are those of these DOFs (give at least one)");
  setup.stability = readStability(out);
  setup.harmonicsCheckTo = readHarmonicsCheckTo(out, harmonics.maxHarmonic(), harmonicsTarget);
  setup.harmonicsCheckKey =
      harmonicsTarget.tolerance > 0 ? scene.where("harmonics_max") : out.where("harmonics_check_to");
  setup.harmonicsTolerance = harmonicsTarget.tolerance;
  out.rejectUnknownKeys();
  for (int d : setup.outputDofs)
    if (d < 0 || d >= in.n) throw InputError(out.where("dofs"), "DOF " + std::to_string(d) + " out of range");
  return setup;
}

ForcedResponseSetup loadForcedResponseScene(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path, "cannot open the scene file");
  std::stringstream text;
  text << in.rdbuf();
  const auto root = parseSceneYaml(text.str(), path);
  const Teuchos::ParameterList& top = root->isSublist("cyclone") ? root->sublist("cyclone") : *root;
  SceneSection scene(top, path, "cyclone");
  return readForcedResponseSetup(scene);
}

}  // namespace cyclone::scenes
