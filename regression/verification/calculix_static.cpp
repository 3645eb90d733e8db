// Verification against another code run in the test: CalculiX (ccx) solves the
// same linear static centrifugal problem on the same mesh, read from the .inp
// deck Cyclone writes. Same element (C3D10), same load, same supports: the
// displacement fields must agree up to the 7 digits ccx prints.
#include <Tpetra_Core.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "BoxMesh.hpp"
#include "cyclone/analysis/StaticAnalysis.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/mesh/AbaqusIO.hpp"
#include "cyclone/mesh/ShroudedSectorGenerator.hpp"

using namespace cyclone;
namespace fs = std::filesystem;

namespace {

// Runs ccx on `mesh` with the problem's material, fixed sets and centrifugal
// load; returns the displacement of every node (by index) from the .dat file.
std::vector<std::array<double, 3>> runCalculix(const mesh::Mesh& mesh, const analysis::StaticProblem& p,
                                               const std::string& block, const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("cyclone_ccx_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  mesh::writeAbaqusInp((dir / "mesh.inp").string(), mesh);
  const double omega = p.speedRpm * 2 * M_PI / 60;
  std::ofstream deck(dir / "job.inp");
  deck.precision(15);  // ccx reads fields of at most 20 characters
  deck << "*INCLUDE, INPUT=mesh.inp\n*NSET, NSET=EVERYNODE\n";
  for (mesh::Index n = 0; n < mesh.numNodes(); ++n) deck << mesh.nodeIds[n] << ((n % 16 == 15) ? ",\n" : ", ");
  deck << "\n*MATERIAL, NAME=M\n*ELASTIC\n" << p.material.E << ", " << p.material.nu
       << "\n*DENSITY\n" << p.material.rho << "\n*SOLID SECTION, ELSET=" << block << ", MATERIAL=M\n*BOUNDARY\n";
  for (const auto& set : p.fixedNodeSets) deck << set << ", 1, 3\n";
  deck << "*STEP\n*STATIC\n*DLOAD\n" << block << ", CENTRIF, " << omega * omega << ", " << p.axis.point[0] << ", "
       << p.axis.point[1] << ", " << p.axis.point[2] << ", " << p.axis.direction[0] << ", " << p.axis.direction[1]
       << ", " << p.axis.direction[2] << "\n*NODE PRINT, NSET=EVERYNODE\nU\n*END STEP\n";
  deck.close();
  const std::string command = "cd '" + dir.string() + "' && OMP_NUM_THREADS=1 ccx -i job > ccx.log 2>&1";
  if (std::system(command.c_str()) != 0) throw std::runtime_error("ccx failed: see " + (dir / "ccx.log").string());

  std::unordered_map<long long, mesh::Index> indexOfId;
  for (mesh::Index n = 0; n < mesh.numNodes(); ++n) indexOfId[mesh.nodeIds[n]] = n;
  std::vector<std::array<double, 3>> u(mesh.numNodes(), {NAN, NAN, NAN});
  std::ifstream dat(dir / "job.dat");
  std::string line;
  bool inTable = false;
  while (std::getline(dat, line)) {
    if (line.find("displacements") != std::string::npos) {
      inTable = true;
      continue;
    }
    if (!inTable) continue;
    std::istringstream in(line);
    long long id;
    double x, y, z;
    if (in >> id >> x >> y >> z) u.at(indexOfId.at(id)) = {x, y, z};
  }
  return u;
}

double relativeMaxDifference(const std::vector<std::array<double, 3>>& a, const std::vector<std::array<double, 3>>& b) {
  double diff = 0, scale = 0;
  for (std::size_t n = 0; n < a.size(); ++n)
    for (int d = 0; d < 3; ++d) {
      if (std::isnan(b[n][d])) return INFINITY;  // a node missing from ccx's table
      diff = std::max(diff, std::abs(a[n][d] - b[n][d]));
      scale = std::max(scale, std::abs(b[n][d]));
    }
  return diff / scale;
}

}  // namespace

TEST(CalculixStatic, BoxCantileverCentrifugal) {
  log::setQuiet(true);
  auto box = test_support::makeBoxMesh(100.0, 10.0, 10.0, 10, 2, 2, mesh::ElementType::Tet10);
  analysis::StaticProblem p;
  p.material = fe::IsotropicElastic{"steel", 2.1e5, 0.3, 7.85e-9};
  p.fixedNodeSets = {"x0"};
  p.speedRpm = 6000;
  p.axis.point = Eigen::Vector3d(-20, 0, 0);
  p.axis.direction = Eigen::Vector3d(0, 0, 1);
  Timer timer;
  const auto ours = analysis::solveStatic(box, p, Tpetra::getDefaultComm());
  const double tOurs = timer.seconds();
  timer.restart();
  const auto ccx = runCalculix(box, p, "box", "box");
  const double diff = relativeMaxDifference(ours.displacement, ccx);
  std::printf("tet10 box cantilever, centrifugal: max |u_cyclone - u_ccx| / max |u_ccx| = %.2e "
              "(cyclone %.2f s, ccx %.2f s)\n", diff, tOurs, timer.seconds());
  EXPECT_LT(diff, 1e-5);  // straight-edged elements: both integrations are exact; 7 printed digits
}

TEST(CalculixStatic, ShroudedSectorCentrifugal) {
  log::setQuiet(true);
  mesh::ShroudedSectorParameters sector;
  sector.meshSize = 8.0;
  const auto mesh = mesh::generateShroudedSector(sector);
  analysis::StaticProblem p;  // titanium, z axis
  p.fixedNodeSets = {"bore"};
  p.speedRpm = 10000;
  Timer timer;
  const auto ours = analysis::solveStatic(mesh, p, Tpetra::getDefaultComm());
  const double tOurs = timer.seconds();
  timer.restart();
  const auto ccx = runCalculix(mesh, p, "sector", "sector");
  const double diff = relativeMaxDifference(ours.displacement, ccx);
  std::printf("shrouded sector, 10000 rpm: max |u_cyclone - u_ccx| / max |u_ccx| = %.2e (cyclone %.2f s, ccx %.2f s)\n",
              diff, tOurs, timer.seconds());
  EXPECT_LT(diff, 1e-5);  // measured 2e-6: ccx prints 7 digits
}
