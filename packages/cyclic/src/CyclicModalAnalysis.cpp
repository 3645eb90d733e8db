#include "cyclone/cyclic/CyclicModalAnalysis.hpp"

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>

#include <cstdio>
#include <sstream>

#include "cyclone/core/AtomicFile.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/cyclic/CyclicTransform.hpp"
#include "cyclone/fe/Assembler.hpp"
#include "cyclone/mesh/ExodusIO.hpp"
#include "cyclone/solvers/ModalSolver.hpp"

namespace cyclone::cyclic {

HarmonicOperators assembleHarmonicOperators(const mesh::Mesh& mesh, const CyclicSector& sector, int k,
                                            const fe::IsotropicElastic& material,
                                            const std::vector<std::string>& fixedNodeSets,
                                            const PrestressState* prestress, linalg::CommPtr comm) {
  checkHarmonicIndex(sector.sectors, k);
  HarmonicOperators op;
  op.harmonic = k;
  op.copies = copiesFor(sector.sectors, k);
  op.assembler = std::make_unique<fe::Assembler>(mesh, cyclicTransform(mesh, sector, k, fixedNodeSets), comm);
  op.K = tangentStiffness(*op.assembler, material, prestress);
  op.M = op.assembler->mass(material);
  return op;
}

solvers::ModalResult solveHarmonicModes(const HarmonicOperators& operators, int distinctModes, double shift,
                                        solvers::EigenMethod method) {
  const auto& assembler = *operators.assembler;
  solvers::ModalOptions opt;
  opt.numModes = int(std::min<long long>(distinctModes * operators.copies, assembler.transform().numEquations() - 1));
  opt.shift = shift;
  opt.blockSize = std::max(4, 2 * operators.copies);
  opt.method = method;
  if (opt.method == solvers::EigenMethod::Lobpcg) {
    // The sector's unknowns are rigid-body-like per copy away from the side faces.
    opt.nearNullSpace = assembler.rigidBodyModes();
    opt.equationsPerNode = assembler.transform().blockedByNode() ? 3 * operators.copies : 1;
  }
  return solvers::solveModes(*operators.K, *operators.M, opt);
}

std::vector<HarmonicModes> solveCyclicModes(const mesh::Mesh& mesh, const CyclicSector& sector,
                                            const CyclicModalProblem& problem, linalg::CommPtr comm) {
  problem.material.validate("material");
  std::vector<int> harmonics = problem.harmonics;
  if (harmonics.empty())
    for (int k = 0; k <= sector.maxHarmonicIndex(); ++k) harmonics.push_back(k);
  for (int k : harmonics) checkHarmonicIndex(sector.sectors, k);
  if (problem.modesPerHarmonic < 1) throw InputError("modes_per_nd", "must be at least 1");

  std::vector<HarmonicModes> out;
  for (int k : harmonics) {
    Timer timer;
    const auto op = assembleHarmonicOperators(mesh, sector, k, problem.material, problem.fixedNodeSets,
                                              problem.prestress, comm);
    const auto& assembler = *op.assembler;
    HarmonicModes hm;
    hm.harmonic = k;
    hm.copies = op.copies;
    hm.equations = assembler.transform().numEquations();
    const double assemblySeconds = timer.seconds();
    const auto result = solveHarmonicModes(op, problem.modesPerHarmonic, problem.shift, problem.method);
    const int numModes = int(result.frequenciesHz.size());
    hm.frequenciesHz = result.frequenciesHz;
    for (int i = 0; i < numModes; ++i) {
      hm.shapeReal.push_back(assembler.nodalField(*result.modes, i, 0));
      hm.shapeImag.push_back(hm.copies == 2 ? assembler.nodalField(*result.modes, i, 1)
                                            : std::vector<std::array<double, 3>>(mesh.numNodes(), {0, 0, 0}));
    }
    hm.seconds = timer.seconds();
    std::ostringstream msg;
    msg << "nodal diameter " << k << ": " << hm.equations << " equations, " << numModes << " modes, "
        << (hm.frequenciesHz.empty() ? 0.0 : hm.frequenciesHz.front()) << " .. "
        << (hm.frequenciesHz.empty() ? 0.0 : hm.frequenciesHz.back()) << " Hz, " << hm.seconds
        << " s (assembly " << assemblySeconds << " s, "
        << (problem.method == solvers::EigenMethod::Lobpcg ? "preconditioner " : "factorization ")
        << result.factorSeconds << " s, eigen-solution " << result.solveSeconds << " s, " << result.operatorApplies
        << (problem.method == solvers::EigenMethod::Lobpcg ? " LOBPCG iterations)" : " solves)");
    log::info(msg.str());
    out.push_back(std::move(hm));
  }
  return out;
}

void writeFrequenciesCsv(const std::string& path, const std::vector<SpeedModes>& speeds) {
  AtomicFile file(path);
  std::FILE* f = std::fopen(file.tempPath().c_str(), "w");
  if (!f) throw Error("cannot write " + path);
  std::fprintf(f, "rpm,nd,mode,freq_hz\n");
  for (const auto& speed : speeds)
    for (const auto& hm : speed.harmonics)
      for (std::size_t i = 0; i < hm.frequenciesHz.size(); ++i)
        std::fprintf(f, "%.10g,%d,%zu,%.12g\n", speed.rpm, hm.harmonic, i + 1, hm.frequenciesHz[i]);
  const bool ok = std::fclose(f) == 0;
  if (!ok) throw Error("cannot write " + path);
  file.commit();
}

void writeModesExodus(const std::string& path, const mesh::Mesh& mesh, double rpm,
                      const std::vector<HarmonicModes>& modes) {
  mesh::ExodusResults r;
  r.nodalNames = {"ux", "uy", "uz", "ux_imag", "uy_imag", "uz_imag"};
  r.globalNames = {"nd", "mode", "rpm"};
  for (const auto& hm : modes)
    for (std::size_t i = 0; i < hm.frequenciesHz.size(); ++i) {
      mesh::ExodusResults::Step step;
      step.time = hm.frequenciesHz[i];
      step.nodal.assign(6, std::vector<double>(mesh.numNodes()));
      for (mesh::Index n = 0; n < mesh.numNodes(); ++n)
        for (int d = 0; d < 3; ++d) {
          step.nodal[d][n] = hm.shapeReal[i][n][d];
          step.nodal[3 + d][n] = hm.shapeImag[i][n][d];
        }
      step.global = {double(hm.harmonic), double(i + 1), rpm};
      r.steps.push_back(std::move(step));
    }
  mesh::writeExodus(path, mesh, r);
}

}  // namespace cyclone::cyclic
