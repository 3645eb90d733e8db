// Verification against CalculiX run in the test: the same built-in sector mesh
// and case as a ccx deck with *CYCLIC SYMMETRY MODEL, a *STATIC NLGEOM step with
// CENTRIF and a perturbation *FREQUENCY step with *SELECT CYCLIC SYMMETRY MODES.
// Every frequency per nodal diameter is compared, at rest and at 10000 rpm,
// fixed shroud and cantilever. Same mesh and element (C3D10), so the two
// codes should agree to the digits ccx prints.
#include <Tpetra_Core.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "cyclone/core/Log.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/cyclic/CyclicModalAnalysis.hpp"
#include "cyclone/cyclic/CyclicTransform.hpp"
#include "cyclone/mesh/AbaqusIO.hpp"
#include "cyclone/mesh/ShroudedSectorGenerator.hpp"

using namespace cyclone;
namespace fs = std::filesystem;

namespace {

const int kSectors = 12;
const int kFamilies = 2;

std::string nodeList(const std::string& name, const std::vector<long long>& ids) {
  std::ostringstream s;
  s << "*NSET, NSET=" << name << "\n";
  for (std::size_t i = 0; i < ids.size(); ++i) s << ids[i] << ((i % 10 == 9 || i + 1 == ids.size()) ? "\n" : ", ");
  return s.str();
}

// ccx's distinct frequencies per nodal diameter (it lists every eigenvalue twice).
std::map<int, std::vector<double>> runCalculix(const mesh::Mesh& mesh, const std::vector<std::string>& left,
                                               const std::vector<std::string>& right, double rpm,
                                               const std::string& name, const fe::IsotropicElastic& mat) {
  const fs::path dir = fs::temp_directory_path() / ("cyclone_ccx_cyclic_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  mesh::writeAbaqusInp((dir / "mesh.inp").string(), mesh);
  // Fixed nodes may not be dependent in ccx's cyclic MPCs: leave them out of the tie.
  std::set<mesh::Index> bore(mesh.nodeSet("bore").begin(), mesh.nodeSet("bore").end());
  auto ids = [&](const std::vector<std::string>& sets) {
    std::vector<long long> out;
    for (const auto& s : sets)
      for (auto n : mesh.nodeSet(s))
        if (!bore.count(n)) out.push_back(mesh.nodeIds[n]);
    return out;
  };
  std::ofstream deck(dir / "job.inp");
  deck.precision(15);
  const double w2 = std::pow(rpm * 2 * M_PI / 60, 2);
  deck << "*INCLUDE, INPUT=mesh.inp\n" << nodeList("LEFTFACE", ids(left)) << nodeList("RIGHTFACE", ids(right))
       << "*SURFACE, NAME=SLEFT, TYPE=NODE\nLEFTFACE\n*SURFACE, NAME=SRIGHT, TYPE=NODE\nRIGHTFACE\n"
       << "*TIE, NAME=CYC, CYCLIC SYMMETRY, POSITION TOLERANCE=0.01\nSRIGHT, SLEFT\n"
       << "*CYCLIC SYMMETRY MODEL, N=" << kSectors << ", NGRAPH=1, TIE=CYC\n0., 0., 0., 0., 0., 1.\n"
       << "*MATERIAL, NAME=M\n*ELASTIC\n" << mat.E << ", " << mat.nu << "\n*DENSITY\n" << mat.rho
       << "\n*SOLID SECTION, ELSET=sector, MATERIAL=M\n*BOUNDARY\nbore, 1, 3\n";
  if (rpm > 0)
    deck << "*STEP, NLGEOM\n*STATIC\n*DLOAD\nsector, CENTRIF, " << w2 << ", 0., 0., 0., 0., 0., 1.\n*END STEP\n"
         << "*STEP, PERTURBATION\n";
  else
    deck << "*STEP\n";
  deck << "*FREQUENCY\n" << 2 * kFamilies << "\n*SELECT CYCLIC SYMMETRY MODES, NMIN=0, NMAX=" << kSectors / 2
       << "\n*END STEP\n";
  deck.close();
  const std::string command = "cd '" + dir.string() + "' && OMP_NUM_THREADS=1 ccx -i job > ccx.log 2>&1";
  if (std::system(command.c_str()) != 0) throw std::runtime_error("ccx failed: see " + (dir / "ccx.log").string());
  std::map<int, std::vector<double>> all;
  std::ifstream dat(dir / "job.dat");
  std::string line;
  bool table = false;
  while (std::getline(dat, line)) {
    if (line.find("E I G E N V A L U E   O U T P U T") != std::string::npos) table = true;
    if (line.find("P A R T I C I P A T I O N") != std::string::npos) table = false;
    if (!table) continue;
    std::istringstream in(line);
    int nd, mode;
    double eig, rad, hz, imag;
    if (in >> nd >> mode >> eig >> rad >> hz >> imag) all[nd].push_back(hz);
  }
  std::map<int, std::vector<double>> distinct;
  for (auto& [nd, f] : all)
    for (std::size_t i = 0; i < f.size(); i += 2) distinct[nd].push_back(f[i]);
  return distinct;
}

void compare(const std::vector<std::string>& left, const std::vector<std::string>& right, double rpm,
             const char* name) {
  log::setQuiet(getenv("CYCLONE_VERBOSE") == nullptr);
  mesh::ShroudedSectorParameters p;
  p.sectors = kSectors;
  p.meshSize = 8.0;
  const auto mesh = mesh::generateShroudedSector(p);
  const auto sector = cyclic::makeCyclicSector(mesh, kSectors, {}, left, right);
  cyclic::CyclicModalProblem problem;
  problem.fixedNodeSets = {"bore"};
  problem.modesPerHarmonic = kFamilies;
  Timer timer;
  cyclic::PrestressState state;
  if (rpm > 0) {
    state = cyclic::solveNonlinearPrestress(mesh, cyclic::cyclicTransform(mesh, sector, 0, {"bore"}),
                                            problem.material, rpm, fe::Axis{}, Tpetra::getDefaultComm());
    problem.prestress = &state;
  }
  const auto ours = cyclic::solveCyclicModes(mesh, sector, problem, Tpetra::getDefaultComm());
  const double tOurs = timer.seconds();
  timer.restart();
  const auto ccx = runCalculix(mesh, left, right, rpm, std::string(name) + std::to_string(int(rpm)), problem.material);
  double worst = 0;
  for (const auto& hm : ours) {
    ASSERT_EQ(ccx.count(hm.harmonic), 1u) << "ccx gave no modes for ND " << hm.harmonic;
    const auto& theirs = ccx.at(hm.harmonic);
    ASSERT_GE(theirs.size(), std::size_t(kFamilies));
    for (int j = 0; j < kFamilies; ++j) {
      const double mine = hm.frequenciesHz[j * hm.copies];
      worst = std::max(worst, std::abs(mine / theirs[j] - 1));
      if (getenv("CYCLONE_VERBOSE")) std::printf("ND %d family %d: %.7g %.7g\n", hm.harmonic, j + 1, mine, theirs[j]);
      EXPECT_NEAR(mine / theirs[j], 1.0, 2e-5) << name << " " << rpm << " rpm, ND " << hm.harmonic << " family " << j + 1;
    }
  }
  std::printf("%s at %5.0f rpm: ND 0..%d x %d families, max |f_cyclone / f_ccx - 1| = %.1e (cyclone %.1f s, ccx %.1f s)\n",
              name, rpm, kSectors / 2, kFamilies, worst, tOurs, timer.seconds());
}

}  // namespace

TEST(CalculixCyclic, FixedShroudAtRest) {
  compare({"disc_left", "shroud_left"}, {"disc_right", "shroud_right"}, 0, "fixed shroud");
}
TEST(CalculixCyclic, FixedShroudNlgeom10000rpm) {
  compare({"disc_left", "shroud_left"}, {"disc_right", "shroud_right"}, 10000, "fixed shroud");
}
TEST(CalculixCyclic, CantileverAtRest) { compare({"disc_left"}, {"disc_right"}, 0, "cantilever"); }
TEST(CalculixCyclic, CantileverNlgeom10000rpm) { compare({"disc_left"}, {"disc_right"}, 10000, "cantilever"); }
