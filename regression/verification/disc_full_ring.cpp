// Verification (slow): the friction-damped forced response of the built-in
// shrouded disc from its cyclic sector (makeDiscForcedResponse over the full-FE
// compliance per nodal diameter, buildDiscReducedModels kind full_fe) against
// the full ring with no cyclic reduction:
//   - the ring FE model: the sector replicated N times (cyclic::replicateSector,
//     disc side faces merged, shroud side faces left apart), bore fixed, global
//     x, y, z DOFs, assembled and factored as one model;
//   - its exact compliance at every sector's retained nodes (shroud contact nodes
//     and mid-blade node) by a sparse complex LU of (1 + i eta) K - w^2 M per
//     frequency, the mean (harmonic 0) from one real factorization of K, wrapped as
//     a non-cyclic hbm::ReceptanceModel;
//   - a friction3d element between every right-face contact node of sector j and
//     its left-face partner of sector j+1 (frame: sector 0's rotated by Q^j), and
//     the excitation at every sector's mid-blade node, delayed by j 2 pi EO / N.
// The frequencies come from cheap hybrid models of the sector (20 modes and the
// static correction): the free and stuck resonances (disc::estimateResonance), the
// preload, and the friction-damped peak of the hybrid sector's curve. Both full-FE
// sides are then solved by Newton at three fixed frequencies (below, at and above
// that peak; one LU per frequency on each side, the operator cached), and sector j of the ring is
// compared with the sector solution delayed by j 2 pi EO / N per harmonic and
// rotated by Q^j into the global frame. The contacts slip over part of the
// period at the peak (printed and asserted), so the check is nonlinear.
//
// N: CYCLONE_DISC_RING_SECTORS overrides the default (8); 24 is the
// built-in disc's own count.
#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <string>

#include "cyclone/continuation/NewtonSolve.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/cyclic/FullRing.hpp"
#include "cyclone/fe/Assembler.hpp"
#include "cyclone/fe/DofMap.hpp"
#include "cyclone/hbm/CondensedSystem.hpp"
#include "cyclone/hbm/FrictionContact.hpp"
#include "cyclone/mesh/ShroudedSectorGenerator.hpp"
#include "cyclone/disc/DiscHarmonicBalance.hpp"
#include "cyclone/solvers/DirectSolver.hpp"

using namespace cyclone;

namespace {

double peakMemoryGb() {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("VmHWM:", 0) == 0) return std::atof(line.c_str() + 6) / (1024.0 * 1024.0);
  return 0;
}

constexpr int kContactPairs = 6;

int ringSectors() {
  const char* env = std::getenv("CYCLONE_DISC_RING_SECTORS");
  if (!env) return 8;
  char* end = nullptr;
  const long n = std::strtol(env, &end, 10);
  if (end == env || *end != '\0' || n < 3 || n > 240)
    throw InputError("CYCLONE_DISC_RING_SECTORS", std::string("'") + env +
                                                      "' is not a number of sectors in 3..240 (the ring needs at "
                                                      "least 3 sectors for a travelling wave with EO 1 < N/2)");
  return int(n);
}

/// The ring FE model's compliance at the retained DOFs (ring DOF r = global equation
/// equations[r]): a complex LU per frequency, the mean from one CHOLMOD factorization.
class RingReceptance final : public hbm::ReceptanceModel {
public:
  RingReceptance(Teuchos::RCP<linalg::Matrix> K, Teuchos::RCP<linalg::Matrix> M, double eta,
                 std::vector<long long> equations)
      : K_(std::move(K)), M_(std::move(M)), eta_(eta), equations_(std::move(equations)) {
    Timer t;
    const solvers::DirectSolver chol(*K_);
    mean_.resize(numDofs(), numDofs());
    solveBlocks([&](const linalg::MultiVector& b, linalg::MultiVector& x) { chol.solve(b, x); },
                [&](const linalg::MultiVector& x, int c0) {
                  for (std::size_t c = 0; c < x.getNumVectors(); ++c) mean_.col(c0 + long(c)) = retained(x, c);
                });
    mean_ = 0.5 * (mean_ + mean_.transpose()).eval();
    std::printf("ring mean compliance (CHOLMOD, %d right-hand sides): %.1f s\n", numDofs(), t.seconds());
  }
  int numDofs() const override { return int(equations_.size()); }
  int sectors() const override { return 1; }
  Eigen::MatrixXd meanCompliance() const override { return mean_; }
  Eigen::MatrixXcd compliance(double frequency, long phaseIndex) const override {
    if (phaseIndex != 0) throw Error("the ring is not cyclic: phase index " + std::to_string(phaseIndex));
    const auto it = cache_.find(frequency);
    if (it != cache_.end()) return it->second;
    Timer t;
    const solvers::ComplexDirectSolver lu(*K_, {1.0, eta_}, *M_, -frequency * frequency);
    const double factor = t.seconds();
    Eigen::MatrixXcd A(numDofs(), numDofs());
    solveBlocks(
        [&](const linalg::MultiVector& b, linalg::MultiVector& x) {
          linalg::MultiVector xi(b.getMap(), b.getNumVectors());
          lu.solve(b, x, xi);
          imag_ = Teuchos::rcp(new linalg::MultiVector(xi, Teuchos::Copy));
        },
        [&](const linalg::MultiVector& x, int c0) {
          for (std::size_t c = 0; c < x.getNumVectors(); ++c) {
            A.col(c0 + long(c)).real() = retained(x, c);
            A.col(c0 + long(c)).imag() = retained(*imag_, c);
          }
        });
    std::printf("  ring compliance at %.2f Hz: complex LU %.1f s, %d solves %.1f s\n", frequency / (2 * M_PI), factor,
                numDofs(), t.seconds() - factor);
    std::fflush(stdout);
    cache_[frequency] = A;
    return A;
  }

private:
  template <class Solve, class Take>
  void solveBlocks(Solve solve, Take take) const {
    const int block = 96;
    for (int c0 = 0; c0 < numDofs(); c0 += block) {
      const int nb = std::min(block, numDofs() - c0);
      linalg::MultiVector b(K_->getRowMap(), std::size_t(nb)), x(K_->getRowMap(), std::size_t(nb));
      for (int c = 0; c < nb; ++c)
        if (K_->getRowMap()->isNodeGlobalElement(equations_[c0 + c]))
          b.replaceGlobalValue(equations_[c0 + c], std::size_t(c), 1.0);
      solve(b, x);
      take(x, c0);
    }
  }
  Eigen::VectorXd retained(const linalg::MultiVector& x, std::size_t column) const {
    const auto data = x.getData(column);
    const auto& map = *x.getMap();
    Eigen::VectorXd out(numDofs());
    for (int r = 0; r < numDofs(); ++r) out(r) = data[map.getLocalElement(equations_[r])];
    return out;
  }
  Teuchos::RCP<linalg::Matrix> K_, M_;
  double eta_;
  std::vector<long long> equations_;
  Eigen::MatrixXd mean_;
  mutable std::map<double, Eigen::MatrixXcd> cache_;
  mutable Teuchos::RCP<linalg::MultiVector> imag_;
};

/// Contact pair p of a system: the DOF blocks (3 each) of its two nodes and its frame.
struct Pair {
  int right, left;  // first DOF of the right node (this sector) and of the left node (the next)
  Eigen::Matrix3d E;
};

/// The relative displacement coefficients (nc x 3) of a pair: w = E^T (u_left - u_right).
Eigen::MatrixXd relative(const Eigen::VectorXd& X, int nc, const Pair& p) {
  Eigen::MatrixXd U(nc, 3);
  for (int d = 0; d < 3; ++d)
    U.col(d) = X.segment(long(p.left + d) * nc, nc) - X.segment(long(p.right + d) * nc, nc);
  return U * p.E;  // column c: coordinate c
}

/// The fractions of the period a contact slips (|f_t| at mu N with N > 0) and is
/// open (N <= 0), from the element's own force samples.
std::pair<double, double> slipAndOpen(const hbm::FrictionContact& e, const hbm::Aft& aft, const Eigen::MatrixXd& Wc) {
  const int ns = aft.numSamples();
  const Eigen::MatrixXd f = e.forceSamples(aft, Wc, 0.0);
  const auto& p = e.parameters();
  int slip = 0, open = 0;
  for (int i = 0; i < ns; ++i) {
    const double normal = f(i, 2);
    if (normal <= 0) ++open;
    else if (f.row(i).head(2).norm() >= (1 - 1e-9) * p.mu * normal) ++slip;
  }
  return {double(slip) / ns, double(open) / ns};
}

/// One more Newton step's length from a converged point: the a posteriori error estimate.
double newtonStep(const continuation::ContinuationProblem& problem, const Eigen::VectorXd& X, double omega) {
  Eigen::VectorXd R;
  Eigen::MatrixXd J;
  problem.residual(X, omega, R);
  problem.jacobian(X, omega, J);
  return J.partialPivLu().solve(R).norm();
}

/// Newton at the fixed frequency w from rest (its first step is the stuck response); where
/// it stagnates at a stick-slip kink, the excitation is raised from 5% to 100% of its
/// value in 20 steps at w (Newton on the force-scale problem from the previous scale, the
/// first from the stuck response), then polished on the frequency problem. The iterations
/// count all Newton iterations; `homotopy` reports whether the second path was needed.
struct Solved : continuation::NewtonResult {
  bool homotopy = false;
};
Solved solveAt(const hbm::HarmonicBalanceSystem& system, const continuation::ContinuationProblem& problem, double w,
               double tol, Eigen::VectorXd& X) {
  Solved out;
  X = Eigen::VectorXd::Zero(system.numDofs() * system.numCoefficients());
  static_cast<continuation::NewtonResult&>(out) = continuation::solveNewton(problem, X, w, tol);
  if (out.converged) return out;
  out.homotopy = true;
  int iterations = out.iterations;
  const auto scaled = response::continuationProblem(system, response::ForcedResponseSetup::Parameter::ForceScale, w);
  X = system.linearizedSolution(w, 0.05);
  for (int i = 1; i <= 20; ++i) {
    const auto r = continuation::solveNewton(scaled, X, 0.05 * i, tol);
    iterations += r.iterations;
    if (!r.converged) {
      static_cast<continuation::NewtonResult&>(out) = r;
      out.iterations = iterations;
      return out;
    }
  }
  static_cast<continuation::NewtonResult&>(out) = continuation::solveNewton(problem, X, w, tol);
  out.iterations += iterations;
  return out;
}


/// Contact at a few node pairs spread over the shroud faces (farthest-point choice
/// among the generator's pairs, the same indices on both faces): the coarse mesh has
/// 43 pairs per face, and the ring's dense Newton system grows as (N x retained DOFs)^3.
/// The chosen pairs become the node sets ring_contact_left and ring_contact_right.
void chooseRingContacts(mesh::Mesh& mesh) {
  const auto& L = mesh.nodeSet("shroud_contact_left");
  const auto& R = mesh.nodeSet("shroud_contact_right");
  ASSERT_EQ(L.size(), R.size());
  ASSERT_GE(int(L.size()), kContactPairs) << "fewer shroud contact pairs than asked for";
  auto at = [&](std::size_t i) {
    const auto& c = mesh.coords[L[i]];
    return Eigen::Vector3d(c[0], c[1], c[2]);
  };
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < L.size(); ++i) centre += at(i) / double(L.size());
  std::vector<double> dist(L.size());
  for (std::size_t i = 0; i < L.size(); ++i) dist[i] = (at(i) - centre).norm();
  std::vector<std::size_t> chosen{std::size_t(std::min_element(dist.begin(), dist.end()) - dist.begin())};
  for (std::size_t i = 0; i < L.size(); ++i) dist[i] = (at(i) - at(chosen[0])).norm();  // to the chosen set
  while (int(chosen.size()) < kContactPairs) {
    chosen.push_back(std::size_t(std::max_element(dist.begin(), dist.end()) - dist.begin()));
    for (std::size_t i = 0; i < L.size(); ++i) dist[i] = std::min(dist[i], (at(i) - at(chosen.back())).norm());
  }
  std::vector<mesh::Index> left, right;
  for (auto i : chosen) left.push_back(L[i]), right.push_back(R[i]);
  mesh.nodeSets["ring_contact_left"] = left;
  mesh.nodeSets["ring_contact_right"] = right;
}

/// The hybrid models' spec of the cyclic side (cantilever, rpm 0, 20 modes).
disc::DiscModelSpec hybridModelSpec(int N) {
  disc::DiscModelSpec modelSpec;
  modelSpec.sectors = N;
  modelSpec.kind = disc::ReducedModelKind::Hybrid;
  modelSpec.prestress = cyclic::PrestressKind::None;
  modelSpec.rpm = 0;
  modelSpec.modes = 20;
  modelSpec.lossFactor = 0.006;
  modelSpec.retainedNodeSets = {"ring_contact_left", "ring_contact_right", "mid_blade"};
  return modelSpec;
}

/// The sector's forced response: engine order EO, harmonics 0 and 1, friction at the ring's
/// contact pairs (preload to be calibrated), unit excitation.
disc::DiscResponseSpec sectorResponseSpec(int EO) {
  disc::DiscResponseSpec responseSpec;
  responseSpec.engineOrder = EO;
  responseSpec.harmonics = {0, 1};
  responseSpec.contact.leftSet = "ring_contact_left", responseSpec.contact.rightSet = "ring_contact_right";
  responseSpec.contact.law = disc::ShroudContactSpec::Law::PerPair;  // as the full ring's contacts
  responseSpec.contact.kn = responseSpec.contact.kt = 1e4;
  responseSpec.contact.mu = 0.4;
  responseSpec.contact.preload = 1.0;  // recalibrated below
  responseSpec.excitation.amplitude = 1.0;
  return responseSpec;
}

/// The sector's models per nodal diameter: the hybrid ones (modelSpec as given), then the
/// full-FE ones (modelSpec switched to them), on the same retained nodes.
struct SectorModels {
  disc::DiscReducedModels hybrid, models;
};
void buildSectorModels(const mesh::Mesh& mesh, disc::DiscModelSpec& modelSpec, const std::vector<int>& diameters,
                       const linalg::CommPtr& comm, SectorModels& out) {
  const int N = modelSpec.sectors;
  auto& hybrid = out.hybrid;
  auto& models = out.models;
  Timer t;
  hybrid = disc::buildDiscReducedModels(mesh, modelSpec, diameters, "", comm);
  const double tHybrid = t.seconds();
  modelSpec.kind = disc::ReducedModelKind::FullFe;
  modelSpec.modes = 3;  // natural frequencies only for the log line; the model is the FE compliance
  t.restart();
  models = disc::buildDiscReducedModels(mesh, modelSpec, diameters, "", comm);
  const double tModels = t.seconds();
  ASSERT_EQ(hybrid.retainedNodes, models.retainedNodes);
  const int n = int(3 * models.retainedNodes.size());
  std::printf("N = %d sectors; sector: %lld nodes, %d retained DOFs; models per ND (", N, (long long)mesh.numNodes(), n);
  for (const auto& [k, m] : models.models) std::printf(" %d", k);
  std::printf(" ): hybrid %.1f s, full FE %.1f s\n", tHybrid, tModels);
}

/// The sector's retained DOFs (3 per retained node, x, y, z) and contact geometry, as
/// both sides read them.
struct Layout {
  int N, n, nc;  // sectors, retained DOFs per sector, coefficients per DOF
  const hbm::HarmonicSet& set;
  Eigen::Matrix3d Q, E;  // the sector rotation and the shroud contact frame
  const std::vector<mesh::Index>& leftSet;
  const std::vector<mesh::Index>& rightSet;
  const std::vector<mesh::Index>& retainedNodes;
  int indexOf(mesh::Index node) const {
    return int(std::find(retainedNodes.begin(), retainedNodes.end(), node) - retainedNodes.begin());
  }
};

/// The contact preload: mu N0 = the median tangential force amplitude of the stuck
/// (linearised) response at its resonance, so part of the contacts slip there.
void calibratePreload(const hbm::HarmonicBalanceSystem& s, const Layout& layout,
                      const disc::ResonanceEstimate& resonance, double tResonance,
                      disc::DiscResponseSpec& responseSpec) {
  const int nc = layout.nc;
  const auto& set = layout.set;
  const Eigen::Matrix3d& Q = layout.Q;
  const Eigen::Matrix3d& E = layout.E;
  const Eigen::VectorXd X = s.linearizedSolution(2 * M_PI * resonance.stuckHz);
  const Eigen::MatrixXd S = s.nextSectorMap();
  std::vector<double> forces;
  for (std::size_t i = 0; i < layout.leftSet.size(); ++i) {
    // w = E^T (Q u_next(left) - u(right)), u_next = S u (per DOF).
    Eigen::MatrixXd U(nc, 3);
    const int r = 3 * layout.indexOf(layout.rightSet[i]), l = 3 * layout.indexOf(layout.leftSet[i]);
    Eigen::MatrixXd next(nc, 3);
    for (int d = 0; d < 3; ++d) next.col(d) = S * X.segment(long(l + d) * nc, nc);
    for (int d = 0; d < 3; ++d) U.col(d) = -X.segment(long(r + d) * nc, nc);
    U += next * Q.transpose();
    const Eigen::MatrixXd w = U * E;
    const int c1 = set.cosIndex(1), s1 = set.sinIndex(1);
    forces.push_back(responseSpec.contact.kt * std::hypot(w.row(c1).head(2).norm(), w.row(s1).head(2).norm()));
  }
  std::sort(forces.begin(), forces.end());
  responseSpec.contact.preload = forces[forces.size() / 2] / responseSpec.contact.mu;
  std::printf("resonance of ND %d (hybrid): %.2f Hz shroud free, %.2f Hz stuck; stuck tangential force amplitudes "
              "%.3g..%.3g N: preload N0 = %.4g N (%.1f s)\n",
              resonance.nodalDiameter, resonance.freeHz, resonance.stuckHz, forces.front(), forces.back(),
              responseSpec.contact.preload, tResonance);
}

/// The friction-damped peak on the hybrid sector's curve over f0..f1 (Newton from the
/// previous point): its frequency in peakHz.
void findHybridPeak(const mesh::Mesh& mesh, const disc::DiscReducedModels& hybrid,
                    const disc::DiscResponseSpec& responseSpec, double f0, double f1, double& peakHz) {
  double peak = -1;
  auto hybridSpec = responseSpec;
  hybridSpec.condensed = true;  // the product's path: only the output DOF is read
  auto hybridSetup = disc::makeDiscForcedResponse(mesh, hybrid, hybridSpec);
  auto& hs = *hybridSetup.system;
  const auto problem = response::continuationProblem(hs, response::ForcedResponseSetup::Parameter::Omega);
  const int steps = 60;
  Eigen::VectorXd X = hs.linearizedSolution(2 * M_PI * f0);
  Timer t;
  int skipped = 0;  // points where Newton stagnates at a stick-slip kink from every start (they only locate the peak)
  for (int i = 0; i <= steps; ++i) {
    const double f = f0 + (f1 - f0) * i / steps, w = 2 * M_PI * f;
    Eigen::VectorXd Y = X;
    bool ok = continuation::solveNewton(problem, Y, w).converged;
    if (!ok) Y = hs.linearizedSolution(w), ok = continuation::solveNewton(problem, Y, w).converged;
    if (!ok) Y = Eigen::VectorXd::Zero(X.size()), ok = continuation::solveNewton(problem, Y, w).converged;
    if (!ok) {
      ++skipped;
      continue;
    }
    X = Y;
    const double a = hs.amplitude(X, hybridSetup.outputDofs.front(), 1);
    if (a > peak) peak = a, peakHz = f;
  }
  std::printf("hybrid sector sweep %.1f..%.1f Hz (%d points, %d without a converged Newton, %.1f s): friction-damped "
              "peak %.4g at %.2f Hz\n",
              f0, f1, steps + 1, skipped, t.seconds(), peak, peakHz);
  ASSERT_LE(skipped, steps / 4) << "the hybrid sweep lost too many points to locate the peak";
  ASSERT_GT(peakHz, f0);
  ASSERT_LT(peakHz, f1);
}

/// The condensed sector (hbm/CondensedSystem.hpp: the contacts' relative displacements
/// and the excited and output DOFs), its retained DOFs recovered from its forces.
hbm::CondensedSystem condenseSector(const hbm::HarmonicBalanceSystem& sector, int outDof, int nc) {
  std::vector<int> kept{outDof};
  for (int r = 0; r < sector.numDofs(); ++r)
    if (sector.excitation().segment(long(r) * nc, nc).squaredNorm() > 0) kept.push_back(r);
  auto condensed = hbm::condenseOntoElements(sector, kept);
  std::printf("condensed sector: %d coordinates for %d retained DOFs\n", condensed.system->numDofs(), sector.numDofs());
  return condensed;
}

/// The ring FE model: its matrices, its retained equations, the rotations Q^j of its
/// sectors and its contact pairs.
struct RingModel {
  Teuchos::RCP<linalg::Matrix> K, M;
  std::vector<long long> equations;
  std::vector<Eigen::Matrix3d> Qj;
  std::vector<Pair> pairs;
};
void buildRing(const mesh::Mesh& mesh, const disc::DiscReducedModels& models, const disc::DiscModelSpec& modelSpec,
               const Layout& layout, double tipRadius, const linalg::CommPtr& comm, RingModel& out) {
  const int N = layout.N, n = layout.n;
  const auto& leftSet = layout.leftSet;
  const auto& rightSet = layout.rightSet;
  Timer t;
  const auto ring = cyclic::replicateSector(mesh, models.sector);
  fe::DofMap dofs(ring.mesh.numNodes());
  dofs.constrain(ring.mesh.nodeSet("bore"));
  dofs.finalize();
  const fe::Assembler assembler(ring.mesh, dofs, comm);
  out.K = assembler.stiffness(modelSpec.material);
  out.M = assembler.mass(modelSpec.material);
  std::printf("ring: %lld nodes, %lld free DOFs, assembled in %.1f s\n", (long long)ring.mesh.numNodes(),
              (long long)dofs.numFree(), t.seconds());
  // Retained ring DOFs: sector j's retained nodes in the cyclic order, x, y, z global.
  std::vector<long long>& equations = out.equations;
  std::vector<char> used(ring.mesh.numNodes(), 0);
  for (int j = 0; j < N; ++j)
    for (auto node : models.retainedNodes) {
      const auto rn = ring.ringNode[j][node];
      if (used[rn]++) throw Error("retained node " + std::to_string(node) + " is shared between ring sectors");
      for (int d = 0; d < 3; ++d) {
        const auto eq = dofs.equation(rn, d);
        if (eq < 0) throw Error("a retained node is fixed");
        equations.push_back(eq);
      }
    }
  const int nr = int(equations.size());
  ASSERT_EQ(nr, N * n);
  std::vector<Eigen::Matrix3d>& Qj = out.Qj;
  Qj.assign(N, Eigen::Matrix3d::Identity());
  for (int j = 1; j < N; ++j) Qj[j] = layout.Q * Qj[j - 1];
  // Contact pairs of the ring: right node of sector j, left node of sector j + 1, which
  // must touch in the ring mesh (the shroud faces are not merged).
  for (int j = 0; j < N; ++j)
    for (std::size_t i = 0; i < leftSet.size(); ++i) {
      Pair p{j * n + 3 * layout.indexOf(rightSet[i]), ((j + 1) % N) * n + 3 * layout.indexOf(leftSet[i]),
             Qj[j] * layout.E};
      const auto& a = ring.mesh.coords[ring.ringNode[j][rightSet[i]]];
      const auto& b = ring.mesh.coords[ring.ringNode[(j + 1) % N][leftSet[i]]];
      const double gap = std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
      ASSERT_LT(gap, 1e-6 * tipRadius) << "ring contact pair " << i << " of sector " << j << " apart";
      out.pairs.push_back(p);
    }
}

/// The ring's harmonic balance system over its exact compliance: a friction3d element
/// per contact pair, the excitation at every sector's mid-blade node delayed by j a.
struct RingSystem {
  std::unique_ptr<hbm::HarmonicBalanceSystem> system;
  std::shared_ptr<hbm::FrictionContact> contact;
};
RingSystem buildRingSystem(const RingModel& ring, const mesh::Mesh& mesh, const disc::DiscModelSpec& modelSpec,
                           const disc::DiscResponseSpec& responseSpec, const Layout& layout, double a, int samples) {
  const int N = layout.N, n = layout.n, nr = int(ring.equations.size());
  auto receptance = std::make_shared<RingReceptance>(ring.K, ring.M, modelSpec.lossFactor, ring.equations);
  auto ringSystem = std::make_unique<hbm::HarmonicBalanceSystem>(receptance, layout.set, samples);
  ringSystem->useDynamicStiffness(true);
  hbm::FrictionContactParameters cp;
  cp.tangentialDirections = 2, cp.kn = responseSpec.contact.kn, cp.kt = responseSpec.contact.kt;
  cp.mu = responseSpec.contact.mu, cp.preload = responseSpec.contact.preload;
  const auto contact = std::make_shared<hbm::FrictionContact>(cp);
  for (const auto& p : ring.pairs) {
    Eigen::MatrixXd W = Eigen::MatrixXd::Zero(nr, 3);
    W.middleRows(p.right, 3) = -p.E;
    W.middleRows(p.left, 3) = p.E;
    ringSystem->addElement(contact, W);
  }
  const Eigen::Vector3d d = responseSpec.excitation.direction.normalized();
  for (int j = 0; j < N; ++j)
    for (auto node : mesh.nodeSet(responseSpec.excitation.nodeSet)) {
      const Eigen::Vector3d dj = ring.Qj[j] * d * responseSpec.excitation.amplitude;
      for (int c = 0; c < 3; ++c)
        if (dj(c) != 0)
          ringSystem->addExcitation(j * n + 3 * layout.indexOf(node) + c, 1, dj(c) * std::cos(j * a),
                                    dj(c) * std::sin(j * a));
    }
  return {std::move(ringSystem), contact};
}

/// Sector solution -> ring: harmonic h of sector j delayed by h j a, vectors rotated by Q^j.
struct SectorToRing {
  const Layout& layout;
  const std::vector<Eigen::Matrix3d>& Qj;
  double a;
  int nr;
  Eigen::VectorXd operator()(const Eigen::VectorXd& Xs) const {
    const int N = layout.N, n = layout.n, nc = layout.nc;
    const auto& set = layout.set;
    Eigen::VectorXd out(long(nr) * nc);
    for (int j = 0; j < N; ++j)
      for (int node = 0; node < n / 3; ++node) {
        Eigen::MatrixXd V(3, nc);  // local vector per coefficient
        for (int c = 0; c < 3; ++c) V.row(c) = Xs.segment(long(3 * node + c) * nc, nc).transpose();
        Eigen::MatrixXd Vp = V;
        for (int h : set.harmonics()) {
          if (h == 0) continue;
          const int ic = set.cosIndex(h), is = set.sinIndex(h);
          const double ph = h * j * a;
          Vp.col(ic) = std::cos(ph) * V.col(ic) - std::sin(ph) * V.col(is);
          Vp.col(is) = std::sin(ph) * V.col(ic) + std::cos(ph) * V.col(is);
        }
        const Eigen::MatrixXd G = Qj[j] * Vp;
        for (int c = 0; c < 3; ++c) out.segment(long(j * n + 3 * node + c) * nc, nc) = G.row(c).transpose();
      }
    return out;
  }
};

/// What the comparison at one frequency works on: the full-FE sector, its condensed form,
/// the ring, the ring's contacts and the sector-to-ring map.
struct Comparison {
  const hbm::HarmonicBalanceSystem& sector;
  const continuation::ContinuationProblem& sectorProblem;
  int outDof;
  const hbm::CondensedSystem& condensed;
  const continuation::ContinuationProblem& condensedProblem;
  const hbm::HarmonicBalanceSystem& ring;
  const continuation::ContinuationProblem& ringProblem;
  const std::vector<Pair>& ringPairs;
  const hbm::FrictionContact& contact;
  const SectorToRing& expand;
  double tol, peakHz;
};

/// The worst differences over the frequencies, and how many ring contacts slip at the peak.
struct Summary {
  double worst = 0;
  int slippingAtPeak = 0;
  double worstCondensed = 0;  // the condensed sector solved from its own start, against the ring
};

/// The ring at w, from rest (Xr), independently of the sector's solution Xs; fromSector
/// tells whether it had to start from the expanded sector solution instead.
Solved solveRing(const Comparison& cmp, double w, const Eigen::VectorXd& Xs, Eigen::VectorXd& Xr, bool& fromSector) {
  const int N = cmp.expand.layout.N, n = cmp.expand.layout.n, nc = cmp.expand.layout.nc, nr = cmp.expand.nr;
  const double tol = cmp.tol;
  const auto& ringProblem = cmp.ringProblem;
  auto rr = solveAt(cmp.ring, ringProblem, w, tol, Xr);
  // Where both paths stagnate (48 contacts: many kinks), Newton on the ring's equations
  // from the expanded sector solution: then the evidence is the ring's residual there
  // (printed) and the distance Newton moves it (err), not an independent start.
  fromSector = !rr.converged;
  if (fromSector) {
    std::printf("  ring Newton from rest and by force homotopy stagnated (residual %.1e): from the sector's solution\n",
                rr.residualNorm);
    Xr = cmp.expand(Xs);
    Eigen::VectorXd R0;
    ringProblem.residual(Xr, w, R0);
    std::printf("  ring residual at the expanded sector solution %.2e; per coefficient:", R0.norm());
    for (int c = 0; c < nc; ++c) {
      double sum = 0;
      for (int r = 0; r < nr; ++r) sum += R0(long(r) * nc + c) * R0(long(r) * nc + c);
      std::printf(" %.2e", std::sqrt(sum));
    }
    std::printf("; per sector:");
    for (int j = 0; j < N; ++j) std::printf(" %.2e", R0.segment(long(j) * n * nc, long(n) * nc).norm());
    std::printf("\n");
    std::fflush(stdout);
    static_cast<continuation::NewtonResult&>(rr) = continuation::solveNewton(ringProblem, Xr, w, tol);
  }
  return rr;
}

/// Slip: every ring contact over its settled period (how many slip, how many open, and
/// the longest slip as a fraction of the period).
struct RingSlip {
  int slipping = 0, opening = 0;
  double slipFraction = 0;
};
RingSlip ringSlip(const Comparison& cmp, const Eigen::VectorXd& Xr) {
  RingSlip out;
  for (const auto& p : cmp.ringPairs) {
    const auto [slip, open] = slipAndOpen(cmp.contact, cmp.ring.aft(), relative(Xr, cmp.expand.layout.nc, p));
    out.slipping += slip > 0, out.opening += open > 0;
    out.slipFraction = std::max(out.slipFraction, slip);
  }
  return out;
}

/// The condensed sector at f, solved from its own start, against the ring (Xr) and the
/// full sector (Xs).
void compareCondensed(const Comparison& cmp, double f, const Eigen::VectorXd& Xs, const Eigen::VectorXd& Xr,
                      Summary& summary) {
  const auto& sector = cmp.sector;
  const auto& condensed = cmp.condensed;
  const auto& condensedProblem = cmp.condensedProblem;
  const int nc = cmp.expand.layout.nc;
  const double w = 2 * M_PI * f, tol = cmp.tol;
  Timer tf;
  Eigen::VectorXd Xq;
  const auto rq = solveAt(*condensed.system, condensedProblem, w, tol, Xq);
  EXPECT_TRUE(rq.converged) << "condensed sector Newton at " << f << " Hz (residual " << rq.residualNorm << ")";
  if (!rq.converged) return;
  const Eigen::VectorXd Xqs = hbm::expandToAllDofs(sector, condensed, Xq, w);
  const double errCondensed = (cmp.expand(Xqs) - Xr).norm() / Xr.norm(), errForms = (Xqs - Xs).norm() / Xs.norm();
  const double stepCondensed = newtonStep(condensedProblem, Xq, w) / Xq.norm();
  // The same equations: the full sector's solution, in the condensed coordinates, solves
  // the condensed equations to the Newton tolerance.
  Eigen::VectorXd Qs(condensed.system->numUnknowns()), Rq;
  {
    const Eigen::Map<const Eigen::MatrixXd> Xm(Xs.data(), nc, sector.numDofs());
    for (std::size_t i = 0; i < condensed.keptDofs.size(); ++i) Qs.segment(long(i) * nc, nc) = Xm.col(condensed.keptDofs[i]);
    for (std::size_t e = 0; e < sector.elements().size(); ++e) {
      const auto& el = sector.elements()[e];
      Eigen::MatrixXd wq = Xm * el.W;
      if (el.Wnext.size() != 0) wq += sector.nextSectorMap() * (Xm * el.Wnext);
      for (int k = 0; k < wq.cols(); ++k) Qs.segment(long(condensed.elementCoordinate[e] + k) * nc, nc) = wq.col(k);
    }
  }
  condensedProblem.residual(Qs, w, Rq);
  std::printf("  condensed sector (%d iterations, %.2f s): vs ring %.2e, vs full sector %.2e (its Newton-step estimate "
              "%.1e); its residual at the full sector's solution %.1e\n",
              rq.iterations, tf.seconds(), errCondensed, errForms, stepCondensed, Rq.norm());
  EXPECT_LT(Rq.norm(), 10 * tol) << "at " << f << " Hz";
  summary.worstCondensed = std::max(summary.worstCondensed, errCondensed);
}

/// Both full-FE sides by Newton at the fixed frequency f, sector j of the ring against the
/// sector solution delayed and rotated; then the condensed sector.
void compareAt(const Comparison& cmp, double f, Summary& summary) {
  const auto& sector = cmp.sector;
  const auto& sectorProblem = cmp.sectorProblem;
  const auto& ringProblem = cmp.ringProblem;
  const auto& expand = cmp.expand;
  const double tol = cmp.tol;
  const double w = 2 * M_PI * f;
  Timer tf;
  Eigen::VectorXd Xs;
  const auto rs = solveAt(sector, sectorProblem, w, tol, Xs);
  ASSERT_TRUE(rs.converged) << "sector Newton at " << f << " Hz (residual " << rs.residualNorm << ")";
  const double tSector = tf.seconds();
  tf.restart();
  Eigen::VectorXd Xr;  // from rest, independently of the sector's solution
  bool fromSector = false;
  const auto rr = solveRing(cmp, w, Xs, Xr, fromSector);
  EXPECT_TRUE(rr.converged) << "ring Newton at " << f << " Hz (residual " << rr.residualNorm << ")";
  if (!rr.converged) return;
  const double tRing = tf.seconds();
  const Eigen::VectorXd expanded = expand(Xs);
  const double err = (expanded - Xr).norm() / Xr.norm();
  // Error estimates: one more Newton step of each, relative to the solution.
  const double stepRing = newtonStep(ringProblem, Xr, w) / Xr.norm();
  const double stepSector = newtonStep(sectorProblem, Xs, w) / Xs.norm();
  Eigen::VectorXd R;
  ringProblem.residual(expanded, w, R);
  const Eigen::VectorXd stuckRing = cmp.ring.linearizedSolution(w);
  const double linear = (expand(sector.linearizedSolution(w)) - stuckRing).norm() / stuckRing.norm();
  const auto [slipping, opening, slipFraction] = ringSlip(cmp, Xr);
  if (f == cmp.peakHz) summary.slippingAtPeak = slipping;
  std::printf("%.2f Hz: |x| mid-blade %.4g (ring %.4g); ring vs sector %.2e (Newton-step estimates: ring %.1e, "
              "sector %.1e); ring residual at the expanded sector solution %.1e; stuck (linear) responses %.1e; %d of %zu contacts slip (longest "
              "%.0f%% of the period), %d open; sector %d iterations%s %.2f s, ring %d iterations%s %.1f s\n",
              f, sector.amplitude(Xs, cmp.outDof, 1), cmp.ring.amplitude(Xr, cmp.outDof, 1), err, stepRing, stepSector,
              R.norm(), linear, slipping, cmp.ringPairs.size(), 100 * slipFraction, opening, rs.iterations, rs.homotopy ? " (force homotopy)" : "",
              tSector, rr.iterations, fromSector ? " (from the sector's solution)" : rr.homotopy ? " (force homotopy)" : "", tRing);
  std::fflush(stdout);
  // Both solutions satisfy their equations to tol (scaled residual, force units relative
  // to the forces on each row); the Newton-step estimates say how far that leaves each
  // from its exact solution. What remains is the two linear parts' disagreement (the two
  // LUs' rounding), measured here on the stuck responses (cached operators, no new LU).
  // Their sum, with a factor 100 for the estimates' first-order nature at the stick-slip
  // kinks, bounds the difference.
  const double bound = 100 * (stepRing + stepSector + linear);
  EXPECT_LT(err, bound) << "at " << f << " Hz";
  summary.worst = std::max(summary.worst, err);
  // The condensed sector, solved from its own start, against the ring and the full sector.
  compareCondensed(cmp, f, Xs, Xr, summary);
}

}  // namespace

TEST(DiscFullRing, CyclicSectorEqualsFullRingWithFriction) {
  Timer total;
  const auto comm = Tpetra::getDefaultComm();
  ASSERT_EQ(comm->getSize(), 1) << "the ring reference runs on one rank";
  const int N = ringSectors(), EO = 3;
  ASSERT_LT(EO, N) << "the engine order must lie below N";

  mesh::ShroudedSectorParameters geometry;
  geometry.sectors = N;
  geometry.meshSize = 6.0;  // coarse (the demo's size)
  auto mesh = mesh::generateShroudedSector(geometry);
  ASSERT_NO_FATAL_FAILURE(chooseRingContacts(mesh));

  // The cyclic side: cantilever, rpm 0, per nodal diameter. Hybrid models (20 modes and the
  // exact static correction; a modal sum per frequency) place the frequencies: the
  // resonances, the preload and the friction-damped peak. The comparison itself uses the
  // full-FE compliance (a sector LU per frequency), the same operator as the ring's.
  disc::DiscModelSpec modelSpec = hybridModelSpec(N);
  disc::DiscResponseSpec responseSpec = sectorResponseSpec(EO);
  const auto diameters = disc::nodalDiametersFor(N, EO, responseSpec.harmonics);
  SectorModels built;
  ASSERT_NO_FATAL_FAILURE(buildSectorModels(mesh, modelSpec, diameters, comm, built));
  const auto &hybrid = built.hybrid, &models = built.models;
  const int n = int(3 * models.retainedNodes.size());

  // The resonances on the hybrid models: the shroud-free one and the stuck (linearised at
  // rest) peak by disc::estimateResonance's scan and polish.
  responseSpec.condensed = false;  // the probe's and the sector's solutions are read per retained DOF
  auto probe = disc::makeDiscForcedResponse(mesh, hybrid, responseSpec);
  Timer t;
  const auto resonance = disc::estimateResonance(probe, hybrid);
  const double tResonance = t.seconds();
  const Layout layout{N, n, probe.system->numCoefficients(), probe.system->aft().harmonics(), models.sector.rotation(),
                      disc::shroudContactFrame(mesh, models, responseSpec.contact),
                      mesh.nodeSet(responseSpec.contact.leftSet), mesh.nodeSet(responseSpec.contact.rightSet),
                      models.retainedNodes};
  calibratePreload(*probe.system, layout, resonance, tResonance, responseSpec);

  // The friction-damped peak on the hybrid sector's curve (Newton from the previous point).
  const double f0 = 0.9 * resonance.freeHz, f1 = 1.1 * resonance.stuckHz;
  double peakHz = 0;
  ASSERT_NO_FATAL_FAILURE(findHybridPeak(mesh, hybrid, responseSpec, f0, f1, peakHz));
  std::fflush(stdout);
  auto setup = disc::makeDiscForcedResponse(mesh, models, responseSpec);
  auto& sector = *setup.system;
  const auto sectorProblem = response::continuationProblem(sector, response::ForcedResponseSetup::Parameter::Omega);
  const int outDof = setup.outputDofs.front();
  const auto condensed = condenseSector(sector, outDof, layout.nc);
  const auto condensedProblem =
      response::continuationProblem(*condensed.system, response::ForcedResponseSetup::Parameter::Omega);

  // The ring FE model.
  RingModel ring;
  ASSERT_NO_FATAL_FAILURE(buildRing(mesh, models, modelSpec, layout, geometry.tipRadius(), comm, ring));
  const double a = 2 * M_PI * EO / N;
  const RingSystem ringSide = buildRingSystem(ring, mesh, modelSpec, responseSpec, layout, a, sector.aft().numSamples());
  const auto ringProblem = response::continuationProblem(*ringSide.system, response::ForcedResponseSetup::Parameter::Omega);
  const SectorToRing expand{layout, ring.Qj, a, int(ring.equations.size())};

  const double tol = 1e-10;
  const Comparison cmp{sector, sectorProblem, outDof, condensed, condensedProblem, *ringSide.system, ringProblem,
                       ring.pairs, *ringSide.contact, expand, tol, peakHz};
  Summary summary;
  for (double f : {f0 + 0.25 * (peakHz - f0), peakHz, peakHz + 0.5 * (f1 - peakHz)})
    ASSERT_NO_FATAL_FAILURE(compareAt(cmp, f, summary));
  EXPECT_GT(summary.slippingAtPeak, 0) << "no contact slips at the peak: the check would be linear";
  std::printf("worst ring vs sector difference %.2e (condensed sector from its own start %.2e); total %.1f s, peak "
              "memory %.2f GB\n",
              summary.worst, summary.worstCondensed, total.seconds(), peakMemoryGb());
}
