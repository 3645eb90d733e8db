#include "CalculixCyclic.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

#include "MeasuredCommand.hpp"
#include "cyclone/mesh/AbaqusIO.hpp"

namespace cyclone::regression {

namespace fs = std::filesystem;

namespace {

std::string nodeList(const std::string& name, const std::vector<long long>& ids) {
  std::ostringstream s;
  s << "*NSET, NSET=" << name << "\n";
  for (std::size_t i = 0; i < ids.size(); ++i) s << ids[i] << ((i % 10 == 9 || i + 1 == ids.size()) ? "\n" : ", ");
  return s.str();
}

}  // namespace

CalculixCyclicRun runCalculixCyclic(const mesh::Mesh& mesh, const CalculixCyclicCase& c) {
  const fs::path dir = c.directory;
  fs::remove_all(dir);
  fs::create_directories(dir);
  mesh::writeAbaqusInp((dir / "mesh.inp").string(), mesh);
  // Fixed nodes may not be dependent in ccx's cyclic MPCs: leave them out of the tie.
  std::set<mesh::Index> fixed(mesh.nodeSet(c.fixedSet).begin(), mesh.nodeSet(c.fixedSet).end());
  auto ids = [&](const std::vector<std::string>& sets) {
    std::vector<long long> out;
    for (const auto& s : sets)
      for (auto n : mesh.nodeSet(s))
        if (!fixed.count(n)) out.push_back(mesh.nodeIds[n]);
    return out;
  };
  std::ofstream deck(dir / "job.inp");
  deck.precision(15);
  const double w2 = std::pow(c.rpm * 2 * M_PI / 60, 2);
  const auto& m = c.material;
  deck << "*INCLUDE, INPUT=mesh.inp\n" << nodeList("LEFTFACE", ids(c.left)) << nodeList("RIGHTFACE", ids(c.right))
       << "*SURFACE, NAME=SLEFT, TYPE=NODE\nLEFTFACE\n*SURFACE, NAME=SRIGHT, TYPE=NODE\nRIGHTFACE\n"
       << "*TIE, NAME=CYC, CYCLIC SYMMETRY, POSITION TOLERANCE=0.01\nSRIGHT, SLEFT\n"
       << "*CYCLIC SYMMETRY MODEL, N=" << c.sectors << ", NGRAPH=1, TIE=CYC\n0., 0., 0., 0., 0., 1.\n"
       << "*MATERIAL, NAME=M\n*ELASTIC\n" << m.E << ", " << m.nu << "\n*DENSITY\n" << m.rho
       << "\n*SOLID SECTION, ELSET=sector, MATERIAL=M\n*BOUNDARY\n" << c.fixedSet << ", 1, 3\n";
  if (c.rpm > 0) {
    deck << "*STEP, NLGEOM\n*STATIC\n";
    // Residual and correction criteria (R_n, C_n) from 0.005 and 0.01 down to 1e-9.
    if (c.tightNewton) deck << "*CONTROLS, PARAMETERS=FIELD\n1.e-9, 1.e-9\n";
    deck << "*DLOAD\nsector, CENTRIF, " << w2 << ", 0., 0., 0., 0., 0., 1.\n*END STEP\n"
         << "*STEP, PERTURBATION\n";
  } else {
    deck << "*STEP\n";
  }
  deck << "*FREQUENCY\n" << 2 * c.modesPerNd << "\n*SELECT CYCLIC SYMMETRY MODES, NMIN=0, NMAX=" << c.maxNd
       << "\n*END STEP\n";
  deck.close();
  const std::string t = std::to_string(c.threads);
  CalculixCyclicRun run;
  const MeasuredCommand measured =
      runMeasured("cd '" + dir.string() + "' && OMP_NUM_THREADS=" + t + " CCX_NPROC_EQUATION_SOLVER=" + t +
                  " CCX_NPROC_STIFFNESS=" + t + " CCX_NPROC_RESULTS=" + t + " exec ccx -i job > ccx.log 2>&1");
  run.seconds = measured.seconds;
  run.peakMemoryMb = measured.peakResidentMb;
  run.peakPssMb = measured.peakTreePssMb;
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
  // ccx lists every eigenvalue twice (its two cyclic copies).
  for (auto& [nd, f] : all)
    for (std::size_t i = 0; i < f.size(); i += 2) run.frequenciesHz[nd].push_back(f[i]);
  if (run.frequenciesHz.empty()) throw std::runtime_error("ccx gave no frequencies: see " + (dir / "ccx.log").string());
  return run;
}

}  // namespace cyclone::regression
