#include "cyclone/scenes/SceneRunner.hpp"

#include <Teuchos_Comm.hpp>
#include <Teuchos_YamlParameterListCoreHelpers.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "DemoScene.hpp"
#include "cyclone/analysis/StaticAnalysis.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/mesh/AbaqusIO.hpp"
#include "cyclone/mesh/ExodusIO.hpp"
#include "cyclone/mesh/MeshReader.hpp"
#include "cyclone/mesh/ShroudedSectorGenerator.hpp"
#include "cyclone/scenes/SceneSection.hpp"

namespace cyclone::scenes {

const char* demoScene() { return demoSceneYaml(); }

namespace {

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
                     const std::string& outDir, const linalg::Comm& comm, SceneSummary& summary) {
  const bool writer = comm.getRank() == 0;
  const std::string source = s.getString("source", "shrouded_sector");
  const auto write = s.getStringList("write", {});
  SceneSection sector = s.section("shrouded_sector");
  mesh::Mesh mesh;
  if (source == "shrouded_sector") {
    auto p = readSectorParameters(sector);
    if (overrides.meshSize) p.meshSize = *overrides.meshSize;
    mesh = mesh::generateShroudedSector(p);
  } else {
    sector.rejectUnknownKeys();
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

void staticStage(SceneSection& scene, const mesh::Mesh& mesh, const std::string& outDir, linalg::CommPtr comm,
                 SceneSummary& summary) {
  analysis::StaticProblem problem;
  {
    auto m = scene.section("material");
    problem.material.name = m.getString("name", problem.material.name);
    problem.material.E = m.getDouble("E", problem.material.E);
    problem.material.nu = m.getDouble("nu", problem.material.nu);
    problem.material.rho = m.getDouble("rho", problem.material.rho);
    m.rejectUnknownKeys();
    problem.material.validate(m.location());
  }
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
    const auto p = l.getVector3("axis_point", {0, 0, 0});
    const auto d = l.getVector3("axis_direction", {0, 0, 1});
    problem.axis.point = Eigen::Vector3d(p[0], p[1], p[2]);
    problem.axis.direction = Eigen::Vector3d(d[0], d[1], d[2]);
    if (problem.axis.direction.norm() == 0) throw InputError(l.where("axis_direction"), "must not be zero");
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
  scene.rejectUnknownKeys();
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

SceneSummary runSceneText(const std::string& yaml, const std::string& source, const SceneOverrides& overrides,
                          linalg::CommPtr comm) {
  Teuchos::RCP<Teuchos::ParameterList> root;
  try {
    root = Teuchos::getParametersFromYamlString(yaml);
  } catch (const std::exception& e) {
    throw InputError(source, std::string("not a valid YAML scene: ") + e.what());
  }
  const std::string sceneDir = std::filesystem::path(source).has_parent_path()
                                   ? std::filesystem::path(source).parent_path().string()
                                   : ".";
  // Teuchos names the root list after the single top-level key.
  if (root->name() != "cyclone" && !root->isSublist("cyclone"))
    throw InputError(source, "the scene's top-level key must be 'cyclone'");
  const Teuchos::ParameterList& top = root->isSublist("cyclone") ? root->sublist("cyclone") : *root;
  SceneSection scene(top, source, "cyclone");
  SceneSummary summary;
  const std::string analysis = scene.getString("analysis", "static");
  if (analysis != "static" && analysis != "mesh")
    throw InputError(scene.where("analysis"), "unknown analysis '" + analysis + "' (use static or mesh)");
  const std::string outDir = overrides.outputDirectory ? *overrides.outputDirectory
                                                       : scene.getString("output_directory", "cyclone_out");
  if (overrides.outputDirectory) scene.getString("output_directory", "");
  if (comm->getRank() == 0) std::filesystem::create_directories(outDir);
  comm->barrier();

  auto mesh = meshStage(scene.section("mesh"), overrides, sceneDir, outDir, *comm, summary);
  if (analysis == "static") staticStage(scene, mesh, outDir, comm, summary);
  scene.rejectUnknownKeys();
  return summary;
}

SceneSummary runSceneFile(const std::string& path, const SceneOverrides& overrides, linalg::CommPtr comm) {
  std::ifstream in(path);
  if (!in) throw InputError(path, "cannot open the scene file");
  std::stringstream text;
  text << in.rdbuf();
  return runSceneText(text.str(), path, overrides, comm);
}

}  // namespace cyclone::scenes
