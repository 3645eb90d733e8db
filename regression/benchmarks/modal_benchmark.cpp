// Benchmark (a program, not a test): the cyclic modal chain against CalculiX on the
// same work. The built-in shrouded sector (24 sectors, titanium, bore fixed, fixed
// shroud) at a fine mesh, NLGEOM prestress at 10 000 rpm, every nodal diameter
// 0..12 with 5 distinct modes. Cyclone runs as its command line (`cyclone run`) on
// 1 and 2 MPI ranks (a thread each), and on 1 rank with its nodal diameters on 2
// threads (modal/threads); ccx 2.20 (SPOOLES) on the same mesh with 1 and 2 threads and
// tight Newton tolerances. Printed: wall time, peak memory (Cyclone: summed over its
// ranks, from its log; ccx: the kernel's high-water mark), the peak physical memory of
// the run's process tree (summed PSS sampled every 250 ms, MeasuredCommand.hpp: shared
// pages counted once) and the largest relative
// frequency difference to ccx with 2 threads. A last Cyclone run (one rank) uses ccx's
// tet10 mass rule (material mass_quadrature: stiffness_rule): the frequencies at ccx's
// own discretisation, where the difference is ccx's printed digits.
//   build/regression/modal_benchmark [--mesh-size 2.7] [--work /tmp/cyclone_modal_benchmark]
// Large sectors (which path fits a machine): --large runs Cyclone alone on one rank,
// shift-invert (CHOLMOD) and LOBPCG + MueLu, and compares their frequencies:
//   build/regression/modal_benchmark --mesh-size 1.45 --large

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>

#include "CalculixCyclic.hpp"
#include "MeasuredCommand.hpp"
#include "cyclone/mesh/ShroudedSectorGenerator.hpp"

using namespace cyclone;
namespace fs = std::filesystem;

namespace {

constexpr int kSectors = 24, kModes = 5;
constexpr double kRpm = 10000;

struct Run {
  std::string name;
  double seconds = 0, peakMb = 0, pssMb = 0;
  std::map<int, std::vector<double>> frequenciesHz;
};

regression::MeasuredCommand runShell(const std::string& command) {
  try {
    return regression::runMeasured(command);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    std::exit(1);
  }
}

// Cyclone's scene: the same sector and case as the ccx deck.
void writeScene(const fs::path& path, const fs::path& out, double meshSize, const std::string& eigenSolver,
                const std::string& massQuadrature, int threads) {
  std::ofstream f(path);
  f << "cyclone:\n  analysis: [modal]\n  output_directory: " << out.string()
    << "\n  mesh:\n    source: shrouded_sector\n    shrouded_sector:\n      sectors: " << kSectors
    << "\n      mesh_size: " << meshSize
    << "\n  material:\n    mass_quadrature: " << massQuadrature
    << "\n  constraints:\n    fixed_node_sets: [bore]\n  loads:\n    speed_rpm: " << kRpm
    << "\n  cyclic:\n    configuration: fixed_shroud\n  modal:\n    modes_per_nd: " << kModes
    << "\n    speeds_rpm: [" << kRpm << "]\n    prestress: nonlinear\n    eigen_solver: " << eigenSolver
    << "\n    threads: " << threads << "\n";
}

Run runCyclone(const std::string& name, const std::string& launcher, const fs::path& work, double meshSize,
               const std::string& eigenSolver = "shift_invert", const std::string& massQuadrature = "exact",
               int threads = 1) {
  Run run;
  run.name = name;
  const fs::path out = work / name, scene = work / (name + ".yaml"), log = work / (name + ".log");
  writeScene(scene, out, meshSize, eigenSolver, massQuadrature, threads);
  const auto measured =
      runShell(launcher + " " + CYCLONE_EXECUTABLE + " run " + scene.string() + " > " + log.string() + " 2>&1");
  run.seconds = measured.seconds;
  run.pssMb = measured.peakTreePssMb;
  // "peak memory after the modes at ...: X MB[ on rank 0, Y MB summed over N ranks]"
  std::ifstream in(log);
  std::string line;
  const std::regex single("peak memory after the (?:prestress and )?modes[^:]*: ([0-9.e+]+) MB"),
      summed("([0-9.e+]+) MB summed over");
  while (std::getline(in, line)) {
    std::smatch m;
    if (std::regex_search(line, m, summed)) run.peakMb = std::stod(m[1]);
    else if (std::regex_search(line, m, single)) run.peakMb = std::stod(m[1]);
  }
  std::ifstream csv(out / "frequencies.csv");
  std::getline(csv, line);
  std::map<int, std::vector<double>> all;
  while (std::getline(csv, line)) {
    double rpm, hz;
    int nd, mode;
    char c;
    std::istringstream row(line);
    if (row >> rpm >> c >> nd >> c >> mode >> c >> hz) all[nd].push_back(hz);
  }
  for (auto& [nd, f] : all) {
    const int copies = (nd == 0 || 2 * nd == kSectors) ? 1 : 2;
    for (std::size_t i = 0; i < f.size(); i += copies) run.frequenciesHz[nd].push_back(f[i]);
  }
  return run;
}

Run runCcx(const std::string& name, int threads, const mesh::Mesh& mesh, const fs::path& work) {
  regression::CalculixCyclicCase c;
  c.directory = (work / name).string();
  c.left = {"disc_left", "shroud_left"};
  c.right = {"disc_right", "shroud_right"};
  c.sectors = kSectors;
  c.rpm = kRpm;
  c.material = fe::IsotropicElastic{};  // titanium, as the scene's default
  c.modesPerNd = kModes;
  c.maxNd = kSectors / 2;
  c.threads = threads;
  c.tightNewton = true;
  const auto r = regression::runCalculixCyclic(mesh, c);
  return Run{name, r.seconds, r.peakMemoryMb, r.peakPssMb, r.frequenciesHz};
}

double worstDifference(const Run& a, const Run& b) {
  double worst = 0;
  for (const auto& [nd, f] : a.frequenciesHz) {
    const auto it = b.frequenciesHz.find(nd);
    if (it == b.frequenciesHz.end()) return NAN;
    for (std::size_t i = 0; i < f.size() && i < it->second.size(); ++i)
      worst = std::max(worst, std::abs(f[i] / it->second[i] - 1));
  }
  return worst;
}

}  // namespace

int main(int argc, char** argv) {
  double meshSize = 2.7;
  bool large = false;
  fs::path work = fs::temp_directory_path() / "cyclone_modal_benchmark";
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--large")) large = true;
    else if (i + 1 < argc && !std::strcmp(argv[i], "--mesh-size")) meshSize = std::atof(argv[++i]);
    else if (i + 1 < argc && !std::strcmp(argv[i], "--work")) work = argv[++i];
    else {
      std::fprintf(stderr, "usage: modal_benchmark [--mesh-size h] [--work dir] [--large]\n");
      return 2;
    }
  }
  fs::create_directories(work);
  mesh::ShroudedSectorParameters p;
  p.sectors = kSectors;
  p.meshSize = meshSize;
  const auto mesh = mesh::generateShroudedSector(p);
  std::printf("Cyclic modal chain, built-in sector at mesh size %g: %lld nodes, %lld tet10, %lld DOFs; NLGEOM at "
              "%g rpm, ND 0..%d x %d modes\n",
              meshSize, (long long)mesh.numNodes(), (long long)mesh.numElements(), 3LL * mesh.numNodes(), kRpm,
              kSectors / 2, kModes);
  setenv("OPENBLAS_NUM_THREADS", "1", 1);
  setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
  setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
  std::vector<Run> runs;
  if (large) {
    for (const char* solver : {"shift_invert", "lobpcg"}) {
      runs.push_back(runCyclone(std::string("cyclone_") + solver, "", work, meshSize, solver));
      std::printf("  %-20s %7.1f s\n", runs.back().name.c_str(), runs.back().seconds);
    }
    std::printf("\n| run | wall time | peak memory | max |f / f_shift_invert - 1| |\n|---|---|---|---|\n");
    for (const auto& r : runs)
      std::printf("| %s | %.1f s | %.0f MB | %.1e |\n", r.name.c_str(), r.seconds, r.peakMb,
                  worstDifference(r, runs.front()));
    return 0;
  }
  runs.push_back(runCyclone("cyclone_np1", "", work, meshSize));
  std::printf("  %-12s %7.1f s\n", runs.back().name.c_str(), runs.back().seconds);
  runs.push_back(runCyclone("cyclone_np2",
                            std::string(MPIEXEC_EXECUTABLE) + " -np 2 --oversubscribe -x OPENBLAS_NUM_THREADS", work,
                            meshSize));
  std::printf("  %-12s %7.1f s\n", runs.back().name.c_str(), runs.back().seconds);
  // One process, the nodal diameters on 2 threads (each its own factor).
  runs.push_back(runCyclone("cyclone_np1_2threads", "", work, meshSize, "shift_invert", "exact", 2));
  std::printf("  %-12s %7.1f s\n", runs.back().name.c_str(), runs.back().seconds);
  for (int threads : {1, 2}) {
    runs.push_back(runCcx("ccx_" + std::to_string(threads) + "threads", threads, mesh, work));
    std::printf("  %-12s %7.1f s\n", runs.back().name.c_str(), runs.back().seconds);
  }
  // The same work with ccx's tet10 mass rule (4 points, its stiffness rule): the
  // frequencies at ccx's own discretisation (docs/verification.md).
  runs.push_back(runCyclone("cyclone_np1_ccx_mass_rule", "", work, meshSize, "shift_invert", "stiffness_rule"));
  std::printf("  %-12s %7.1f s\n", runs.back().name.c_str(), runs.back().seconds);
  const Run& reference = runs[4];
  double ccxBest = std::min(runs[3].seconds, runs[4].seconds);
  std::printf("\n| run | wall time | / ccx best | peak memory | peak physical memory (summed PSS) | max |f / f_ccx - 1| "
              "|\n|---|---|---|---|---|---|\n");
  for (const auto& r : runs)
    std::printf("| %s | %.1f s | %.2f | %.0f MB | %.0f MB | %.1e |\n", r.name.c_str(), r.seconds, r.seconds / ccxBest,
                r.peakMb, r.pssMb, worstDifference(r, reference));
  return 0;
}
