#include "cyclone/cyclic/CyclicModalAnalysis.hpp"

#include <Tpetra_CrsMatrix.hpp>
#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultSerialComm.hpp>
#include <Tpetra_MultiVector.hpp>

#include <atomic>
#include <exception>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <limits>
#include <system_error>
#include <mutex>
#include <optional>
#include <sstream>
#include <thread>

#include "cyclone/core/AtomicFile.hpp"
#include "cyclone/core/ContentHash.hpp"
#include "cyclone/mesh/MeshDigest.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/core/PeakMemory.hpp"
#include "cyclone/core/ProcessorCores.hpp"
#include "cyclone/core/SingleThreadedBlas.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/cyclic/CyclicTransform.hpp"
#include "cyclone/cyclic/NodalDiameterForm.hpp"
#include "cyclone/cyclic/SectorMatrices.hpp"
#include "cyclone/fe/Assembler.hpp"
#include "cyclone/mesh/ExodusIO.hpp"
#include "cyclone/solvers/ModalSolver.hpp"

namespace cyclone::cyclic {

NodalDiameterOperators assembleNodalDiameterOperators(const mesh::Mesh& mesh, const CyclicSector& sector, int k,
                                            const fe::IsotropicElastic& material,
                                            const std::vector<std::string>& fixedNodeSets,
                                            const PrestressState* prestress, linalg::CommPtr comm) {
  checkNodalDiameter(sector.sectors, k);
  NodalDiameterOperators op;
  op.nodalDiameter = k;
  op.copies = copiesFor(sector.sectors, k);
  op.assembler = std::make_unique<fe::Assembler>(mesh, cyclicTransform(mesh, sector, k, fixedNodeSets), comm);
  op.K = tangentStiffness(*op.assembler, material, prestress);
  op.M = op.assembler->mass(material);
  return op;
}

solvers::ModalResult solveNodalDiameterModes(const NodalDiameterOperators& operators, int distinctModes, double shift,
                                        solvers::EigenMethod method) {
  const auto& assembler = *operators.assembler;
  solvers::ModalOptions opt;
  opt.numModes = int(std::min<long long>(distinctModes * operators.copies, assembler.transform().numEquations() - 1));
  opt.shift = shift;
  opt.blockSize = std::max(4, 2 * operators.copies);
  opt.method = method;
  if (travellingWavePaired(assembler.transform())) opt.structure = solvers::DirectSolver::Structure::TravellingWavePairs;
  if (opt.method == solvers::EigenMethod::Lobpcg) {
    // The sector's unknowns are rigid-body-like per copy away from the side faces.
    opt.nearNullSpace = assembler.rigidBodyModes();
    opt.equationsPerNode = assembler.transform().blockedByNode() ? 3 * operators.copies : 1;
  }
  return solvers::solveModes(*operators.K, *operators.M, opt);
}

namespace {

std::string describe(const NodalDiameterModes& hm, solvers::EigenMethod method) {
  std::ostringstream msg;
  msg << "nodal diameter " << hm.nodalDiameter << ": " << hm.equations << " equations, " << hm.frequenciesHz.size()
      << " modes, " << (hm.frequenciesHz.empty() ? 0.0 : hm.frequenciesHz.front()) << " .. "
      << (hm.frequenciesHz.empty() ? 0.0 : hm.frequenciesHz.back()) << " Hz, " << hm.seconds << " s ("
      << (hm.projected ? "projection " : "assembly ") << hm.assemblySeconds << " s, "
      << (method == solvers::EigenMethod::Lobpcg ? "preconditioner " : "factorization ") << hm.factorSeconds
      << " s, eigen-solution " << hm.solveSeconds << " s, " << hm.solves
      << (method == solvers::EigenMethod::Lobpcg ? " LOBPCG iterations" : " solves");
  if (hm.rank > 0) msg << "; rank " << hm.rank;
  msg << ")";
  return msg.str();
}

// What one thread solving nodal diameters carries: its own factorizations, and when
// threads share the process, the locks taken around the libraries that are not
// thread-safe here. Trilinos: Tpetra's vectors reduce through Kokkos::Serial's one
// scratch buffer, Teuchos counts RCP references without atomics
// (HAVE_TEUCHOS_THREAD_SAFE is off) and Anasazi's solvers share named timers. The
// checkpoints: HDF5 (Debian's MPI build is not thread-safe), or whatever a caller's
// ResultCheckpoints does. CHOLMOD (a common per factor), OpenBLAS, the projections
// and the scratch files of the shapes are used by both threads at once.
struct NodalDiameterWorker {
  FactorCache factors;
  std::mutex* trilinos = nullptr;
  std::mutex* checkpoints = nullptr;
  /// Called after each factorization with the factor's size in bytes.
  std::function<void(double)> factored;
};

// A worker's lock, or none on one thread.
std::unique_lock<std::mutex> section(std::mutex* lock) {
  return lock ? std::unique_lock<std::mutex>(*lock) : std::unique_lock<std::mutex>();
}
std::unique_lock<std::mutex> trilinosSection(const NodalDiameterWorker& worker) { return section(worker.trilinos); }

// One nodal diameter on its own operators assembled on the transform (Tpetra, distributed
// over comm): the LOBPCG path, and shift-invert for a free sector whose shift must be found.
NodalDiameterModes solveAssembled(const mesh::Mesh& mesh, const CyclicSector& sector, int k,
                             const CyclicModalProblem& problem, linalg::CommPtr comm) {
  Timer timer;
  const auto op = assembleNodalDiameterOperators(mesh, sector, k, problem.material, problem.fixedNodeSets,
                                            problem.prestress.get(), comm);
  const auto& assembler = *op.assembler;
  NodalDiameterModes hm;
  hm.nodalDiameter = k;
  hm.copies = op.copies;
  hm.equations = assembler.transform().numEquations();
  hm.assemblySeconds = timer.seconds();
  const auto result = solveNodalDiameterModes(op, problem.modesPerNodalDiameter, problem.shift, problem.method);
  hm.frequenciesHz = result.frequenciesHz;
  for (std::size_t i = 0; i < result.frequenciesHz.size(); ++i) {
    hm.shapes.push_back({assembler.nodalField(*result.modes, int(i), 0),
                         hm.copies == 2 ? assembler.nodalField(*result.modes, int(i), 1) : NodalField()});
  }
  hm.factorSeconds = result.factorSeconds;
  hm.solveSeconds = result.solveSeconds;
  hm.solves = result.operatorApplies;
  hm.seconds = timer.seconds();
  return hm;
}

// One nodal diameter projected from the sector's matrices (one process). Empty when the
// shift is automatic and K_k does not factor (a free sector): the caller then takes the
// assembled path, whose shift search handles rigid-body modes.
std::optional<NodalDiameterModes> solveProjected(const mesh::Mesh& mesh, const CyclicSector& sector, int k,
                                            const SectorMatrices& matrices, const CyclicModalProblem& problem,
                                            NodalDiameterWorker& worker) {
  Timer timer;
  const auto transform = cyclicTransform(mesh, sector, k, problem.fixedNodeSets);
  NodalDiameterForm form(matrices, transform);
  releaseFreedMemory();  // the projection's work, before the factor's peak
  NodalDiameterModes hm;
  hm.nodalDiameter = k;
  hm.copies = transform.copies();
  hm.equations = transform.numEquations();
  hm.projected = true;
  hm.assemblySeconds = timer.seconds();
  Timer factorTimer;
  const bool automatic = std::isnan(problem.shift);
  const double shift = automatic ? 0.0 : problem.shift;
  try {
    form.factor(shift, worker.factors);
  } catch (const SolverError& e) {
    if (automatic) return std::nullopt;
    throw SolverError(std::string(e.what()) + ". For the eigen-solution: K - sigma M with sigma = " +
                      std::to_string(shift) +
                      " must be positive definite; an unconstrained (free) model needs a negative shift "
                      "of the order of its first elastic eigenvalue (2 pi f)^2");
  }
  form.releaseProjections();  // the factor holds what the solves need; K and M through the sector's
  hm.factorSeconds = factorTimer.seconds();
  // In complex entries: a real nodal diameter (k = 0, first) announces what the pairs will hold.
  if (worker.factored) worker.factored(16.0 * form.factorNonzeros());
  solvers::ShiftInvertedProblem eigen;
  eigen.size = form.size();
  eigen.shift = shift;
  eigen.normK = form.normK();
  eigen.normM = form.normM();
  eigen.applyK = [&](const Eigen::MatrixXd& x, Eigen::MatrixXd& y) { form.applyK(x, y); };
  eigen.applyM = [&](const Eigen::MatrixXd& x, Eigen::MatrixXd& y) { form.applyM(x, y); };
  eigen.solveShifted = [&](const Eigen::MatrixXd& x, Eigen::MatrixXd& y) { form.solveShifted(x, y); };
  eigen.solveLower = [&](const Eigen::MatrixXd& x, Eigen::MatrixXd& y) { form.solveLower(x, y); };
  eigen.solveUpper = [&](const Eigen::MatrixXd& x, Eigen::MatrixXd& y) { form.solveUpper(x, y); };
  if (form.complexForm()) eigen.partner = [&](const Eigen::MatrixXd& x, Eigen::MatrixXd& y) { form.timesI(x, y); };
  solvers::ModalOptions opt;
  opt.numModes = int(std::min<long long>(problem.modesPerNodalDiameter * hm.copies, hm.equations - 1));
  // Blocks of 2. A travelling-wave pair starts from [v, iv] and then needs one solve per
  // block (solveModes' partner): a complex Krylov space of numBlocks vectors, 22 for 5
  // pairs, converged on the built-in sector without a restart (14 and 17 restarted and
  // took more solves). A real form takes 2 per block: 12 blocks for 5 modes (24 solves;
  // 17 blocks took 34).
  opt.blockSize = 2;
  opt.numBlocks = form.complexForm() ? opt.numModes + 12 : opt.numModes + 7;
  {
    // The eigen-solution (Anasazi on Tpetra vectors) and every Tpetra object it returns
    // live and die inside the lock: `result` is declared after it, so goes first.
    const auto trilinos = trilinosSection(worker);
    const auto result = solvers::solveModes(eigen, opt);
    hm.frequenciesHz = result.frequenciesHz;
    for (std::size_t i = 0; i < result.frequenciesHz.size(); ++i) {
      const auto x = result.modes->getData(i);
      hm.shapes.push_back({transform.nodalField(x.getRawPtr(), 0),
                           hm.copies == 2 ? transform.nodalField(x.getRawPtr(), 1) : NodalField()});
    }
    hm.solveSeconds = result.solveSeconds;
    hm.solves = result.operatorApplies;
  }
  hm.seconds = timer.seconds();
  return hm;
}

// A nodal diameter's result as numbers, for the owner rank to broadcast.
std::vector<double> pack(const NodalDiameterModes& hm) {
  std::vector<double> out = {double(hm.nodalDiameter), double(hm.copies), double(hm.equations), hm.seconds,
                             hm.assemblySeconds, hm.factorSeconds, hm.solveSeconds, double(hm.solves),
                             double(hm.rank), double(hm.projected), double(hm.frequenciesHz.size())};
  out.insert(out.end(), hm.frequenciesHz.begin(), hm.frequenciesHz.end());
  // Every real part, then every imaginary part (zero for one copy): the checkpoints' format.
  for (const bool imaginary : {false, true})
    for (std::size_t i = 0; i < hm.shapes.size(); ++i) {
      const auto shape = hm.shapes[i];
      for (const auto& node : imaginary ? shape.imag : shape.real) out.insert(out.end(), node.begin(), node.end());
    }
  return out;
}

NodalDiameterModes unpack(const std::vector<double>& in, mesh::Index numNodes) {
  NodalDiameterModes hm;
  std::size_t at = 0;
  auto next = [&]() { return in.at(at++); };
  hm.nodalDiameter = int(next());
  hm.copies = int(next());
  hm.equations = (long long)next();
  hm.seconds = next();
  hm.assemblySeconds = next();
  hm.factorSeconds = next();
  hm.solveSeconds = next();
  hm.solves = int(next());
  hm.rank = int(next());
  hm.projected = next() != 0.0;
  const std::size_t modes = std::size_t(next());
  for (std::size_t i = 0; i < modes; ++i) hm.frequenciesHz.push_back(next());
  std::vector<ModeShape> shapes(modes);
  for (const bool imaginary : {false, true})
    for (auto& shape : shapes) {
      auto field = NodalField(std::size_t(numNodes));
      for (auto& node : field)
        for (double& v : node) v = next();
      (imaginary ? shape.imag : shape.real) = std::move(field);
    }
  for (auto& shape : shapes) {
    if (hm.copies == 1) shape.imag.clear();
    hm.shapes.push_back(shape);
  }
  return hm;
}

// Everything one nodal diameter's modes depend on (ResultCheckpoints' key).
std::string harmonicModesKey(const mesh::Mesh& mesh, const CyclicSector& sector, const CyclicModalProblem& problem,
                             int k) {
  ContentHash h;
  h.add(std::string("cyclone harmonic modes v1"));
  mesh::addToHash(h, mesh);
  mesh::addNodeSetsToHash(h, mesh, problem.fixedNodeSets);
  h.add(sector.sectors).addAll(std::vector<long long>(sector.left.begin(), sector.left.end()));
  h.addAll(std::vector<long long>(sector.right.begin(), sector.right.end()));
  h.add(sector.axis.point.data(), sizeof(double) * 3).add(sector.axis.direction.data(), sizeof(double) * 3);
  h.add(problem.material.E).add(problem.material.nu).add(problem.material.rho);
  // Only when not the default, so that the default's cached results keep their keys.
  if (problem.material.massQuadrature != fe::MassQuadrature::Exact)
    h.add(std::string("mass quadrature: stiffness rule"));
  h.add(problem.modesPerNodalDiameter).add(problem.shift).add(int(problem.method)).add(k);
  if (const auto* p = problem.prestress.get()) {
    h.add(std::string("prestress")).add(p->speedRpm).add(p->omega).add(int(p->nonlinear));
    h.add(p->axis.point.data(), sizeof(double) * 3).add(p->axis.direction.data(), sizeof(double) * 3);
    for (const auto& u : p->displacement) h.add(u.data(), sizeof(double) * 3);
    for (const auto& s : p->stress) h.add(s.data(), sizeof(double) * std::size_t(s.size()));
  }
  return h.hex();
}

}  // namespace

namespace {

// A solved nodal diameter's shapes put where the problem keeps them while the others are solved.
void keepShapes(NodalDiameterModes& hm, const CyclicModalProblem& problem) {
  if (problem.shapeStorage != CyclicModalProblem::ShapeStorage::ScratchFile) return;
  hm.shapes.moveToScratchFile(problem.scratchDirectory.empty() ? std::filesystem::temp_directory_path().string()
                                                               : problem.scratchDirectory);
}

// A nodal diameter saved by an earlier run under the same inputs (`key`: where its
// result is saved when it is solved now).
std::optional<NodalDiameterModes> readBackModes(const mesh::Mesh& mesh, const CyclicSector& sector,
                                                const CyclicModalProblem& problem, int k, std::string& key, int rank) {
  if (!problem.checkpoints) return std::nullopt;
  key = harmonicModesKey(mesh, sector, problem, k);
  const auto saved = problem.checkpoints->load(key);
  if (!saved) return std::nullopt;
  NodalDiameterModes hm;
  try {
    hm = unpack(*saved, mesh.numNodes());
  } catch (const std::exception&) {  // too short: not this mesh's modes
    return std::nullopt;
  }
  hm.rank = rank;
  if (hm.nodalDiameter != k) return std::nullopt;
  log::info("nodal diameter " + std::to_string(k) + ": " + std::to_string(hm.frequenciesHz.size()) +
            " modes read back from the checkpoint of an earlier run (" + key.substr(0, 8) + ")");
  return hm;
}

// Each nodal diameter's result broadcast by its owner (round robin over the ranks) to
// every rank. A failure on one rank is carried to all of them with its message: the
// others would otherwise wait in the broadcast for a result that never comes.
std::vector<NodalDiameterModes> shareOwnersResults(std::vector<NodalDiameterModes>& mine,
                                                   const std::vector<std::string>& failure,
                                                   const std::vector<int>& nodalDiameters, const mesh::Mesh& mesh,
                                                   const CyclicModalProblem& problem, linalg::CommPtr comm) {
  const int ranks = comm->getSize(), rank = comm->getRank();
  std::vector<NodalDiameterModes> out;
  for (std::size_t i = 0; i < nodalDiameters.size(); ++i) {
    const int owner = int(i % ranks);
    std::string message = owner == rank ? failure[i] : std::string();
    int length = int(message.size());
    Teuchos::broadcast(*comm, owner, &length);
    if (length > 0) {
      message.resize(std::size_t(length));
      Teuchos::broadcast(*comm, owner, length, message.data());
      throw SolverError("nodal diameter " + std::to_string(nodalDiameters[i]) + " (rank " + std::to_string(owner) +
                        "): " + message);
    }
    std::vector<double> buffer = owner == rank ? pack(mine[i]) : std::vector<double>();
    long long size = (long long)buffer.size();
    Teuchos::broadcast(*comm, owner, &size);
    buffer.resize(std::size_t(size));
    Teuchos::broadcast(*comm, owner, int(size), buffer.data());
    out.push_back(owner == rank ? std::move(mine[i]) : unpack(buffer, mesh.numNodes()));
    keepShapes(out.back(), problem);
    if (owner != 0) log::info(describe(out.back(), problem.method));
  }
  return out;
}

}  // namespace

namespace {

// The threads a rank solves its nodal diameters on: `asked`, or for 0 the cores this
// process may run on shared among the ranks (all taken to be on one machine).
int threadsPerRank(int asked, int ranks) {
  if (asked > 0) return asked;
  return std::max(1, usableProcessorCores() / std::max(1, ranks));
}

// The nodal diameters `owned` (indices) solved on `threads` threads, each taking the next
// one left. Every thread but the first starts once the first has factored: its factor's
// size in complex entries (with half again for the factorization's transient and the
// Krylov basis) is what each further thread will hold, and a thread is started only
// while the memory the system has available covers it; a first thread that ends without
// a factor of its own (nodal diameters read back, a free sector's assembled path)
// leaves the others unstarted, its work done. The answers are those of one thread: each nodal
// diameter is solved alone from its own seeded start, whichever thread takes it.
void solveOnThreads(const std::vector<std::size_t>& owned, int threads,
                    const std::function<NodalDiameterModes(std::size_t, NodalDiameterWorker&)>& solveOne,
                    std::vector<NodalDiameterModes>& results, std::vector<std::exception_ptr>& failure) {
  std::mutex trilinos, checkpoints, gate;
  std::condition_variable opened;
  bool open = false;
  double perThreadMb = 0, availableMb = 0;
  std::atomic<std::size_t> next{0};
  std::atomic<bool> failed{false};
  std::exception_ptr outsideAnyNd;  // a failure of a thread itself (under `gate`)
  // factorBytes < 0: nothing measured (the first thread ended without factoring, e.g. a
  // free sector's assembled path): the others are not started.
  auto openGate = [&](double factorBytes) {
    const std::lock_guard<std::mutex> guard(gate);
    if (open) return;
    open = true;
    perThreadMb = factorBytes < 0 ? std::numeric_limits<double>::infinity() : 1.5 * factorBytes / (1024.0 * 1024.0);
    availableMb = availableMemoryMb();
    opened.notify_all();
  };
  auto work = [&](int t) {
    try {
      NodalDiameterWorker worker;
      worker.trilinos = &trilinos;
      worker.checkpoints = &checkpoints;
      if (t == 0) {
        worker.factored = [&](double bytes) { openGate(bytes); };
      } else {
        std::unique_lock<std::mutex> guard(gate);
        opened.wait(guard, [&] { return open; });
        if (failed || next >= owned.size()) return;
        // Each further thread claims its share of what is available, or is not started.
        if (!(availableMb >= perThreadMb)) {
          std::ostringstream msg;
          msg << "nodal diameters: thread " << t + 1 << " not started (";
          if (std::isinf(perThreadMb)) msg << "no factor measured";
          else msg << perThreadMb << " MB needed, " << availableMb << " MB available";
          log::info(msg.str() + ")");
          return;
        }
        availableMb -= perThreadMb;
      }
      for (std::size_t j; !failed && (j = next++) < owned.size();) {
        const std::size_t i = owned[j];
        try {
          results[i] = solveOne(i, worker);
        } catch (...) {
          failure[i] = std::current_exception();
          failed = true;
        }
      }
    } catch (...) {
      const std::lock_guard<std::mutex> guard(gate);
      if (!outsideAnyNd) outsideAnyNd = std::current_exception();
      failed = true;
    }
    if (t == 0) openGate(-1.0);
  };
  log::info("nodal diameters on " + std::to_string(threads) + " threads");
  // Ours are the threads: OpenBLAS's own would oversubscribe the cores. (OpenBLAS built
  // with OpenMP takes each thread's own OpenMP count instead; Debian's is the pthreads build.)
  const SingleThreadedBlas oneBlasThread;
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) {
    try {
      pool.emplace_back(work, t);
    } catch (const std::system_error& e) {  // the system's thread limit: go on with fewer
      log::info(std::string("nodal diameters: ") + std::to_string(pool.size() + 1) + " threads (" + e.what() + ")");
      break;
    }
  }
  work(0);
  for (auto& thread : pool) thread.join();
  if (outsideAnyNd) std::rethrow_exception(outsideAnyNd);
}

}  // namespace

std::vector<NodalDiameterModes> solveCyclicModes(const mesh::Mesh& mesh, const CyclicSector& sector,
                                            const CyclicModalProblem& problem, linalg::CommPtr comm) {
  problem.material.validate("material");
  std::vector<int> nodalDiameters = problem.nodalDiameters;
  if (nodalDiameters.empty())
    for (int k = 0; k <= sector.maxNodalDiameter(); ++k) nodalDiameters.push_back(k);
  for (int k : nodalDiameters) checkNodalDiameter(sector.sectors, k);
  if (problem.modesPerNodalDiameter < 1) throw InputError("modes_per_nd", "must be at least 1");
  if (problem.threads < 0 || problem.threads > 1024)
    throw InputError("threads", std::to_string(problem.threads) + ": use 0 (as many as the cores) or 1..1024");

  std::vector<NodalDiameterModes> out;
  const int ranks = comm->getSize(), rank = comm->getRank();
  if (problem.method == solvers::EigenMethod::Lobpcg) {
    // Distributed operators and preconditioner: every rank works on every nodal diameter.
    for (int k : nodalDiameters) {
      std::string key;
      if (auto hm = readBackModes(mesh, sector, problem, k, key, rank)) {
        out.push_back(std::move(*hm));
        keepShapes(out.back(), problem);
        continue;
      }
      out.push_back(solveAssembled(mesh, sector, k, problem, comm));
      keepShapes(out.back(), problem);
      log::info(describe(out.back(), problem.method));
      if (problem.checkpoints && rank == 0) problem.checkpoints->save(key, pack(out.back()));
    }
    return out;
  }
  // Shift-invert: the element matrices once per speed on every rank, then the nodal
  // diameters spread over the ranks (round robin), each solved on one process and
  // broadcast by its owner; the same answer on any number of ranks.
  const auto matrices = assembleSectorMatrices(mesh, problem.material, problem.prestress.get());
  {
    std::ostringstream msg;
    msg << "sector matrices (every nodal diameter's element work): " << matrices.dofs() << " DOFs, "
        << matrices.nonzeros() << " nonzeros (K and M as lower 3 x 3 blocks on one pattern, " << matrices.bytes() / 1e6
        << " MB), " << matrices.seconds << " s";
    log::info(msg.str());
  }
  const auto serial = Teuchos::rcp(new Teuchos::SerialComm<int>());
  auto solveOne = [&](std::size_t i, NodalDiameterWorker& worker) {
    std::string key;
    std::optional<NodalDiameterModes> saved;
    {
      const auto lock = section(worker.checkpoints);
      saved = readBackModes(mesh, sector, problem, nodalDiameters[i], key, rank);
    }
    if (saved) {
      keepShapes(*saved, problem);
      return std::move(*saved);
    }
    auto solved = solveProjected(mesh, sector, nodalDiameters[i], matrices, problem, worker);
    NodalDiameterModes hm;
    if (solved) {
      hm = std::move(*solved);
    } else {
      const auto trilinos = trilinosSection(worker);
      hm = solveAssembled(mesh, sector, nodalDiameters[i], problem, serial);
    }
    hm.rank = rank;
    releaseFreedMemory();  // the Krylov basis and the solves' work, before the next factor
    if (rank == 0) {
      std::ostringstream memory;
      memory.precision(4);
      memory << "; memory " << currentMemoryMb() << " MB, peak " << peakMemoryMb() << " MB";
      log::info(describe(hm, problem.method) + memory.str());
    }
    if (problem.checkpoints) {
      const auto lock = section(worker.checkpoints);
      problem.checkpoints->save(key, pack(hm));
    }
    keepShapes(hm, problem);
    return hm;
  };
  // This rank's nodal diameters: all of them on one rank, else round robin.
  std::vector<std::size_t> owned;
  for (std::size_t i = 0; i < nodalDiameters.size(); ++i)
    if (int(i % ranks) == rank) owned.push_back(i);
  std::vector<NodalDiameterModes> mine(nodalDiameters.size());
  std::vector<std::exception_ptr> failure(nodalDiameters.size());
  const int threads = int(std::min<std::size_t>(std::size_t(threadsPerRank(problem.threads, ranks)), owned.size()));
  if (threads <= 1) {
    NodalDiameterWorker worker;
    for (std::size_t i : owned) {
      try {
        mine[i] = solveOne(i, worker);
      } catch (...) {
        failure[i] = std::current_exception();
        break;
      }
    }
  } else {
    solveOnThreads(owned, threads, solveOne, mine, failure);
  }
  // On one rank the first failure is thrown as it is; on several its message goes to all.
  std::vector<std::string> messages(nodalDiameters.size());
  for (std::size_t i = 0; i < nodalDiameters.size(); ++i) {
    if (!failure[i]) continue;
    if (ranks == 1) std::rethrow_exception(failure[i]);
    try {
      std::rethrow_exception(failure[i]);
    } catch (const std::exception& e) {
      messages[i] = e.what();
    } catch (...) {
      messages[i] = "unknown failure";
    }
    if (messages[i].empty()) messages[i] = "failed";
  }
  if (ranks == 1) return mine;
  return shareOwnersResults(mine, messages, nodalDiameters, mesh, problem, comm);
}

void writeFrequenciesCsv(const std::string& path, const std::vector<SpeedModes>& speeds) {
  AtomicFile file(path);
  std::ostringstream text;
  text << "rpm,nd,mode,freq_hz\n";
  char line[96];
  for (const auto& speed : speeds)
    for (const auto& hm : speed.nodalDiameters)
      for (std::size_t i = 0; i < hm.frequenciesHz.size(); ++i) {
        std::snprintf(line, sizeof line, "%.10g,%d,%zu,%.12g\n", speed.rpm, hm.nodalDiameter, i + 1, hm.frequenciesHz[i]);
        text << line;
      }
  const std::string bytes = text.str();
  file.write(bytes.data(), bytes.size());
  file.commit();
}

void writeModesExodus(const std::string& path, const mesh::Mesh& mesh, double rpm,
                      const std::vector<NodalDiameterModes>& modes) {
  mesh::ExodusResults r;
  r.nodalNames = {"ux", "uy", "uz", "u_imag_x", "u_imag_y", "u_imag_z"};  // ParaView groups both as vectors
  r.globalNames = {"nd", "mode", "rpm"};
  for (const auto& hm : modes)
    for (std::size_t i = 0; i < hm.frequenciesHz.size(); ++i) {
      mesh::ExodusResults::Step step;
      step.time = hm.frequenciesHz[i];
      step.nodal.assign(6, std::vector<double>(mesh.numNodes()));
      const auto shape = hm.shapes[i];
      for (mesh::Index n = 0; n < mesh.numNodes(); ++n)
        for (int d = 0; d < 3; ++d) {
          step.nodal[d][n] = shape.real[n][d];
          step.nodal[3 + d][n] = shape.imag[n][d];
        }
      step.global = {double(hm.nodalDiameter), double(i + 1), rpm};
      r.steps.push_back(std::move(step));
    }
  mesh::writeExodus(path, mesh, r);
}

int NodalDiameterModes::rigidBodyModes() const {
  if (frequenciesHz.empty()) return 0;
  int count = 0;
  for (double f : frequenciesHz) count += f < 1e-4 * frequenciesHz.back();
  return count;
}

}  // namespace cyclone::cyclic
