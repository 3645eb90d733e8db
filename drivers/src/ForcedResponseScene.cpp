// A matrix-defined forced-response scene (analysis: forced_response) read into a
// response::ForcedResponseSetup: system matrices, nonlinear elements, engine order,
// forces and continuation keys.
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
#include "cyclone/hbm/ModalDamping.hpp"
#include "cyclone/hbm/QuadraticDamper.hpp"
#include "cyclone/hbm/ScalarElementAdapter.hpp"
#include "cyclone/hbm/UnilateralSpring.hpp"
#include "cyclone/scenes/ForcedResponseScene.hpp"
#include "cyclone/scenes/SceneSection.hpp"

namespace cyclone::scenes {

namespace {

Eigen::MatrixXd squareMatrix(SceneSection& s, const std::string& key, int n, bool required) {
  if (!s.has(key)) {
    if (required) throw InputError(s.where(key), "is required (" + std::to_string(n * n) + " numbers, row by row)");
    return Eigen::MatrixXd::Zero(n, n);
  }
  if (s.isSection(key)) {  // sparse: {rows: [...], cols: [...], values: [...]}, 0-based, duplicates summed
    auto t = s.section(key);
    const auto r = t.getIntList("rows", {}), c = t.getIntList("cols", {});
    const auto v = t.getDoubleList("values", {});
    t.rejectUnknownKeys();
    if (r.size() != v.size() || c.size() != v.size())
      throw InputError(t.location(), "rows, cols and values must have the same length");
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n);
    for (std::size_t k = 0; k < v.size(); ++k) {
      if (r[k] < 0 || r[k] >= n || c[k] < 0 || c[k] >= n)
        throw InputError(t.location(), "entry " + std::to_string(k) + " (" + std::to_string(r[k]) + ", " +
                                           std::to_string(c[k]) + ") is outside " + std::to_string(n) + " x " +
                                           std::to_string(n));
      A(r[k], c[k]) += v[k];
    }
    return A;
  }
  const auto v = s.getDoubleList(key, {});
  if ((long long)v.size() != (long long)n * n)  // 1e5 DOFs: n * n overflowed an int in the message
    throw InputError(s.where(key), "needs " + std::to_string((long long)n * n) + " numbers (row by row for " +
                                       std::to_string(n) + " DOFs), got " + std::to_string(v.size()));
  Eigen::MatrixXd A(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) A(i, j) = v[i * n + j];
  return A;
}


// Forced response of a matrix-defined system with nonlinear elements: harmonic
// balance (AFT) traced by arclength continuation in the excitation frequency.
}  // namespace

double readContinuationTolerance(SceneSection& cs, double defaultValue) {
  const double tolerance = cs.getDouble("tolerance", defaultValue);
  if (!(tolerance >= 1e-14 && tolerance <= 1e-4))
    throw InputError(cs.where("tolerance"), numberText(tolerance) +
                                                ": must lie in 1e-14..1e-4, the residual relative to the forces acting "
                                                "(below: under the rounding of double precision; above: a response "
                                                "near a resonance, amplified by its quality factor, off by percents)");
  return tolerance;
}

void readContinuationSteps(SceneSection& cs, continuation::ContinuationOptions& opt, const std::string& defaultEngine) {
  using Options = continuation::ContinuationOptions;
  const std::string engine = cs.getString("engine", defaultEngine);
  if (engine == "predictor_corrector")
    opt.engine = Options::Engine::PredictorCorrector;
  else if (engine == "loca" && opt.engine != Options::Engine::Loca) {
    const Options loca = continuation::locaOptions();  // LOCA's step defaults, its units
    opt.engine = loca.engine;
    opt.initialStep = loca.initialStep, opt.minStep = loca.minStep, opt.maxStep = loca.maxStep;
  } else if (engine == "loca")
    opt.engine = Options::Engine::Loca;
  else
    throw InputError(cs.where("engine"), "'" + engine + "': must be predictor_corrector or loca");
  opt.initialStep = cs.getDouble("initial_step", opt.initialStep);  // the caller's defaults
  opt.minStep = cs.getDouble("min_step", opt.minStep);
  opt.maxStep = cs.getDouble("max_step", opt.maxStep);
  opt.maxSteps = cs.getInt("max_points", opt.maxSteps);
  opt.turnAngle = cs.getDouble("turn_angle", opt.turnAngle);
  if (!(opt.initialStep > 0)) throw InputError(cs.where("initial_step"), "must be positive");
  if (!(opt.minStep > 0)) throw InputError(cs.where("min_step"), "must be positive");
  if (!(opt.maxStep >= opt.minStep)) throw InputError(cs.where("max_step"), "must be at least min_step");
  // The predictor-corrector's steps are in the scaled space (x / |x|, p / |to - from|),
  // where 1 spans the whole range: a longer step means nothing (issue 49: 1000).
  if (opt.engine == Options::Engine::PredictorCorrector)
    for (const auto& [key, value] : {std::pair<const char*, double>{"initial_step", opt.initialStep},
                                     {"max_step", opt.maxStep}})
      if (value > 1)
        throw InputError(cs.where(key), std::to_string(value) + ": must be at most 1 (the steps are in the scaled "
                                        "space x / |x|, p / |to - from|, where 1 spans the whole range)");
  if (opt.maxSteps < 2) throw InputError(cs.where("max_points"), "must be at least 2");
  if (!(opt.turnAngle > 0 && opt.turnAngle < 1.5))
    throw InputError(cs.where("turn_angle"), "must lie in (0, 1.5) radians");
  using LS = Options::LineSearch;
  const std::string name = cs.getString("line_search", "full_step");
  if (name == "full_step")
    opt.lineSearch = LS::FullStep;
  else if (name == "backtrack")
    opt.lineSearch = LS::Backtrack;
  else if (name == "polynomial")
    opt.lineSearch = LS::Polynomial;
  else
    throw InputError(cs.where("line_search"), "'" + name + "': must be full_step, backtrack or polynomial");
  if (cs.has("line_search") && opt.engine != Options::Engine::Loca)
    throw InputError(cs.where("line_search"), "is for engine: loca (the predictor-corrector backtracks by itself)");
}

namespace {

// A matrix scene's `system` section: M, C (with Rayleigh and modal damping), K, the DOF
// names and the next-sector coupling of a cyclic system, checked for physics.
struct MatrixSystemInput {
  int n = 0;
  Eigen::MatrixXd M, C, K;
  std::vector<std::string> dofNames;
  hbm::CyclicCoupling coupling;
  bool cyclic() const { return coupling.sectors > 1; }
};

MatrixSystemInput readMatrixSystem(SceneSection& scene) {
  MatrixSystemInput in;
  auto sys = scene.section("system");
  const int n = in.n = sys.getInt("dofs", 0);
  if (n < 1) throw InputError(sys.where("dofs"), "is required: the number of DOFs (>= 1)");
  in.M = squareMatrix(sys, "M", n, true), in.K = squareMatrix(sys, "K", n, true);
  in.C = squareMatrix(sys, "C", n, false);
  const auto &M = in.M, &K = in.K;
  auto& C = in.C;
  if ((M - M.transpose()).norm() > 1e-12 * M.norm() || (K - K.transpose()).norm() > 1e-12 * K.norm())
    throw InputError(sys.location(), "M and K must be symmetric");
  // Damping on top of C: Rayleigh a M + b K, or a modal damping ratio for every
  // mode of (K, M) (C = M Phi diag(2 zeta w_j) Phi^T M with M-normalised Phi).
  if (sys.has("rayleigh")) {
    const auto ab = sys.getDoubleList("rayleigh", {});
    if (ab.size() != 2) throw InputError(sys.where("rayleigh"), "needs two numbers [a, b]: C += a M + b K");
    C += ab[0] * M + ab[1] * K;
  }
  if (sys.has("modal_damping_ratio")) {
    try {
      C += hbm::modalDamping(M, K, sys.getDouble("modal_damping_ratio", 0.0));
    } catch (const InputError& e) {
      throw InputError(sys.where("modal_damping_ratio"), e.problem());
    }
  }
  in.dofNames = sys.getStringList("dof_names", {});
  if (!in.dofNames.empty() && int(in.dofNames.size()) != n)
    throw InputError(sys.where("dof_names"), "needs one name per DOF (" + std::to_string(n) + ")");
  auto& coupling = in.coupling;
  coupling.sectors = sys.getInt("sectors", 1);
  if (coupling.sectors < 1) throw InputError(sys.where("sectors"), "must be >= 1 (1: not cyclic)");
  const bool cyclic = coupling.sectors > 1;
  for (const char* key : {"K_next", "C_next", "M_next"})
    if (sys.has(key) && !cyclic)
      throw InputError(sys.where(key), "couples a sector to the next one: set sectors >= 2 for a cyclic system");
  coupling.Knext = squareMatrix(sys, "K_next", n, false);
  coupling.Cnext = squareMatrix(sys, "C_next", n, false);
  coupling.Mnext = squareMatrix(sys, "M_next", n, false);
  sys.rejectUnknownKeys();
  // No physical system has a mass matrix that is not positive definite, or damping
  // whose symmetric part (the part that dissipates) has a negative eigenvalue: such
  // input was accepted and traced (issue 20). A cyclic sector's own matrices are
  // checked only without next-sector coupling of the same kind (the ring's matrices
  // per nodal diameter are what must be definite then).
  if (coupling.Mnext.isZero(0) && Eigen::LLT<Eigen::MatrixXd>(M).info() != Eigen::Success)
    throw InputError(sys.where("M"), "must be positive definite (a mass matrix: every DOF carries mass)");
  if (coupling.Cnext.isZero(0) && C.size() > 0) {
    const Eigen::MatrixXd dissipative = 0.5 * (C + C.transpose());
    const double lowest = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(dissipative, Eigen::EigenvaluesOnly).eigenvalues().minCoeff();
    if (lowest < -1e-12 * dissipative.norm())
      throw InputError(sys.location(), "the damping (C with rayleigh and modal_damping_ratio) generates energy: its "
                                       "symmetric part has the eigenvalue " + std::to_string(lowest) + " < 0");
  }

  return in;
}

// A nonlinear element of `nonlinear_elements` and where it acts: w = W^T x (+ W_next^T
// x_next across the sector boundary).
struct PlacedElement {
  std::shared_ptr<const hbm::NonlinearElement> element;
  Eigen::MatrixXd W, Wnext;
};

std::shared_ptr<const hbm::NonlinearElement> elementLaw(SceneSection& e) {
  const std::string type = e.getString("type", "");
  auto scalar = [](std::shared_ptr<const hbm::ScalarElement> s) {
    return std::make_shared<hbm::ScalarElementAdapter>(std::move(s));
  };
  if (type == "cubic") return scalar(std::make_shared<hbm::CubicSpring>(e.requireDouble("k3")));
  if (type == "unilateral")
    return scalar(std::make_shared<hbm::UnilateralSpring>(e.requireDouble("k"), e.getDouble("gap", 0.0)));
  if (type == "quadratic_damper") return scalar(std::make_shared<hbm::QuadraticDamper>(e.requireDouble("c2")));
  if (type == "jenkins")
    return scalar(std::make_shared<hbm::JenkinsElement>(e.requireDouble("kt"), e.requireDouble("slip_force")));
  if (type == "friction2d" || type == "friction3d") {
    hbm::FrictionContactParameters p;
    p.tangentialDirections = type == "friction2d" ? 1 : 2;
    p.kt = e.requireDouble("kt");
    p.kn = e.getDouble("kn", 0.0);
    p.mu = e.requireDouble("mu");
    p.preload = e.getDouble("preload", 0.0);
    return std::make_shared<hbm::FrictionContact>(p);
  }
  throw InputError(e.where("type"), "unknown element type '" + type +
                                        "' (cubic, unilateral, quadratic_damper, jenkins, friction2d, friction3d)");
}

// The element's law, a law's own refusal ("UnilateralSpring: stiffness must be ...") put
// under the element's key in the scene (it named neither; issue 49 probe).
std::shared_ptr<const hbm::NonlinearElement> readElementLaw(SceneSection& e) {
  try {
    return elementLaw(e);
  } catch (const InputError& err) {
    if (err.where().rfind(e.location(), 0) == 0) throw;  // a key of the element, named already
    throw InputError(e.location(), err.what());
  }
}

std::vector<PlacedElement> readNonlinearElements(SceneSection& scene, const MatrixSystemInput& in,
                                                 std::vector<std::string>& names) {
  const int n = in.n;
  auto matrixOf = [&](SceneSection& e, const std::string& key, int d) {
    const auto v = e.getDoubleList(key, {});
    if (int(v.size()) != n * d)
      throw InputError(e.where(key), "needs " + std::to_string(n * d) + " numbers: " + std::to_string(d) +
                                         " direction vector(s) of " + std::to_string(n) +
                                         " DOFs one after another (element coordinates in order)");
    return Eigen::Map<const Eigen::MatrixXd>(v.data(), n, d).eval();
  };
  std::vector<PlacedElement> placed;
  auto elements = scene.section("nonlinear_elements");
  for (const auto& name : elements.sectionNames()) {
    auto e = elements.section(name);
    const std::string type = e.getString("type", "");
    PlacedElement pl{readElementLaw(e), {}, {}};
    const int d = pl.element->dimension();
    if (e.has("direction") && e.has("W"))
      throw InputError(e.location(), "give either direction (one coordinate) or W, not both");
    if (e.has("direction")) {
      if (d != 1) throw InputError(e.where("direction"), "is for one-coordinate elements; use W for " + type);
      pl.W = matrixOf(e, "direction", 1);
    } else if (e.has("W")) {
      pl.W = matrixOf(e, "W", d);
    } else {
      throw InputError(e.location(), "needs direction (n numbers) or W (" + std::to_string(d) + " x " +
                                         std::to_string(n) + " numbers): w = W^T x");
    }
    if (e.has("W_next")) {
      if (!in.cyclic()) throw InputError(e.where("W_next"), "joins a sector to the next one: the system must be cyclic");
      pl.Wnext = matrixOf(e, "W_next", d);
    }
    // Each element coordinate must see some motion (issue 49: direction [0] made an element
    // that never acts, and the curve was the linear one, exit 0). A coordinate across the
    // sector boundary may be W_next's alone.
    const char* key = e.has("direction") ? "direction" : "W";
    for (int j = 0; j < d; ++j)
      if (pl.W.col(j).norm() == 0 && (pl.Wnext.size() == 0 || pl.Wnext.col(j).norm() == 0))
        throw InputError(e.where(key), "coordinate " + std::to_string(j) + " of the element is zero on every DOF: "
                                       "the element would never act (give the DOFs it acts on)");
    e.rejectUnknownKeys();
    placed.push_back(std::move(pl));
    names.push_back(name);
  }
  elements.rejectUnknownKeys();
  return placed;
}

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
  readContinuationSteps(cs, opt, "predictor_corrector");
  opt.tolerance = readContinuationTolerance(cs, opt.tolerance);
  cs.rejectUnknownKeys();
  if (setup.parameter == ForcedResponseSetup::Parameter::Omega && (!(opt.from > 0) || !(opt.to > 0)))
    throw InputError(cs.location(), "the frequency range must be positive");
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
  int recommended = std::max(64, 4 * harmonics.maxHarmonic() + 1);
  for (const auto& p : placed)
    if (p.element->recommendedSamples() > 0)  // a nonsmooth law: samples that grow with the harmonics too
      recommended = std::max({recommended, p.element->recommendedSamples(), harmonics.nonsmoothSamples()});
  const int samples = scene.getInt("samples", recommended);
  if (samples < harmonics.minimumSamples() || samples > kMaxSamples)
    throw InputError(scene.where("samples"), std::to_string(samples) + ": must lie in " +
                                                 std::to_string(harmonics.minimumSamples()) + ".." +
                                                 std::to_string(kMaxSamples) + " time samples per period (2 H + 1 "
                                                 "resolve harmonic H = " + std::to_string(harmonics.maxHarmonic()) +
                                                 "; every residual costs in proportion; the default here is " +
                                                 std::to_string(recommended) + ")");
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
  setup.stability = readStability(out);
  setup.harmonicsCheckTo = readHarmonicsCheckTo(out, harmonics.maxHarmonic(), harmonicsTarget);
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
