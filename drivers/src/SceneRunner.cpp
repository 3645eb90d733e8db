#include "cyclone/scenes/SceneRunner.hpp"

#include <Teuchos_Comm.hpp>
#include <Teuchos_CommHelpers.hpp>

#include <optional>
#include <Teuchos_YamlParameterListCoreHelpers.hpp>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "DemoScene.hpp"
#include "cyclone/analysis/StaticAnalysis.hpp"
#include "cyclone/cyclic/CyclicModalAnalysis.hpp"
#include "cyclone/cyclic/CyclicTransform.hpp"
#include "cyclone/cyclic/ModalSweep.hpp"
#include "cyclone/continuation/ArclengthContinuation.hpp"
#include "cyclone/continuation/NewtonSolve.hpp"
#include "cyclone/core/AtomicFile.hpp"
#include "cyclone/core/PeakMemory.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/hbm/BifurcationFlags.hpp"
#include "cyclone/hbm/CubicSpring.hpp"
#include "cyclone/hbm/FrictionContact.hpp"
#include "cyclone/hbm/ScalarElementAdapter.hpp"
#include "cyclone/hbm/HarmonicBalanceSystem.hpp"
#include "cyclone/hbm/HarmonicRefinement.hpp"
#include "cyclone/hbm/HillStability.hpp"
#include "cyclone/hbm/PeakMagnitude.hpp"
#include "cyclone/hbm/JenkinsElement.hpp"
#include "cyclone/hbm/QuadraticDamper.hpp"
#include "cyclone/hbm/UnilateralSpring.hpp"
#include "cyclone/post/CampbellDiagram.hpp"
#include "cyclone/io/ResponseCurveFile.hpp"
#include "cyclone/io/ResultCheckpointDirectory.hpp"
#include "cyclone/io/TraceCheckpointDirectory.hpp"
#include "cyclone/post/SvgPlot.hpp"
#include "cyclone/post/Mac.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/mesh/AbaqusIO.hpp"
#include "cyclone/mesh/ExodusIO.hpp"
#include "cyclone/mesh/MeshReader.hpp"
#include "cyclone/mesh/ShroudedSectorGenerator.hpp"
#include "cyclone/scenes/ForcedResponseScene.hpp"
#include "cyclone/scenes/SceneSection.hpp"
#include "RunManifest.hpp"
#include "SceneStages.hpp"
#include "cyclone/solvers/ModalSolver.hpp"

namespace cyclone::scenes {

const char* demoScene() { return demoSceneYaml(); }

mesh::RotationAxis readRotationAxis(SceneSection& section) {
  const auto p = section.getVector3("axis_point", {0, 0, 0}), d = section.getVector3("axis_direction", {0, 0, 1});
  mesh::RotationAxis axis{Eigen::Vector3d(p[0], p[1], p[2]), Eigen::Vector3d(d[0], d[1], d[2])};
  if (!(axis.direction.norm() > 0)) throw InputError(section.where("axis_direction"), "must not be zero");
  return axis;
}

cyclic::PrestressKind readPrestressKind(SceneSection& section, const std::string& fallback) {
  const std::string value = section.getString("prestress", fallback);
  if (value == "linear") return cyclic::PrestressKind::Linear;
  if (value == "nonlinear") return cyclic::PrestressKind::Nonlinear;
  if (value == "none") return cyclic::PrestressKind::None;
  throw InputError(section.where("prestress"), "unknown prestress '" + value + "' (use linear, nonlinear or none)");
}

std::vector<int> readHarmonicList(SceneSection& section, int defaultMax) {
  std::vector<int> list = section.getIntList("harmonics", {defaultMax});
  if (list.size() == 1) {  // a single number H means 0..H
    const int H = list[0];
    if (H < 1) throw InputError(section.where("harmonics"), "needs at least harmonic 1 (a single number H means 0..H)");
    list.clear();
    for (int h = 0; h <= H; ++h) list.push_back(h);
  }
  return list;
}

response::ForcedResponseSetup::Stability readStability(SceneSection& section) {
  using Stability = response::ForcedResponseSetup::Stability;
  const std::string value = section.getString("stability", "auto");
  if (value == "auto") return Stability::Auto;
  if (value == "true") return Stability::Always;
  if (value == "false") return Stability::Never;
  throw InputError(section.where("stability"), "must be auto, true or false");
}

int readHarmonicsCheckTo(SceneSection& section, int maxHarmonic) {
  const int upTo = section.getInt("harmonics_check_to", 0);
  if (section.has("harmonics_check_to") && upTo <= maxHarmonic)
    throw InputError(section.where("harmonics_check_to"),
                     "must exceed the curve's highest harmonic " + std::to_string(maxHarmonic) + ", got " +
                         std::to_string(upTo) + " (the check raises H from there)");
  return upTo;
}

std::vector<std::string> CyclicFaces::left() const {
  auto faces = discLeft;
  if (shroudCyclic) faces.insert(faces.end(), shroudLeft.begin(), shroudLeft.end());
  return faces;
}

std::vector<std::string> CyclicFaces::right() const {
  auto faces = discRight;
  if (shroudCyclic) faces.insert(faces.end(), shroudRight.begin(), shroudRight.end());
  return faces;
}

CyclicFaces readCyclicFaces(SceneSection& cy) {
  CyclicFaces f;
  const std::string configuration = cy.getString("configuration", "fixed_shroud");
  if (configuration != "fixed_shroud" && configuration != "cantilever")
    throw InputError(cy.where("configuration"), "unknown configuration '" + configuration +
                                                    "' (fixed_shroud: disc and shroud faces cyclic; cantilever: disc "
                                                    "faces only)");
  f.shroudCyclic = configuration == "fixed_shroud";
  f.discLeft = cy.getStringList("disc_left_node_sets", f.discLeft);
  f.discRight = cy.getStringList("disc_right_node_sets", f.discRight);
  f.shroudLeft = cy.getStringList("shroud_left_node_sets", f.shroudLeft);
  f.shroudRight = cy.getStringList("shroud_right_node_sets", f.shroudRight);
  if (f.discLeft.empty() || f.discLeft.size() != f.discRight.size())
    throw InputError(cy.where("disc_right_node_sets"), "the disc's left and right side faces need as many sets each "
                                                       "(at least one): right = left rotated by +360/N degrees");
  if (f.shroudLeft.size() != f.shroudRight.size())
    throw InputError(cy.where("shroud_right_node_sets"), "the shroud's left and right side faces need as many sets each");
  return f;
}

fe::IsotropicElastic readMaterial(SceneSection m) {
  fe::IsotropicElastic material;
  material.name = m.getString("name", material.name);
  material.E = m.getDouble("E", material.E);
  material.nu = m.getDouble("nu", material.nu);
  material.rho = m.getDouble("rho", material.rho);
  if (m.has("fatigue")) m.section("fatigue");  // read where a margin is asked for (readFatigueMaterial)
  m.rejectUnknownKeys();
  material.validate(m.location());
  return material;
}

namespace {

// "peak memory after <stage>: ..." for the log: rank 0's high-water mark, and the sum
// over the ranks when there are several (what the machine must hold).
void logPeakMemory(const std::string& stage, const linalg::CommPtr& comm) {
  const double mine = peakMemoryMb();
  double total = mine;
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, 1, &mine, &total);
  std::ostringstream msg;
  msg.precision(4);
  msg << "peak memory after " << stage << ": " << mine << " MB";
  if (comm->getSize() > 1) msg << " on rank 0, " << total << " MB summed over " << comm->getSize() << " ranks";
  log::info(msg.str());
}

mesh::ShroudedSectorParameters readSectorParameters(SceneSection s) {
  mesh::ShroudedSectorParameters p;
  p.sectors = s.getInt("sectors", p.sectors);
  p.boreRadius = s.getDouble("bore_radius", p.boreRadius);
  p.rimRadius = s.getDouble("rim_radius", p.rimRadius);
  p.discThickness = s.getDouble("disc_thickness", p.discThickness);
  p.bladeHeight = s.getDouble("blade_height", p.bladeHeight);
  p.bladeChord = s.getDouble("blade_chord", p.bladeChord);
  p.bladeThickness = s.getDouble("blade_thickness", p.bladeThickness);
  p.bladeStaggerDeg = s.getDouble("blade_stagger_deg", p.bladeStaggerDeg);
  p.shroudThickness = s.getDouble("shroud_thickness", p.shroudThickness);
  p.shroudWidth = s.getDouble("shroud_width", p.shroudWidth);
  p.meshSize = s.getDouble("mesh_size", p.meshSize);
  p.elementOrder = s.getInt("element_order", p.elementOrder);
  s.rejectUnknownKeys();
  p.validate(s.location());
  return p;
}

// The mesh stage: built-in generator or a file; optional copies in Exodus and .inp.
mesh::Mesh meshStage(SceneSection s, const SceneOverrides& overrides, const std::string& sceneDir,
                     const std::string& outDir, const linalg::Comm& comm, SceneSummary& summary,
                     int& builtInSectors) {
  builtInSectors = 0;
  const bool writer = comm.getRank() == 0;
  const std::string source = s.getString("source", "shrouded_sector");
  const auto write = s.getStringList("write", {});
  SceneSection sector = s.section("shrouded_sector");
  mesh::Mesh mesh;
  if (source == "shrouded_sector") {
    auto p = readSectorParameters(sector);
    if (overrides.meshSize) p.meshSize = *overrides.meshSize;
    mesh = mesh::generateShroudedSector(p);
    builtInSectors = p.sectors;
  } else {
    // The built-in sector's keys do not apply to a mesh read from a file: say so, not
    // "unknown key (known here: )" (issue 20).
    if (s.has("shrouded_sector"))
      throw InputError(s.where("shrouded_sector"), "applies to source: shrouded_sector only; the mesh is read from '" +
                                                       source + "' (remove the block, or the source key)");
    const std::filesystem::path path = std::filesystem::path(source).is_absolute()
                                           ? std::filesystem::path(source)
                                           : std::filesystem::path(sceneDir) / source;
    log::info("reading mesh " + path.string());
    mesh = mesh::readMesh(path.string());
  }
  s.rejectUnknownKeys();
  std::ostringstream line;
  line << "mesh: " << mesh.numNodes() << " nodes, " << mesh.numElements() << " elements (" << mesh.source << ")";
  summary.computed.push_back(line.str());
  for (const auto& format : write) {
    if (format == "exodus") {
      const std::string path = outDir + "/mesh.exo";
      if (writer) mesh::writeExodus(path, mesh);
      summary.written.push_back(path);
    } else if (format == "inp") {
      const std::string path = outDir + "/mesh.inp";
      if (writer) mesh::writeAbaqusInp(path, mesh);
      summary.written.push_back(path);
    } else {
      throw InputError(s.where("write"), "unknown mesh format '" + format + "' (use exodus, inp)");
    }
  }
  return mesh;
}


std::string rpmTag(double rpm) {
  std::ostringstream s;
  s << rpm << "rpm";
  return s.str();
}

// The summary's line for one speed's modes, with the rigid-body modes counted (those
// below 1e-4 of the highest frequency computed for their ND).
std::string speedModesLine(const cyclic::SpeedModes& sm) {
  std::ostringstream line;
  line << "modes at " << sm.rpm << " rpm: ND " << sm.nodalDiameters.front().nodalDiameter << ".." << sm.nodalDiameters.back().nodalDiameter
       << ", lowest " << sm.nodalDiameters.front().frequenciesHz.front() << " Hz (ND " << sm.nodalDiameters.front().nodalDiameter << ")";
  std::string rigid;
  for (const auto& hm : sm.nodalDiameters) {
    int count = 0;
    for (double f : hm.frequenciesHz) count += f < 1e-4 * hm.frequenciesHz.back();
    if (count) rigid += (rigid.empty() ? "" : ", ") + std::string("ND ") + std::to_string(hm.nodalDiameter) + ": " +
                        std::to_string(count);
  }
  if (!rigid.empty()) line << "; rigid-body modes " << rigid;
  return line.str();
}

// The modal section read onto a sweep over speeds (keys checked before any work), and
// whether the MAC between the lowest and highest speed is asked for.
cyclic::ModalSweepProblem readModalSweep(SceneSection& m, const mesh::Mesh& mesh, int sectors,
                                         const fe::IsotropicElastic& material,
                                         const std::vector<std::string>& fixedSets, const std::string& outDir,
                                         bool& writeMac) {
  cyclic::ModalSweepProblem sweep;
  auto& problem = sweep.modes;
  problem.material = material;
  problem.fixedNodeSets = fixedSets;
  problem.nodalDiameters = m.getIntList("nodal_diameters", {});
  problem.modesPerNodalDiameter = m.getInt("modes_per_nd", 6);
  const std::string eigenSolver = m.getString("eigen_solver", "shift_invert");
  if (eigenSolver == "lobpcg") problem.method = solvers::EigenMethod::Lobpcg;
  else if (eigenSolver != "shift_invert")
    throw InputError(m.where("eigen_solver"), "unknown eigen solver '" + eigenSolver +
                                                  "' (use shift_invert: CHOLMOD factorization; or lobpcg: LOBPCG + "
                                                  "MueLu, no factorization, for meshes too big to factor)");
  if (problem.method == solvers::EigenMethod::Lobpcg) {
    if (m.has("shift"))
      throw InputError(m.where("shift"), "applies to eigen_solver shift_invert only (lobpcg takes no shift)");
    if (fixedSets.empty())
      throw InputError(m.where("eigen_solver"), "lobpcg needs a constrained model (constraints/fixed_node_sets): "
                                                "rigid-body modes need shift_invert");
  }
  // Without a shift the solver picks one (0 when K factors; below the first elastic
  // eigenvalue when rigid-body modes exist).
  problem.shift = m.has("shift") ? m.getDouble("shift", 0.0) : solvers::ModalOptions::automaticShift();
  // Each nodal diameter's modes are kept as solved: a killed sweep resumed with --resume
  // reads them back (the directory is emptied at the start of any other run).
  problem.checkpoints = std::make_shared<io::ResultCheckpointDirectory>(outDir + "/checkpoints");
  const auto speeds = m.getDoubleList("speeds_rpm", {0.0});
  const auto prestress = readPrestressKind(m, "linear");
  const std::string macChoice = m.getString("mac", "none");
  if (macChoice != "speeds" && macChoice != "none")
    throw InputError(m.where("mac"), "use 'speeds' (MAC of each ND's modes, lowest against highest speed) or 'none'");
  writeMac = macChoice == "speeds";
  m.rejectUnknownKeys();
  for (int k : problem.nodalDiameters)
    if (k < 0 || k > sectors / 2)
      throw InputError(m.where("nodal_diameters"), "nodal diameter " + std::to_string(k) + " is outside 0.." +
                                                        std::to_string(sectors / 2) + " for " +
                                                        std::to_string(sectors) + " sectors");
  for (std::size_t i = 0; i < problem.nodalDiameters.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (problem.nodalDiameters[i] == problem.nodalDiameters[j])
        throw InputError(m.where("nodal_diameters"),
                         "nodal diameter " + std::to_string(problem.nodalDiameters[i]) + " is listed twice");
  if (problem.modesPerNodalDiameter < 1) throw InputError(m.where("modes_per_nd"), "must be at least 1");
  // The eigen-solver's Krylov space, about 3 modes_per_nd vectors, must fit in the
  // sector's 3 x nodes DOFs (100000 reached Anasazi and came back as its internal
  // text: issue 20).
  if (const long nodes = long(mesh.numNodes()); problem.modesPerNodalDiameter > nodes / 2)
    throw InputError(m.where("modes_per_nd"), std::to_string(problem.modesPerNodalDiameter) +
                                                  " is more than half the sector's " + std::to_string(nodes) +
                                                  " nodes: the eigen-solver's space of about 3 x modes_per_nd "
                                                  "vectors must fit in its 3 x nodes DOFs");
  for (std::size_t i = 0; i < speeds.size(); ++i) {
    if (!(speeds[i] >= 0)) throw InputError(m.where("speeds_rpm"), "speeds must be non-negative");
    if (i > 0 && !(speeds[i] > speeds[i - 1])) throw InputError(m.where("speeds_rpm"), "speeds must increase");
  }
  if (speeds.empty()) throw InputError(m.where("speeds_rpm"), "needs at least one speed");
  sweep.speedsRpm = speeds;
  sweep.prestress = prestress;
  return sweep;
}

// MAC of each nodal diameter's families, lowest against highest speed: how much the
// prestress changed the mode shapes (diagonal near 1: same shapes, shifted frequencies).
void writeSpeedMac(const std::vector<cyclic::SpeedModes>& results, const std::string& outDir, bool writer,
                   SceneSummary& summary) {
  for (std::size_t h = 0; h < results.front().nodalDiameters.size(); ++h) {
    const auto& a = results.front().nodalDiameters[h];
    const auto mac = post::familyMac(a, results.back().nodalDiameters[h]);
    const std::string base = outDir + "/mac_nd" + std::to_string(a.nodalDiameter);
    if (writer) {
      post::writeMacCsv(base + ".csv", mac);
      post::writeMacSvg(base + ".svg", mac,
                        "MAC ND " + std::to_string(a.nodalDiameter) + ": " + rpmTag(results.front().rpm) + " (rows) vs " +
                            rpmTag(results.back().rpm) + " (columns)");
    }
    summary.written.push_back(base + ".csv");
    summary.written.push_back(base + ".svg");
  }
}

// Diagrams: SAFE at any speed set; Campbell and resonances need a speed range.
void writeDiagrams(const std::vector<cyclic::SpeedModes>& results, int sectors, const std::vector<int>& engineOrders,
                   const std::string& outDir, bool writer, SceneSummary& summary) {
  const auto branches = post::trackFamilies(results);
  const auto resonances = results.size() > 1 ? post::findResonances(branches, sectors, engineOrders)
                                            : std::vector<post::Resonance>{};
  if (writer) post::writeSafeSvg(outDir + "/safe.svg", branches, sectors, engineOrders, resonances);
  summary.written.push_back(outDir + "/safe.svg");
  if (results.size() > 1) {
    if (writer) {
      post::writeCampbellSvg(outDir + "/campbell.svg", branches, engineOrders, resonances);
      post::writeCampbellCsv(outDir + "/campbell.csv", branches);
      post::writeResonancesCsv(outDir + "/resonances.csv", resonances);
    }
    for (const char* f : {"/campbell.svg", "/campbell.csv", "/resonances.csv"}) summary.written.push_back(outDir + f);
    std::ostringstream line;
    line << "diagrams: " << branches.size() << " branches tracked by MAC, " << resonances.size()
         << " resonances in " << results.front().rpm << ".." << results.back().rpm << " rpm";
    for (std::size_t i = 0; i < resonances.size() && i < 3; ++i)
      line << (i ? "; " : ": ") << "EO " << resonances[i].engineOrder << " ND " << resonances[i].nd << " family "
           << resonances[i].family << " at " << std::round(resonances[i].rpm) << " rpm, "
           << std::round(resonances[i].freqHz) << " Hz";
    summary.computed.push_back(line.str());
  } else {
    log::info("one speed: SAFE diagram only (a Campbell diagram and resonances need speeds_rpm with 2 or more values)");
  }
}

// Cyclic modal analysis: per speed, optional prestress (k = 0), then modes for the
// requested nodal diameters; frequencies.csv, modes and prestress in Exodus, MAC,
// Campbell and SAFE diagrams.
void modalStage(SceneSection& scene, const mesh::Mesh& mesh, int builtInSectors, const std::string& outDir,
                linalg::CommPtr comm, SceneSummary& summary) {
  const auto material = readMaterial(scene.section("material"));
  auto c = scene.section("constraints");
  const auto fixedSets = c.getStringList("fixed_node_sets", {});
  c.rejectUnknownKeys();
  for (const auto& name : fixedSets) mesh.nodeSet(name);

  auto cy = scene.section("cyclic");
  const int sectors = cy.getInt("sectors", builtInSectors);
  if (sectors == 0) throw InputError(cy.where("sectors"), "is required for a mesh read from a file");
  const auto faces = readCyclicFaces(cy);
  const auto left = faces.left(), right = faces.right();
  const mesh::RotationAxis axis = readRotationAxis(cy);
  cy.rejectUnknownKeys();
  const auto sector = cyclic::makeCyclicSector(mesh, sectors, axis, left, right);
  {
    std::ostringstream msg;
    msg << "cyclic sector: " << sectors << " sectors, " << sector.left.size() << " paired side-face nodes (max mismatch "
        << sector.maxMismatch << ")";
    log::info(msg.str());
  }

  auto m = scene.section("modal");
  bool writeMac = false;
  auto sweep = readModalSweep(m, mesh, sectors, material, fixedSets, outDir, writeMac);
  sweep.axis = axis;
  auto dg = scene.section("diagrams");
  std::vector<int> defaultOrders;
  for (int eo = 1; eo <= sectors; ++eo) defaultOrders.push_back(eo);
  const auto engineOrders = dg.getIntList("engine_orders", defaultOrders);
  for (int eo : engineOrders)
    if (eo < 1) throw InputError(dg.where("engine_orders"), "engine orders must be positive, got " + std::to_string(eo));
  dg.rejectUnknownKeys();
  if (fixedSets.empty())
    log::warn("modal analysis without fixed node sets: rigid-body modes are expected (zero frequencies)");

  const bool writer = comm->getRank() == 0;
  logPeakMemory("the mesh", comm);
  // Each speed's prestress and modes written as the sweep goes (the prestress is not kept).
  const auto writeSpeed = [&](const cyclic::PrestressState* state, const cyclic::SpeedModes& sm) {
    const double rpm = sm.rpm;
    if (state) {
      const std::string path = outDir + "/prestress_" + rpmTag(rpm) + ".exo";
      if (writer) cyclic::writePrestressExodus(path, mesh, *state);
      summary.written.push_back(path);
    }
    const std::string path = outDir + "/modes_" + rpmTag(rpm) + ".exo";
    if (writer) cyclic::writeModesExodus(path, mesh, rpm, sm.nodalDiameters);
    summary.written.push_back(path);
    logPeakMemory("the prestress and modes at " + rpmTag(rpm), comm);
    summary.computed.push_back(speedModesLine(sm));
  };
  const auto results = cyclic::solveModalSweep(mesh, sector, sweep, comm, writeSpeed);
  const std::string csv = outDir + "/frequencies.csv";
  if (writer) cyclic::writeFrequenciesCsv(csv, results);
  summary.written.push_back(csv);

  if (writeMac && results.size() > 1) writeSpeedMac(results, outDir, writer, summary);
  writeDiagrams(results, sectors, engineOrders, outDir, writer, summary);
}

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
  if (int(v.size()) != n * n)
    throw InputError(s.where(key), "needs " + std::to_string(n * n) + " numbers (row by row for " +
                                       std::to_string(n) + " DOFs), got " + std::to_string(v.size()));
  Eigen::MatrixXd A(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) A(i, j) = v[i * n + j];
  return A;
}

// Forced response of a matrix-defined system with nonlinear elements: harmonic
// balance (AFT) traced by LOCA arclength continuation in the excitation frequency.
}  // namespace

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
    const double zeta = sys.getDouble("modal_damping_ratio", 0.0);
    if (!(zeta >= 0)) throw InputError(sys.where("modal_damping_ratio"), "must be >= 0");
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> modes(K, M);
    if (modes.info() != Eigen::Success || modes.eigenvalues().minCoeff() < 0)
      throw InputError(sys.where("modal_damping_ratio"), "needs K positive semi-definite and M positive definite");
    const Eigen::MatrixXd MPhi = M * modes.eigenvectors();
    const Eigen::VectorXd c = 2 * zeta * modes.eigenvalues().cwiseMax(0).cwiseSqrt();
    C += MPhi * c.asDiagonal() * MPhi.transpose();
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

std::shared_ptr<const hbm::NonlinearElement> readElementLaw(SceneSection& e) {
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
    try {
      return std::make_shared<hbm::FrictionContact>(p);
    } catch (const InputError& err) {
      throw InputError(e.location(), err.what());
    }
  }
  throw InputError(e.where("type"), "unknown element type '" + type +
                                        "' (cubic, unilateral, quadratic_damper, jenkins, friction2d, friction3d)");
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
    hb.addExcitation(f.getInt("dof", 0), f.getInt("harmonic", 1), c, sn);
    f.rejectUnknownKeys();
  }
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
  opt.tolerance = cs.getDouble("tolerance", opt.tolerance);
  if (!(opt.tolerance > 0 && opt.tolerance < 1))
    throw InputError(cs.where("tolerance"), "must lie in (0, 1): the residual relative to the forces acting");
  cs.rejectUnknownKeys();
  if (setup.parameter == ForcedResponseSetup::Parameter::Omega && (!(opt.from > 0) || !(opt.to > 0)))
    throw InputError(cs.location(), "the frequency range must be positive");
}

}  // namespace

ForcedResponseSetup readForcedResponseSetup(SceneSection& scene) {
  MatrixSystemInput in = readMatrixSystem(scene);
  const hbm::HarmonicSet harmonics(readHarmonicList(scene, 7));
  // Elements first: the default sample count depends on them (friction and gaps need
  // many samples per period to place their events).
  ForcedResponseSetup setup;
  const auto placed = readNonlinearElements(scene, in, setup.elementNames);
  int recommended = std::max(64, 4 * harmonics.maxHarmonic() + 1);
  for (const auto& p : placed) recommended = std::max(recommended, p.element->recommendedSamples());
  const int samples = scene.getInt("samples", recommended);
  if (samples < 1 || samples > kMaxSamples)
    throw InputError(scene.where("samples"), std::to_string(samples) + ": must lie in 1.." +
                                                 std::to_string(kMaxSamples) + " time samples per period (every "
                                                 "residual costs in proportion; the default here is " +
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
  auto out = scene.section("output");
  setup.outputDofs = out.getIntList("dofs", {0});
  setup.stability = readStability(out);
  setup.harmonicsCheckTo = readHarmonicsCheckTo(out, harmonics.maxHarmonic());
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

namespace {

void forcedResponseStage(SceneSection& scene, const std::string& outDir,
                         const std::shared_ptr<continuation::TraceCheckpoints>& checkpoints, linalg::CommPtr comm,
                         SceneSummary& summary) {
  auto setup = readForcedResponseSetup(scene);
  setup.continuation.checkpoints = checkpoints;
  if (setup.fallback) setup.fallback->checkpoints = checkpoints;
  for (const auto& note : setup.notes) {
    log::info(note);
    summary.computed.push_back(note);
  }
  traceAndWriteForcedResponse(setup, outDir, "frc", comm, summary);
}

void staticStage(SceneSection& scene, const mesh::Mesh& mesh, const std::string& outDir, linalg::CommPtr comm,
                 SceneSummary& summary) {
  analysis::StaticProblem problem;
  problem.material = readMaterial(scene.section("material"));
  {
    auto c = scene.section("constraints");
    problem.fixedNodeSets = c.getStringList("fixed_node_sets", {});
    c.rejectUnknownKeys();
    for (const auto& name : problem.fixedNodeSets)
      if (!mesh.nodeSets.count(name)) mesh.nodeSet(name);  // throws naming the mesh and its sets
  }
  {
    auto l = scene.section("loads");
    problem.speedRpm = l.getDouble("speed_rpm", 0.0);
    problem.axis = readRotationAxis(l);
    const auto b = l.getVector3("body_force", {0, 0, 0});
    problem.bodyForce = Eigen::Vector3d(b[0], b[1], b[2]);
    auto forces = l.section("nodal_forces");
    for (const auto& name : forces.sectionNames()) {
      auto f = forces.section(name);
      analysis::NodalForce load;
      load.nodeSet = f.getString("node_set", "");
      const auto v = f.getVector3("force", {0, 0, 0});
      load.forcePerNode = Eigen::Vector3d(v[0], v[1], v[2]);
      f.rejectUnknownKeys();
      mesh.nodeSet(load.nodeSet);
      problem.nodalForces.push_back(load);
    }
    forces.rejectUnknownKeys();
    l.rejectUnknownKeys();
  }
  {
    auto s = scene.section("solver");
    problem.solver.kind = solvers::linearSolverKindFromName(s.getString("type", "direct"), s.where("type"));
    problem.solver.tolerance = s.getDouble("tolerance", problem.solver.tolerance);
    problem.solver.maxIterations = s.getInt("max_iterations", problem.solver.maxIterations);
    s.rejectUnknownKeys();
  }
  if (problem.fixedNodeSets.empty())
    throw InputError(scene.where("constraints/fixed_node_sets"),
                     "a static analysis needs fixed node sets (the model would move as a rigid body)");

  {
    std::ostringstream msg;
    msg << "linear static analysis at " << problem.speedRpm << " rpm";
    log::info(msg.str());
  }
  const auto result = analysis::solveStatic(mesh, problem, comm);
  const std::string path = outDir + "/static.exo";
  if (comm->getRank() == 0) analysis::writeStaticResult(path, mesh, result);
  std::ostringstream line;
  line << "static: " << result.equations << " equations, max |u| = " << result.maxDisplacement << " at node "
       << (result.maxDisplacementNode >= 0 ? mesh.nodeIds[result.maxDisplacementNode] : -1)
       << ", max von Mises = " << result.maxVonMises << ", residual " << result.solve.relativeResidual;
  summary.computed.push_back(line.str());
  summary.written.push_back(path);
}

}  // namespace

namespace {
void runStages(SceneSection& scene, const std::vector<std::string>& analyses, const SceneOverrides& overrides,
               const std::string& source, const std::string& sceneDir, const std::string& outDir,
               const std::shared_ptr<continuation::TraceCheckpoints>& checkpoints, linalg::CommPtr comm,
               SceneSummary& summary);
}  // namespace

namespace {

// The analyses a scene asks for; its top-level keys and (for anything with a mass
// matrix) its density checked before anything runs, so a typo costs no computation.
std::vector<std::string> readAnalyses(SceneSection& scene) {
  const auto analyses = scene.getStringList("analysis", {"static"});
  for (const auto& a : analyses)
    if (a != "static" && a != "mesh" && a != "modal" && a != "forced_response" && a != "reduced_model" &&
        a != "disc_response")
      throw InputError(scene.where("analysis"),
                       "unknown analysis '" + a +
                           "' (use static, modal, mesh, reduced_model, disc_response or forced_response, or a list)");
  auto wants = [&](const char* a) { return std::find(analyses.begin(), analyses.end(), a) != analyses.end(); };
  scene.rejectKeysOtherThan({"analysis", "output_directory", "mesh", "material", "constraints", "loads", "solver",
                             "cyclic", "modal", "diagrams", "system", "nonlinear_elements", "excitation", "harmonics",
                             "samples", "continuation", "output", "static_loads", "reduced_model",
                             "disc_response"});
  // A mass matrix needs a density: with rho = 0 the eigen-solver spun for minutes (issue 20).
  if (wants("modal") || wants("disc_response") || wants("reduced_model")) {
    auto m = scene.section("material");
    if (const auto material = readMaterial(m); !(material.rho > 0))
      throw InputError(m.where("rho"), "must be positive for modes, reduced models and forced responses (the mass "
                                       "matrix), got " + std::to_string(material.rho));
  }
  return analyses;
}

// The run's mark in the directory (rank 0), before anything is written: a second run
// into it is refused on every rank; a previous run that did not finish is said.
std::unique_ptr<RunManifest> claimOutputDirectory(const std::string& outDir, const std::string& source,
                                                linalg::CommPtr comm, SceneSummary& summary) {
  if (comm->getRank() == 0) std::filesystem::create_directories(outDir);
  std::unique_ptr<RunManifest> manifest;
  std::string refused, previousUnfinished;
  if (comm->getRank() == 0) {
    try {
      manifest = std::make_unique<RunManifest>(outDir, source, previousUnfinished);
    } catch (const InputError& e) {
      refused = e.what();
    }
  }
  int isRefused = refused.empty() ? 0 : 1;
  Teuchos::broadcast(*comm, 0, &isRefused);
  if (isRefused) throw InputError(outDir, comm->getRank() == 0 ? refused : "another run is writing into it");
  if (!previousUnfinished.empty()) {
    log::warn(previousUnfinished);
    summary.computed.push_back("warning: " + previousUnfinished);
  }
  return manifest;
}

// Curves save their traces in <out>/checkpoints as they go (rank 0 writes; the others,
// which trace the same curves, only read). --resume reads them: finished traces are read
// back, the one the kill interrupted continues; any other run starts without them.
std::shared_ptr<io::TraceCheckpointDirectory> openCheckpoints(const std::string& checkpointDir,
                                                              const SceneOverrides& overrides, linalg::CommPtr comm) {
  if (!(overrides.checkpointSeconds >= 0))
    throw InputError("--checkpoint-seconds", "must be zero or positive, got " + std::to_string(overrides.checkpointSeconds));
  if (comm->getRank() == 0) {
    if (!overrides.resume) {
      std::filesystem::remove_all(checkpointDir);
    } else if (!std::filesystem::exists(checkpointDir)) {
      log::warn("--resume: " + checkpointDir + " holds nothing to continue (the run before completed, or saved "
                "no curve): everything is computed");
    } else {
      log::info("--resume: traces saved in " + checkpointDir + " are read back or continued");
    }
  }
  Teuchos::barrier(*comm);
  auto checkpoints = std::make_shared<io::TraceCheckpointDirectory>(checkpointDir, comm->getRank() != 0);
  checkpoints->intervalSeconds = overrides.checkpointSeconds;
  return checkpoints;
}

}  // namespace

SceneSummary runSceneText(const std::string& yaml, const std::string& source, const SceneOverrides& overrides,
                          linalg::CommPtr comm) {
  const auto root = parseSceneYaml(yaml, source);
  const std::string sceneDir = std::filesystem::path(source).has_parent_path()
                                   ? std::filesystem::path(source).parent_path().string()
                                   : ".";
  // Teuchos names the root list after the single top-level key.
  if (root->name() != "cyclone" && !root->isSublist("cyclone"))
    throw InputError(source, "the scene's top-level key must be 'cyclone'");
  const Teuchos::ParameterList& top = root->isSublist("cyclone") ? root->sublist("cyclone") : *root;
  SceneSection scene(top, source, "cyclone");
  SceneSummary summary;
  const auto analyses = readAnalyses(scene);
  const std::string outDir = overrides.outputDirectory ? *overrides.outputDirectory
                                                       : scene.getString("output_directory", "cyclone_out");
  if (overrides.outputDirectory) scene.getString("output_directory", "");
  auto manifest = claimOutputDirectory(outDir, source, comm, summary);
  const std::string checkpointDir = outDir + "/checkpoints";
  const auto checkpoints = openCheckpoints(checkpointDir, overrides, comm);
  try {
    runStages(scene, analyses, overrides, source, sceneDir, outDir, checkpoints, comm, summary);
  } catch (const InputError& e) {
    // The library names the entry ("excitation: DOF 5 out of range"); the scene file is
    // added where the message does not start with it (issue 20).
    const std::string what = e.what();
    if (manifest) manifest->fail(what);
    if (what.rfind(source, 0) == 0) throw;
    throw InputError(source, what);
  } catch (const std::exception& e) {
    if (manifest) manifest->fail(e.what());
    throw;
  }
  if (manifest) manifest->complete(summary.written);
  if (comm->getRank() == 0) {
    std::error_code ignored;  // a leftover directory costs disk space, not the run
    std::filesystem::remove_all(checkpointDir, ignored);
  }
  return summary;
}

namespace {

void runStages(SceneSection& scene, const std::vector<std::string>& analyses, const SceneOverrides& overrides,
               const std::string& source, const std::string& sceneDir, const std::string& outDir,
               const std::shared_ptr<continuation::TraceCheckpoints>& checkpoints, linalg::CommPtr comm,
               SceneSummary& summary) {
  auto wants = [&](const char* a) { return std::find(analyses.begin(), analyses.end(), a) != analyses.end(); };
  if (wants("forced_response")) {
    // Matrix-defined systems need no mesh.
    Timer stage;
    forcedResponseStage(scene, outDir, checkpoints, comm, summary);
    summary.stages.push_back({"forced response", stage.seconds(), "see the samples check"});
    if (comm->getRank() == 0) writeRunReport(outDir, source, summary);
    summary.written.push_back(outDir + "/report.md");
    return;
  }
  int builtInSectors = 0;
  Timer stage;
  auto mesh = meshStage(scene.section("mesh"), overrides, sceneDir, outDir, *comm, summary, builtInSectors);
  // A node in no element has no stiffness: named here, not by the factorization's
  // "not positive definite" (issue 20). Writing the mesh alone does not need it.
  if (const auto orphans = mesh::orphanNodes(mesh);
      !orphans.empty() && (wants("static") || wants("modal") || wants("disc_response") || wants("reduced_model"))) {
    std::ostringstream ids;
    for (std::size_t i = 0; i < std::min<std::size_t>(orphans.size(), 5); ++i)
      ids << (i ? ", " : "") << mesh.nodeIds[std::size_t(orphans[i])];
    if (orphans.size() > 5) ids << ", ...";
    throw InputError(mesh.source, std::to_string(orphans.size()) + " node" + (orphans.size() > 1 ? "s" : "") +
                                      " in no element (id " + ids.str() +
                                      "): nothing holds them, so every solve would be singular; remove them");
  }
  summary.stages.push_back({"mesh", stage.seconds(), "element Jacobians checked positive at every integration point"});
  if (wants("static")) {
    stage.restart();
    staticStage(scene, mesh, outDir, comm, summary);
    summary.stages.push_back({"static (linear, centrifugal)", stage.seconds(), summary.computed.back()});
  }
  if (wants("modal")) {
    stage.restart();
    modalStage(scene, mesh, builtInSectors, outDir, comm, summary);
    summary.stages.push_back({"prestress and cyclic modes", stage.seconds(),
                              "every mode's backward error ||K x - l M x|| / ((||K||_F + |l| ||M||_F) ||x||) below 1e-6, its value from a Rayleigh-Ritz on the solver's vectors matching the solver's value"});
  }
  if (wants("disc_response") || wants("reduced_model"))
    discStages(scene, mesh, builtInSectors, wants("disc_response"), outDir, checkpoints, comm, summary);
  if (comm->getRank() == 0) writeRunReport(outDir, source, summary);
  summary.written.push_back(outDir + "/report.md");
}

}  // namespace

SceneSummary runSceneFile(const std::string& path, const SceneOverrides& overrides, linalg::CommPtr comm) {
  std::ifstream in(path);
  if (!in) throw InputError(path, "cannot open the scene file");
  std::stringstream text;
  text << in.rdbuf();
  return runSceneText(text.str(), path, overrides, comm);
}

}  // namespace cyclone::scenes
