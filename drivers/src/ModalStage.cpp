// The modal stage: prestress and cyclic modes at every speed (cyclic::solveModalSweep),
// their Exodus files, frequencies.csv, the speeds' MAC and the Campbell and SAFE diagrams.
#include <Teuchos_Comm.hpp>
#include <Teuchos_CommHelpers.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "SceneStages.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/core/PeakMemory.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/cyclic/CyclicModalAnalysis.hpp"
#include "cyclone/cyclic/CyclicTransform.hpp"
#include "cyclone/cyclic/ModalSweep.hpp"
#include "cyclone/io/ResultCheckpointDirectory.hpp"
#include "cyclone/mesh/ExodusIO.hpp"
#include "cyclone/post/CampbellDiagram.hpp"
#include "cyclone/post/Mac.hpp"
#include "cyclone/post/SvgPlot.hpp"
#include "cyclone/scenes/SceneSection.hpp"
#include "cyclone/solvers/ModalSolver.hpp"

namespace cyclone::scenes {

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

namespace {

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
    if (const int count = hm.rigidBodyModes()) rigid += (rigid.empty() ? "" : ", ") + std::string("ND ") + std::to_string(hm.nodalDiameter) + ": " +
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
  // Nodal diameters solved side by side (each thread its own factor): auto takes the
  // cores this process may use, shared among the ranks.
  problem.threads = 0;
  if (m.has("threads")) {
    bool isCount = true, isAuto = false;
    int count = 0;
    try {
      count = m.getInt("threads", 0);
    } catch (const InputError&) {
      isCount = false;
    }
    if (!isCount) try {
        isAuto = m.getString("threads", "") == "auto";
      } catch (const InputError&) {
      }
    if (!isAuto && !(isCount && count >= 1 && count <= 1024))
      throw InputError(m.where("threads"), (isCount ? std::to_string(count) + ": " : std::string()) +
                                               "use auto or a count of threads from 1 to 1024");
    if (isCount) problem.threads = count;
  }
  const auto speeds = m.getDoubleList("speeds_rpm", {0.0});
  const auto prestress = readPrestressKind(m, "linear");
  writeMac = m.getChoice<bool>("mac", "none", {{"speeds", true}, {"none", false}}, [](const std::string&) {
    return "use 'speeds' (MAC of each ND's modes, lowest against highest speed) or 'none'";
  });
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
}  // namespace

ModalPlan readModalPlan(SceneSection& scene, const mesh::Mesh& mesh, int builtInSectors, const std::string& outDir) {
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
  ModalPlan plan{sectors, cyclic::makeCyclicSector(mesh, sectors, axis, left, right), {}, {}, false};
  {
    std::ostringstream msg;
    msg << "cyclic sector: " << sectors << " sectors, " << plan.sector.left.size()
        << " paired side-face nodes (max mismatch " << plan.sector.maxMismatch << ")";
    log::info(msg.str());
  }
  auto m = scene.section("modal");
  plan.sweep = readModalSweep(m, mesh, sectors, material, fixedSets, outDir, plan.writeMac);
  plan.sweep.axis = axis;
  checkCentrifugalStrain(material, plan.sweep.speedsRpm.back(), mesh, axis, m.where("speeds_rpm"),
                         scene.where("mesh"));
  plan.engineOrders = readEngineOrders(scene.section("diagrams"), sectors);
  if (fixedSets.empty())
    log::warn("modal analysis without fixed node sets: rigid-body modes are expected (zero frequencies)");
  return plan;
}

std::vector<int> readEngineOrders(SceneSection dg, int sectors) {
  std::vector<int> defaultOrders;
  for (int eo = 1; eo <= sectors; ++eo) defaultOrders.push_back(eo);
  const auto engineOrders = dg.getIntList("engine_orders", defaultOrders);
  for (int eo : engineOrders)
    if (eo < 1) throw InputError(dg.where("engine_orders"), "engine orders must be positive, got " + std::to_string(eo));
  dg.rejectUnknownKeys();
  return engineOrders;
}

void modalStage(const ModalPlan& plan, const mesh::Mesh& mesh, const std::string& outDir, linalg::CommPtr comm,
                SceneSummary& summary) {
  const auto& sector = plan.sector;
  const auto& sweep = plan.sweep;
  const int sectors = plan.sectors;
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

  if (plan.writeMac && results.size() > 1) writeSpeedMac(results, outDir, writer, summary);
  writeDiagrams(results, sectors, plan.engineOrders, outDir, writer, summary);
}

}  // namespace cyclone::scenes
