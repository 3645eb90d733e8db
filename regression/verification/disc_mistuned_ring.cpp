// Verification: the mistuned ring of reduced sectors by the subset of nominal modes
// (mistuning/DiscMistunedRing.hpp, SubsetOfNominalModes.hpp) against the full-ring FE model
// with the same per-blade Young's modulus. The built-in shrouded sector, coarse and with a
// thin disc (N = 8, as disc_reduced_ring), bore fixed, at rest; hybrid models of every nodal
// diameter (10 modes each and the exact static correction) at the mid-blade node; the
// blade the elements whose centroid lies beyond the rim radius; a fixed pattern of a few
// percent on the blades' E. The reference: the sector replicated N times
// (cyclic::replicateSector), every element's stiffness at its own E (blade j's at f_j E),
// assembled as one model; its lowest modes by shift-invert (Anasazi, CHOLMOD) and its
// response to the engine-order excitation by a sparse complex LU per frequency. Measured:
//   - the first two blade families' 2 N natural frequencies (relative error),
//   - their MAC at the ring's retained DOFs (each sector's mid-blade node in its own frame),
//   - each blade's amplitude under engine order 3 (unit axial force on every mid-blade node,
//     delayed by j 2 pi EO / N; structural damping eta) over a sweep across the family's
//     band: the largest |a_snm - a_fe| over the blades and frequencies, relative to the
//     largest FE amplitude at that frequency.
// The bounds follow from the method. SNM is the Rayleigh-Ritz approximation of the mistuned
// ring FE model on the tuned ring's kept modes (Phi^H M Phi = I and Phi^H K_mistuned Phi =
// diag(l) + dK hold exactly, the same mesh on both sides): its eigenvalues lie above the FE
// ones, by an amount second order in the mode's part outside the kept span, itself first
// order in the scatter, so the frequencies are asserted within 0 and delta_max^2 / 2
// (relative) and the MAC above 1 - delta_max^2. Near a resonance a relative frequency error e
// moves a mode's response by up to 2 e / eta, and the constant part R (the tuned static
// correction, not mistuned) is off by up to delta_max of its share of the response: the
// amplitudes are asserted within the sum of the two.
// Also checked: the realization built from the full shapes gives the hybrid models'
// compliance (the same modes, only their shapes kept in full).
#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <vector>

#include "cyclone/core/Timer.hpp"
#include "cyclone/cyclic/FullRing.hpp"
#include "cyclone/fe/Assembler.hpp"
#include "cyclone/fe/DofMap.hpp"
#include "cyclone/fe/ElementKernels.hpp"
#include "cyclone/mesh/ShroudedSectorGenerator.hpp"
#include "cyclone/mistuning/AmplificationStatistics.hpp"
#include "cyclone/mistuning/DiscMistunedRing.hpp"
#include "cyclone/mistuning/MistunedRingSweep.hpp"
#include "cyclone/mistuning/MistuningPattern.hpp"
#include "cyclone/mistuning/ReducedSectorRing.hpp"
#include "cyclone/rom/SectorReceptance.hpp"
#include "cyclone/solvers/DirectSolver.hpp"
#include "cyclone/solvers/ModalSolver.hpp"
#include "SmallRingDisc.hpp"

using namespace cyclone;
using cd = std::complex<double>;

namespace {

constexpr int kSectors = 8, kEngineOrder = 3;

double mac(const Eigen::VectorXcd& a, const Eigen::VectorXcd& b) {
  return std::norm(a.dot(b)) / (a.squaredNorm() * b.squaredNorm());
}

}  // namespace

TEST(DiscMistunedRing, SubsetOfNominalModesAgainstRingFe) {
  Timer total;
  const auto comm = Tpetra::getDefaultComm();
  const auto geometry = regression::smallRingGeometry(kSectors);
  const auto mesh = mesh::generateShroudedSector(geometry);
  const auto modelSpec = regression::smallRingModelSpec(kSectors, {"mid_blade"});
  Timer t;
  const auto models = disc::buildDiscReducedModels(mesh, modelSpec, mistuning::everyNodalDiameter(kSectors), "", comm);
  const double romSeconds = t.seconds();
  const auto blade = mistuning::bladeElementsAboveRadius(mesh, modelSpec.axis, geometry.rimRadius);
  {
    // The rim radius splits the mesh along element faces: no blade element reaches inside it,
    // no disc element beyond it, but for the sagitta of a straight element edge on the curved
    // rim (a mid-side node 7e-3 mm inside it here): at most meshSize^2 / (8 rimRadius).
    std::vector<char> inBlade(std::size_t(mesh.numElements()), 0);
    for (auto e : blade) inBlade[std::size_t(e)] = 1;
    int straddling = 0;
    mesh::Index g = 0;
    for (const auto& block : mesh.blocks)
      for (mesh::Index e = 0; e < block.numElements(); ++e, ++g) {
        const mesh::Index* nodes = block.element(e);
        for (int a = 0; a < mesh::nodesPerElement(block.type); ++a) {
          const auto& x = mesh.coords[nodes[a]];
          const double r = std::hypot(x[0], x[1]), tol = geometry.meshSize * geometry.meshSize / (8 * geometry.rimRadius);
          if (inBlade[std::size_t(g)] ? r < geometry.rimRadius - tol : r > geometry.rimRadius + tol) {
            ++straddling;
            break;
          }
        }
      }
    std::printf("elements across the rim radius: %d\n", straddling);
    EXPECT_EQ(straddling, 0);
  }
  const auto pattern = mistuning::youngsModulusFactors({1.03, 0.98, 1.01, 0.96, 1.04, 0.99, 1.02, 0.97}, kSectors);
  std::printf("sector: %lld nodes, %lld elements (%zu blade: centroid beyond the rim radius %.0f); hybrid models: %.1f s\n",
              (long long)mesh.numNodes(), (long long)mesh.numElements(), blade.size(), geometry.rimRadius, romSeconds);

  t.restart();
  const auto nominal = mistuning::discNominalModes(mesh, models, modelSpec, comm);
  const auto ring = mistuning::makeDiscMistunedRing(mesh, nominal, modelSpec.material, blade, pattern);
  const auto snmModes = ring.mistuned->modes();
  const double snmSeconds = t.seconds();
  std::printf("SNM: %d ring modes, full shapes and blade projection %.1f s\n", int(snmModes.eigenvalues.size()),
              snmSeconds);

  // Zero scatter: the tuned ring (dK identically zero).
  {
    const auto tunedPattern = mistuning::youngsModulusFactors(std::vector<double>(kSectors, 1.0), kSectors);
    const auto zero = mistuning::makeDiscMistunedRing(mesh, nominal, modelSpec.material, blade, tunedPattern);
    double worst = 0;
    for (double hz : {150.0, 155.8, 400.0}) {
      const Eigen::MatrixXcd a = zero.mistuned->compliance(2 * M_PI * hz, 0), b = zero.tuned->compliance(2 * M_PI * hz, 0);
      worst = std::max(worst, (a - b).norm() / b.norm());
    }
    std::printf("zero scatter against the tuned ring: %.1e\n", worst);
    EXPECT_EQ(zero.mistuned->stiffnessPerturbation().cwiseAbs().maxCoeff(), 0.0);
    EXPECT_LT(worst, 1e-10);
  }

  // The realization from the full shapes against the hybrid models, every phase.
  {
    const rom::SectorReceptance hybrid(kSectors, models.models);
    double worst = 0;
    for (int p = 0; p < kSectors; ++p)
      for (double hz : {200.0, 900.0, 3000.0}) {
        const Eigen::MatrixXcd a = nominal.sectorModel->compliance(2 * M_PI * hz, p), b = hybrid.compliance(2 * M_PI * hz, p);
        worst = std::max(worst, (a - b).norm() / b.norm());
      }
    std::printf("full-shape realization against the hybrid models: %.1e (every phase, 200, 900, 3000 Hz)\n", worst);
    EXPECT_LT(worst, 1e-6);
  }

  // The ring FE model with blade j's elements at f_j E.
  t.restart();
  const auto full = cyclic::replicateSector(mesh, models.sector);
  fe::DofMap dofs(full.mesh.numNodes());
  for (const auto& s : modelSpec.fixedNodeSets) dofs.constrain(full.mesh.nodeSet(s));
  dofs.finalize();
  const fe::Assembler assembler(full.mesh, dofs, comm);
  std::vector<char> isBlade(std::size_t(mesh.numElements()), 0);
  for (auto e : blade) isBlade[std::size_t(e)] = 1;
  std::vector<mesh::Index> blockStart{0};
  for (const auto& b : mesh.blocks) blockStart.push_back(blockStart.back() + b.numElements());
  const auto K = assembler.assemble([&](mesh::Index g, mesh::ElementType type, const fe::ElementCoords& X) {
    auto Ke = fe::elementStiffness(type, X, modelSpec.material);
    const auto [b, eb] = full.mesh.locateElement(g);  // copy j of block b holds its elements j nE_b ..
    const mesh::Index nb = mesh.blocks[b].numElements();
    const int j = int(eb / nb);
    if (isBlade[std::size_t(blockStart[b] + eb % nb)]) Ke *= pattern.youngsFactors[std::size_t(j)];
    return Ke;
  });
  const auto M = assembler.mass(modelSpec.material);
  solvers::ModalOptions options;
  options.numModes = 2 * kSectors + 2;
  const auto fe = solvers::solveModes(*K, *M, options);
  const double feModalSeconds = t.seconds();
  std::printf("ring FE: %lld nodes, %lld free DOFs; %d modes in %.1f s\n", (long long)full.mesh.numNodes(),
              (long long)dofs.numFree(), options.numModes, feModalSeconds);

  // Ring retained DOFs: sector j's mid-blade node, x y z in sector j's frame.
  const auto mid = models.retainedNodes;
  ASSERT_EQ(mid.size(), 1u);
  const int nRing = 3 * kSectors;
  std::vector<long long> eq(static_cast<std::size_t>(nRing), 0);
  std::vector<Eigen::Matrix3d> Q(kSectors, Eigen::Matrix3d::Identity());
  for (int j = 1; j < kSectors; ++j) Q[j] = models.sector.rotation() * Q[j - 1];
  for (int j = 0; j < kSectors; ++j)
    for (int d = 0; d < 3; ++d) eq[3 * j + d] = dofs.equation(full.ringNode[j][mid[0]], d);
  const auto& map = *K->getRowMap();
  const auto retained = [&](const linalg::MultiVector& x, std::size_t column) {
    const auto data = x.getData(column);
    Eigen::VectorXd out(nRing);
    for (int j = 0; j < kSectors; ++j) {
      Eigen::Vector3d g;
      for (int d = 0; d < 3; ++d) g(d) = data[map.getLocalElement(eq[3 * j + d])];
      out.segment<3>(3 * j) = Q[j].transpose() * g;
    }
    return out;
  };

  // First blade family: the lowest N modes of each.
  double deltaMax = 0;
  for (double d : pattern.deviations()) deltaMax = std::max(deltaMax, std::abs(d));
  double worstFrequency = 0, lowestFrequency = 0, worstMac = 1;
  std::printf(" mode   FE (Hz)   SNM (Hz)   SNM - FE (relative)   1 - MAC\n");
  for (int i = 0; i < 2 * kSectors; ++i) {
    const double fFe = fe.frequenciesHz[i], fSnm = std::sqrt(snmModes.eigenvalues(i)) / (2 * M_PI);
    const double e = (fSnm - fFe) / fFe;
    const double m = mac(retained(*fe.modes, std::size_t(i)).cast<cd>(), snmModes.retained.col(i));
    std::printf(" %4d  %8.3f  %8.3f   %9.1e            %.1e   (family %d)\n", i, fFe, fSnm, e, 1 - m, 1 + i / kSectors);
    worstFrequency = std::max(worstFrequency, std::abs(e)), lowestFrequency = std::min(lowestFrequency, e);
    worstMac = std::min(worstMac, m);
  }
  const double spread = (fe.frequenciesHz[kSectors - 1] - fe.frequenciesHz[0]) / fe.frequenciesHz[0];
  std::printf("first two families: frequencies within %.1e (relative; the first spans %.1e), 1 - MAC <= %.1e\n",
              worstFrequency, spread, 1 - worstMac);

  // Engine order 3 on every blade: per blade amplitude across the family's band.
  t.restart();
  const double eta = modelSpec.lossFactor;
  Eigen::VectorXcd F = Eigen::VectorXcd::Zero(nRing);
  linalg::MultiVector rhs(K->getRowMap(), 2);
  for (int j = 0; j < kSectors; ++j) {
    const double a = 2 * M_PI * kEngineOrder * j / kSectors;
    F(3 * j + 2) = cd(std::cos(a), std::sin(a));
    if (map.isNodeGlobalElement(eq[3 * j + 2])) {
      rhs.replaceGlobalValue(eq[3 * j + 2], 0, std::cos(a));
      rhs.replaceGlobalValue(eq[3 * j + 2], 1, std::sin(a));
    }
  }
  const double f0 = fe.frequenciesHz[0], f1 = fe.frequenciesHz[kSectors - 1];
  const int points = 9;
  double worstResponse = 0, worstBound = 0;
  const auto& tunedRing = ring.mistuned->tuned();
  std::vector<double> peakFe(kSectors, 0), peakSnm(kSectors, 0);
  for (int s = 0; s < points; ++s) {
    const double hz = 0.995 * f0 + (1.005 * f1 - 0.995 * f0) * s / (points - 1), w = 2 * M_PI * hz;
    const solvers::ComplexDirectSolver lu(*K, {1.0, eta}, *M, -w * w);
    linalg::MultiVector xr(K->getRowMap(), 2), xi(K->getRowMap(), 2);
    lu.solve(rhs, xr, xi);
    const Eigen::VectorXcd xFe = retained(xr, 0).cast<cd>() + cd(0, 1) * retained(xi, 0).cast<cd>() +
                                 cd(0, 1) * (retained(xr, 1).cast<cd>() + cd(0, 1) * retained(xi, 1).cast<cd>());
    const Eigen::VectorXcd xSnm = ring.mistuned->compliance(w, 0) * F;
    const Eigen::VectorXcd xR = tunedRing.R * F / cd(1, eta);
    double largest = 0, diff = 0, rShare = 0;
    for (int j = 0; j < kSectors; ++j) {
      const double aFe = std::abs(xFe(3 * j + 2)), aSnm = std::abs(xSnm(3 * j + 2));
      largest = std::max(largest, aFe), diff = std::max(diff, std::abs(aSnm - aFe));
      rShare = std::max(rShare, std::abs(xR(3 * j + 2)));
      peakFe[j] = std::max(peakFe[j], aFe), peakSnm[j] = std::max(peakSnm[j], aSnm);
    }
    const double bound = 2 * worstFrequency / eta + deltaMax * rShare / largest;
    std::printf("  %.2f Hz: largest blade amplitude FE %.4e, SNM error %.1e of it (bound %.1e)\n", hz, largest,
                diff / largest, bound);
    worstResponse = std::max(worstResponse, diff / largest);
    worstBound = std::max(worstBound, bound);
    EXPECT_LT(diff / largest, bound) << hz << " Hz";
  }
  double worstPeak = 0;
  for (int j = 0; j < kSectors; ++j) worstPeak = std::max(worstPeak, std::abs(peakSnm[j] - peakFe[j]) / peakFe[j]);
  std::printf("EO %d response: per blade amplitude within %.1e (of the largest, %d frequencies), per blade peak over "
              "the sweep within %.1e; FE solves %.1f s\n",
              kEngineOrder, worstResponse, points, worstPeak, t.seconds());
  std::printf("run time: reduced models %.1f s, SNM %.1f s, ring FE modes %.1f s, total %.1f s\n", romSeconds,
              snmSeconds, feModalSeconds, total.seconds());
  std::printf("bounds: frequencies 0 .. %.1e (delta_max^2 / 2, delta_max %.2f), 1 - MAC %.1e, response %.1e at worst\n",
              0.5 * deltaMax * deltaMax, deltaMax, deltaMax * deltaMax, worstBound);

  // The forced response over a sweep (MistunedRingSweep): the same load (e^{+i 2 pi EO j / N}
  // is phase N - EO in the ring's convention), against the mistuned ring's compliance applied
  // to it at the FE frequencies above; zero scatter against the cyclic sector at phase N - EO;
  // the circular shifts of the pattern; the largest amplification over random patterns
  // against Whitehead's bound.
  {
    t.restart();
    const int eo = (kSectors - kEngineOrder) % kSectors;
    const mistuning::MistunedRingSweep sweep(tunedRing, kSectors, 3, ring.modesPerPhase, ring.bladeProjection, eo, 2, 2);
    const std::vector<double> delta = pattern.deviations();
    std::vector<double> omegas;
    for (int s = 0; s < points; ++s)
      omegas.push_back(2 * M_PI * (0.995 * f0 + (1.005 * f1 - 0.995 * f0) * s / (points - 1)));
    const Eigen::MatrixXcd X = sweep.responses(delta, omegas), X0 = sweep.responses(std::vector<double>(kSectors, 0.0), omegas);
    double worstSweep = 0, worstTuned = 0;
    for (std::size_t k = 0; k < omegas.size(); ++k) {
      const Eigen::VectorXcd x = ring.mistuned->compliance(omegas[k], 0) * F;
      const cd x0 = nominal.sectorModel->compliance(omegas[k], eo)(2, 2);
      double largest = 0;
      for (int j = 0; j < kSectors; ++j) largest = std::max(largest, std::abs(x(3 * j + 2)));
      for (int j = 0; j < kSectors; ++j) {
        worstSweep = std::max(worstSweep, std::abs(X(j, Eigen::Index(k)) - x(3 * j + 2)) / largest);
        const double a = 2 * M_PI * kEngineOrder * j / kSectors;
        worstTuned = std::max(worstTuned, std::abs(X0(j, Eigen::Index(k)) - x0 * cd(std::cos(a), std::sin(a))) / std::abs(x0));
      }
    }
    std::vector<double> band;
    for (int k = 0; k < 400; ++k) band.push_back(omegas.front() + (omegas.back() - omegas.front()) * k / 399);
    const auto base = sweep.peaks(delta, band);
    double worstShift = 0;
    for (int s = 1; s < kSectors; ++s)
      worstShift = std::max(worstShift, std::abs(sweep.peaks(mistuning::shiftedPattern(delta, s), band).largest() -
                                                 base.largest()) / base.largest());
    const auto tunedPeaks = sweep.peaks(std::vector<double>(kSectors, 0.0), band);
    const auto stats = mistuning::monteCarloAmplification(
        kSectors, [&](const std::vector<double>& d) { return sweep.peaks(d, band); }, 0.02, 500, 1);
    std::printf("sweep: against the mistuned compliance %.1e, zero scatter against the cyclic sector %.1e (tuned "
                "amplification %.15f), circular shifts %.1e; this pattern's amplification %.4f (IPR %.3f); 500 patterns "
                "of 2 %%: mean %.4f, p95 %.4f, p99 %.4f, largest %.4f < Whitehead %.4f; %.2f s\n",
                worstSweep, worstTuned, tunedPeaks.largest() / stats.tunedPeak, worstShift,
                base.largest() / stats.tunedPeak, base.localisation, stats.mean, stats.p95.value, stats.p99.value,
                stats.largest, mistuning::whiteheadBound(kSectors), t.seconds());
    EXPECT_LT(worstSweep, 1e-10);
    EXPECT_LT(worstTuned, 1e-9);
    EXPECT_LT(worstShift, 1e-10);
    EXPECT_LT(stats.largest, mistuning::whiteheadBound(kSectors));
    EXPECT_GT(stats.largest, 1.0);
  }
  EXPECT_GT(lowestFrequency, -1e-8) << "Rayleigh-Ritz: SNM's frequencies are not below the FE ones";
  EXPECT_LT(worstFrequency, 0.5 * deltaMax * deltaMax);
  EXPECT_GT(worstMac, 1 - deltaMax * deltaMax);
}
