// Verification: the full ring of reduced sectors (mistuning/ReducedSectorRing.hpp), tuned,
// against the cyclic sector it is built from. The built-in shrouded sector, coarse and
// with a thin disc (N = 8, a few node pairs of the shroud faces in contact), hybrid
// reduced models of every nodal diameter 0..4; the cyclic sector's harmonic balance
// (engine order 3, harmonics 0 and 1, friction3d at the pairs, the excitation at the
// mid-blade node) and the ring's (N x the retained DOFs, a friction3d element between
// every pair of neighbouring sectors, the excitation on every blade delayed by
// j 2 pi EO / N, the linear part the inverse cyclic transform of the sector's phases) are
// each solved from rest by Newton at fixed frequencies below, at and above the sector's
// friction-damped peak. The ring knows nothing of the engine order's cyclic constraint,
// so its solution equal to the sector's delayed on every blade (hbm::ringCoefficients)
// checks the transform, the contacts' placement between sectors and the excitation's
// delay together. The linear limits too: the shroud free (no contact) and stuck (the
// contacts linearised at rest), also for every other engine order (the phases a tuned
// response of engine order 3 leaves unexcited).
#include <Tpetra_Core.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <string>
#include <vector>

#include "cyclone/continuation/NewtonSolve.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/disc/DiscHarmonicBalance.hpp"
#include "cyclone/hbm/FullRingSystem.hpp"
#include "cyclone/hbm/ModalStiffness.hpp"
#include "cyclone/mesh/ShroudedSectorGenerator.hpp"
#include "cyclone/mistuning/ReducedSectorRing.hpp"
#include "SmallRingDisc.hpp"

using namespace cyclone;

namespace {

constexpr int kSectors = 8, kEngineOrder = 3, kContactPairs = 4;
constexpr double kTolerance = 1e-10;  // Newton's, on the scaled residual

/// A few node pairs of the shroud faces (evenly through the pairing's order), as the node
/// sets ring_contact_left and ring_contact_right: the ring's dense Newton system grows as
/// (N x retained DOFs)^3.
void chooseContacts(mesh::Mesh& mesh, const mesh::RotationAxis& axis) {
  const auto pairs = disc::shroudContactPairs(mesh, kSectors, axis, disc::ShroudContactSpec());
  const int n = int(pairs.left.size());
  ASSERT_GE(n, kContactPairs);
  std::vector<mesh::Index> left, right;
  for (int i = 0; i < kContactPairs; ++i) {
    const int at = i * (n - 1) / (kContactPairs - 1);
    left.push_back(pairs.left[at]), right.push_back(pairs.right[at]);
  }
  mesh.nodeSets["ring_contact_left"] = left;
  mesh.nodeSets["ring_contact_right"] = right;
}

disc::DiscResponseSpec responseSpec(double preload) {
  disc::DiscResponseSpec spec;
  spec.engineOrder = kEngineOrder;
  spec.harmonics = {0, 1};
  spec.contact.leftSet = "ring_contact_left", spec.contact.rightSet = "ring_contact_right";
  spec.contact.law = disc::ShroudContactSpec::Law::PerPair;
  spec.contact.kn = spec.contact.kt = 1e4;
  spec.contact.mu = 0.4;
  spec.contact.preload = preload;
  spec.excitation.amplitude = 1.0;
  return spec;
}

/// The median over the sector's contacts of kt times the tangential relative motion's
/// amplitude in the response linearised at rest (contacts stuck) at f: with mu N0 that
/// force, part of the contacts slip near the resonance.
double stuckTangentialForce(const hbm::HarmonicBalanceSystem& s, double f, double kt) {
  const Eigen::VectorXd X = s.linearizedSolution(2 * M_PI * f);
  const int nc = s.numCoefficients();
  const Eigen::Map<const Eigen::MatrixXd> Xm(X.data(), nc, s.numDofs());
  const int c1 = s.aft().harmonics().cosIndex(1), s1 = s.aft().harmonics().sinIndex(1);
  std::vector<double> forces;
  for (const auto& e : s.elements()) {
    Eigen::MatrixXd w = Xm * e.W;
    if (e.Wnext.size()) w += s.nextSectorMap() * (Xm * e.Wnext);
    forces.push_back(kt * std::hypot(w.row(c1).head(2).norm(), w.row(s1).head(2).norm()));
  }
  std::sort(forces.begin(), forces.end());
  return forces[forces.size() / 2];
}

/// Newton at w from rest; where it stagnates (a stick-slip kink), from the response
/// linearised at rest, then by raising the excitation in 20 steps at w.
continuation::NewtonResult solveAt(const hbm::HarmonicBalanceSystem& s, double w, Eigen::VectorXd& X,
                                   std::string& how) {
  const auto problem = response::continuationProblem(s, response::ForcedResponseSetup::Parameter::Omega);
  X = Eigen::VectorXd::Zero(s.numUnknowns());
  how = "from rest";
  auto r = continuation::solveNewton(problem, X, w, kTolerance);
  if (r.converged) return r;
  how = "from the stuck response";
  X = s.linearizedSolution(w);
  r = continuation::solveNewton(problem, X, w, kTolerance);
  if (r.converged) return r;
  how = "by force homotopy";
  const auto scaled = response::continuationProblem(s, response::ForcedResponseSetup::Parameter::ForceScale, w);
  X = s.linearizedSolution(w, 0.05);
  int iterations = r.iterations;
  for (int i = 1; i <= 20; ++i) {
    const auto step = continuation::solveNewton(scaled, X, 0.05 * i, kTolerance);
    iterations += step.iterations;
    if (!step.converged) return step;
  }
  r = continuation::solveNewton(problem, X, w, kTolerance);
  r.iterations += iterations;
  return r;
}

double relative(const Eigen::VectorXd& a, const Eigen::VectorXd& b) { return (a - b).norm() / b.norm(); }

}  // namespace

TEST(DiscReducedRing, TunedRingGivesTheCyclicSectorOnEveryBlade) {
  Timer total;
  const auto comm = Tpetra::getDefaultComm();
  auto mesh = mesh::generateShroudedSector(regression::smallRingGeometry(kSectors));
  auto modelSpec = regression::smallRingModelSpec(kSectors, {"ring_contact_left", "ring_contact_right", "mid_blade"});
  ASSERT_NO_FATAL_FAILURE(chooseContacts(mesh, modelSpec.axis));
  Timer t;
  const auto models =
      disc::buildDiscReducedModels(mesh, modelSpec, mistuning::everyNodalDiameter(kSectors), "", comm);
  std::printf("sector: %lld nodes; hybrid models (%d modes) of nodal diameters 0..%d: %.1f s\n",
              (long long)mesh.numNodes(), modelSpec.modes, kSectors / 2, t.seconds());

  // The resonance (any preload closes the contacts at rest), then the preload that lets
  // part of the contacts slip there.
  auto spec = responseSpec(1.0);
  const auto resonance = disc::estimateDiscResonance(mesh, models, spec);
  {
    const auto probe = mistuning::makeDiscRing(mesh, models, spec);
    spec.contact.preload = stuckTangentialForce(*probe.sector.system, resonance.stuckHz, spec.contact.kt) / spec.contact.mu;
  }
  t.restart();
  const auto ring = mistuning::makeDiscRing(mesh, models, spec);
  const auto& sector = *ring.sector.system;
  const auto& full = *ring.ring.system;
  const int N = ring.sectors, n = ring.sectorDofs, samples = sector.aft().numSamples();
  std::printf("ND %d: %.2f Hz shroud free, %.2f Hz stuck; preload %.4g N per pair; sector %d DOFs, ring %d DOFs "
              "(%d unknowns), %d samples; ring built in %.2f s\n",
              resonance.nodalDiameter, resonance.freeHz, resonance.stuckHz, spec.contact.preload, n, full.numDofs(),
              full.numUnknowns(), samples, t.seconds());
  ASSERT_EQ(full.numDofs(), N * n);
  ASSERT_EQ(full.elements().size(), std::size_t(N) * sector.elements().size());
  // The blades' samples are the same instants shifted when N divides samples x EO.
  ASSERT_EQ((long(samples) * kEngineOrder) % N, 0);
  {
    // Harmonic 0: the ring's mean compliance (from every nodal diameter's static compliance)
    // against its compliance far below the first mode, undamped: (1 + i eta) A(w) at
    // w = 1e-3 rad/s, O(w^2 / w_1^2) = 1e-14 from the static one.
    const auto& model = *full.receptance();
    const Eigen::MatrixXd mean = model.meanCompliance();
    const Eigen::MatrixXcd low = std::complex<double>(1, modelSpec.lossFactor) * model.compliance(1e-3, 0);
    const double err = (low.real() - mean).norm() / mean.norm(), imag = low.imag().norm() / mean.norm();
    std::printf("ring mean compliance against (1 + i eta) A(1e-3 rad/s): %.1e (imaginary part %.1e)\n", err, imag);
    EXPECT_LT(err, 1e-9);
    EXPECT_LT(imag, 1e-9);
    // The ring's modal realization (every nodal diameter's modes times their phase
    // pattern: what mistuning perturbs) against its compliance, through the stuck resonance.
    const auto modal = model.modalRealization(0);
    ASSERT_TRUE(modal.has_value());
    double worst = 0;
    for (double f : {resonance.freeHz, 0.5 * (resonance.freeHz + resonance.stuckHz), resonance.stuckHz}) {
      const Eigen::MatrixXcd A = model.compliance(2 * M_PI * f, 0);
      worst = std::max(worst, (hbm::ModalStiffness::compliance(*modal, 2 * M_PI * f) - A).norm() / A.norm());
    }
    std::printf("ring modal realization (%d modes) against its compliance: %.1e\n", modal->numModes(), worst);
    EXPECT_LT(worst, 1e-9);
  }

  // The sector's friction-damped peak on a short sweep (Newton from the previous point).
  const int out = ring.sector.outputDofs.front();
  const double f0 = 0.95 * resonance.freeHz, f1 = 1.05 * resonance.stuckHz;
  double peakHz = f0, peak = 0;
  {
    t.restart();
    const auto problem = response::continuationProblem(sector, response::ForcedResponseSetup::Parameter::Omega);
    Eigen::VectorXd X = sector.linearizedSolution(2 * M_PI * f0);
    for (int i = 0; i <= 40; ++i) {
      const double f = f0 + (f1 - f0) * i / 40;
      Eigen::VectorXd Y = X;
      if (!continuation::solveNewton(problem, Y, 2 * M_PI * f).converged) {
        std::string how;
        if (!solveAt(sector, 2 * M_PI * f, Y, how).converged) continue;
      }
      X = Y;
      const double a = sector.amplitude(X, out, 1);
      if (a > peak) peak = a, peakHz = f;
    }
    std::printf("sector sweep %.1f..%.1f Hz (41 points, %.1f s): friction-damped peak %.4g at %.2f Hz\n", f0, f1,
                t.seconds(), peak, peakHz);
    ASSERT_GT(peakHz, f0);
    ASSERT_LT(peakHz, f1);
  }

  double worstFriction = 0, worstLinear = 0, nonlinearity = 1e300;
  for (double f : {0.5 * (f0 + peakHz), peakHz, 0.5 * (peakHz + f1)}) {
    const double w = 2 * M_PI * f;
    // The linear limits: the shroud free (no contact) and stuck (linearised at rest).
    t.restart();
    const double free = relative(full.linearSolution(w), hbm::ringCoefficients(sector, sector.linearSolution(w)));
    const Eigen::VectorXd stuckRing = full.linearizedSolution(w);
    const double stuck = relative(stuckRing, hbm::ringCoefficients(sector, sector.linearizedSolution(w)));
    const double tLinear = t.seconds();
    // With friction: each solved from its own start.
    t.restart();
    Eigen::VectorXd Xs, Xr;
    std::string hows, howr;
    const auto rs = solveAt(sector, w, Xs, hows);
    const double tSector = t.seconds();
    t.restart();
    const auto rr = solveAt(full, w, Xr, howr);
    const double tRing = t.seconds();
    ASSERT_TRUE(rs.converged) << "sector Newton at " << f << " Hz, residual " << rs.residualNorm;
    ASSERT_TRUE(rr.converged) << "ring Newton at " << f << " Hz, residual " << rr.residualNorm;
    const Eigen::VectorXd expanded = hbm::ringCoefficients(sector, Xs);
    const double err = relative(Xr, expanded);
    double blade = 0;  // the output DOF's amplitude on every blade against the sector's
    const double a0 = sector.amplitude(Xs, out, 1);
    for (int j = 0; j < N; ++j)
      blade = std::max(blade, std::abs(full.amplitude(Xr, ring.bladeOutputDofs[j].front(), 1) - a0) / a0);
    const double slipping = relative(Xr, stuckRing);  // how far friction takes it from the stuck response
    std::printf("%.2f Hz: linear ring vs sector: shroud free %.1e, stuck %.1e (%.2f s); with friction: ring vs "
                "sector %.1e, blade amplitudes %.1e (|x| %.4g; %.0f%% from the stuck response); sector %d "
                "iterations %s %.2f s, ring %d iterations %s %.2f s\n",
                f, free, stuck, tLinear, err, blade, a0, 100 * slipping, rs.iterations, hows.c_str(), tSector,
                rr.iterations, howr.c_str(), tRing);
    std::fflush(stdout);
    EXPECT_LT(free, 1e-9) << f;
    EXPECT_LT(stuck, 1e-9) << f;
    EXPECT_LT(err, 1e-8) << f;
    EXPECT_LT(blade, 1e-8) << f;
    worstLinear = std::max({worstLinear, free, stuck});
    worstFriction = std::max({worstFriction, err, blade});
    if (f == peakHz) nonlinearity = slipping;
  }
  // The contacts slip at the peak: the friction response is away from the stuck one.
  EXPECT_GT(nonlinearity, 0.01) << "the friction response at the peak is the stuck one: the check would be linear";
  // Tuned, only the engine order's phase is excited; the others by engine orders 1..N-1
  // (harmonic 1 on phase index EO: every nodal diameter, both waves of a pair), in the
  // linear limits at the same frequency.
  t.restart();
  std::printf("engine orders 1..%d at %.2f Hz, ring vs sector (shroud free, stuck):", N - 1, peakHz);
  for (int eo = 1; eo < N; ++eo) {
    auto other = spec;
    other.engineOrder = eo;
    const auto r = mistuning::makeDiscRing(mesh, models, other);
    const auto &s = *r.sector.system, &ringSystem = *r.ring.system;
    const double w = 2 * M_PI * peakHz;
    const double free = relative(ringSystem.linearSolution(w), hbm::ringCoefficients(s, s.linearSolution(w)));
    const double stuck =
        relative(ringSystem.linearizedSolution(w), hbm::ringCoefficients(s, s.linearizedSolution(w)));
    std::printf(" EO %d %.1e, %.1e;", eo, free, stuck);
    EXPECT_LT(free, 1e-9) << "EO " << eo;
    EXPECT_LT(stuck, 1e-9) << "EO " << eo;
    worstLinear = std::max({worstLinear, free, stuck});
  }
  std::printf(" %.2f s\n", t.seconds());
  std::printf("worst ring vs sector: linear %.1e, with friction %.1e; total %.1f s\n", worstLinear, worstFriction,
              total.seconds());
}
