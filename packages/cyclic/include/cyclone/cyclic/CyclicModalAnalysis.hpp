#pragma once
// Modes of a cyclic sector for each requested nodal diameter. Shift-invert: the sector's element matrices once per speed
// (SectorMatrices), each nodal diameter projected by its cyclic transform
// (NodalDiameterForm, complex Hermitian for travelling-wave pairs), factored by CHOLMOD
// and solved by Anasazi's block Krylov-Schur; on several MPI ranks the nodal
// diameters are spread over the ranks. LOBPCG + MueLu (no factorization): the
// operators assembled per nodal diameter, distributed over the ranks. Mode shapes are
// mass-normalised over the sector in the real form: sum over the copies of
// u_c^T M u_c = 1.
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "cyclone/core/ResultCheckpoints.hpp"
#include "cyclone/cyclic/CyclicSector.hpp"
#include "cyclone/cyclic/ModeShapes.hpp"
#include "cyclone/cyclic/Prestress.hpp"
#include "cyclone/fe/Assembler.hpp"
#include "cyclone/fe/LinearAlgebra.hpp"
#include "cyclone/fe/Material.hpp"
#include "cyclone/solvers/ModalSolver.hpp"

namespace cyclone::cyclic {

struct CyclicModalProblem {
  fe::IsotropicElastic material;
  std::vector<std::string> fixedNodeSets;
  std::vector<int> nodalDiameters;  ///< empty: all of 0..N/2
  int modesPerNodalDiameter = 6;       ///< distinct frequencies per k (a pair counts once)
  double shift = 0.0;             ///< (rad/s)^2, below the lowest eigenvalue (shift-invert only)
  /// Shift-invert (CHOLMOD) or LOBPCG with MueLu preconditioned by the per-copy
  /// rigid-body near null space (constrained models only).
  solvers::EigenMethod method = solvers::EigenMethod::ShiftInvert;
  /// Prestressed tangent K + K_sigma - K_Omega at this state's speed; null: K alone.
  std::shared_ptr<const PrestressState> prestress;
  /// Each nodal diameter's modes are saved here when solved and read back instead of
  /// solved when they are there under the same inputs (mesh, sector, material, fixed
  /// sets, prestress state, modes, shift, method): a killed sweep resumes per nodal
  /// diameter. None: nothing saved.
  std::shared_ptr<ResultCheckpoints> checkpoints;
  /// Where each solved nodal diameter's shapes are kept while the others are solved: in
  /// an unnamed scratch file (ModeShapes; 70 MB out of the memory peak at 42k DOFs) in
  /// `scratchDirectory` (empty: the system's temporary directory), or in memory.
  enum class ShapeStorage { ScratchFile, Memory } shapeStorage = ShapeStorage::ScratchFile;
  std::string scratchDirectory;
  /// Threads each rank solves its nodal diameters on (shift-invert): each thread holds
  /// its own factor, so the memory of the nodal-diameter stage grows with them; a thread
  /// is started only while the system's available memory covers one more factor. 0:
  /// the cores this process may use shared among the ranks (taken to be on one
  /// machine). The answers do not depend on it. LOBPCG always uses one.
  int threads = 1;
};

struct NodalDiameterModes {
  int nodalDiameter = 0;
  int copies = 1;
  long long equations = 0;
  double seconds = 0;
  /// Where the time went: operators (projected from the sector's matrices, or assembled),
  /// factorization (or preconditioner), eigen-solution; shifted solves (or LOBPCG iterations).
  double assemblySeconds = 0, factorSeconds = 0, solveSeconds = 0;
  int solves = 0;
  bool projected = false;
  int rank = 0;  ///< the MPI rank that solved it
  std::vector<double> frequenciesHz;  ///< ascending; each member of a pair listed
  /// Nodal shapes per mode: real part (copy a) and imaginary part (copy b; zero when single).
  ModeShapes shapes;
  /// The rigid-body modes among frequenciesHz: those below 1e-4 of the highest computed
  /// (an unheld sector's, at round-off above zero).
  int rigidBodyModes() const;
};

/// The real-form sector operators at one nodal diameter k: the assembler of the
/// cyclic transform (its unknowns), the tangent K (K + K_sigma - K_Omega when a
/// prestress is given) and M. What solveCyclicModes and the reduced models share.
struct NodalDiameterOperators {
  int nodalDiameter = 0;
  int copies = 1;
  std::unique_ptr<fe::Assembler> assembler;
  Teuchos::RCP<linalg::Matrix> K, M;
};

/// Checks k (InputError) and assembles K_k, M_k on the cyclic transform with `fixedNodeSets` held.
NodalDiameterOperators assembleNodalDiameterOperators(const mesh::Mesh& mesh, const CyclicSector& sector, int k,
                                            const fe::IsotropicElastic& material,
                                            const std::vector<std::string>& fixedNodeSets,
                                            const PrestressState* prestress, linalg::CommPtr comm);

/// The lowest `distinctModes` x copies modes of K_k, M_k (a pair counts once) by
/// shift-invert at `shift` (ModalOptions::automaticShift() allowed) or LOBPCG + MueLu.
solvers::ModalResult solveNodalDiameterModes(const NodalDiameterOperators& operators, int distinctModes, double shift,
                                        solvers::EigenMethod method = solvers::EigenMethod::ShiftInvert);

std::vector<NodalDiameterModes> solveCyclicModes(const mesh::Mesh& mesh, const CyclicSector& sector,
                                            const CyclicModalProblem& problem, linalg::CommPtr comm);

/// The modes of every nodal diameter at one speed.
struct SpeedModes {
  double rpm = 0;
  std::vector<NodalDiameterModes> nodalDiameters;
};

/// frequencies.csv: rpm,nd,mode,freq_hz (mode from 1 within each nd). Atomic.
void writeFrequenciesCsv(const std::string& path, const std::vector<SpeedModes>& speeds);
/// Modes in Exodus: one step per mode (time = frequency in Hz), nodal ux,uy,uz (real
/// part) and u_imag_x,u_imag_y,u_imag_z (ParaView: vectors u and u_imag), globals nd, mode, rpm. Atomic.
void writeModesExodus(const std::string& path, const mesh::Mesh& mesh, double rpm,
                      const std::vector<NodalDiameterModes>& modes);

}  // namespace cyclone::cyclic
