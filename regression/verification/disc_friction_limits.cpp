// Verification of the whole chain on the default disc (built-in shrouded sector,
// 24 sectors, coarse mesh): reduced models at the shroud contacts, friction at
// the shroud, engine-order forced response. Every reference is independent of
// the harmonic balance:
//  - contacts that cannot slip (huge preload) give the linear stuck response,
//    x = (I + A T^H K T)^{-1} A F with the contact springs K on the relative
//    motion T of the neighbours, formed here in complex arithmetic;
//  - contacts without friction and normal stiffness (mu = 0, kn = 0) carry only a
//    constant preload: at harmonic 1 the free response A F;
//  - very stiff stuck contacts tie the shroud faces: the stuck resonance is the
//    first family of the fixed-shroud cyclic modal analysis (another code path:
//    the cyclic constraint on the side faces, Anasazi on the full sector);
//  - with stuck contacts the disc is a linear damped structure: Hill's method on
//    the reduced model's modal realization finds it stable;
//  - in between, friction damps: the curve's peak lies below the stuck limit's
//    peak and between the two limits' resonances, and moves up with the preload;
//  - the peak followed over the preload (issue 21) tends to those linear limits' peaks:
//    with a constant normal load (kn = 0) the slip force mu N0 alone sets the friction,
//    free as it vanishes, stuck as it grows;
//  - gap elements (seed 8.6) at the outermost pairs: with an interference larger
//    than the motion they are linear normal springs, with a clearance larger
//    than it they are absent; the same linear formula gives both references.
#include <Tpetra_Core.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>

#include "cyclone/continuation/NewtonSolve.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/cyclic/CyclicModalAnalysis.hpp"
#include "cyclone/hbm/HarmonicRefinement.hpp"
#include "cyclone/hbm/HillStability.hpp"
#include "cyclone/hbm/PeakMagnitude.hpp"
#include "cyclone/mesh/ShroudedSectorGenerator.hpp"
#include "cyclone/rom/SectorReceptance.hpp"
#include "cyclone/response/ForcedResponseTrace.hpp"
#include "cyclone/disc/DiscHarmonicBalance.hpp"
#include "cyclone/disc/DiscPeakFollowing.hpp"

using namespace cyclone;
using namespace cyclone::response;
using namespace cyclone::disc;

namespace {

constexpr int kEngineOrder = 3;

struct Disc {
  mesh::Mesh mesh;
  DiscModelSpec spec;
  DiscReducedModels models;

  explicit Disc(double rpm, std::vector<int> harmonics) {
    mesh::ShroudedSectorParameters p;  // the default disc, coarse
    mesh = mesh::generateShroudedSector(p);
    spec.sectors = p.sectors;
    spec.rpm = rpm;
    spec.prestress = cyclic::PrestressKind::Linear;
    spec.modes = 20;
    models = buildDiscReducedModels(mesh, spec, nodalDiametersFor(p.sectors, kEngineOrder, harmonics), "",
                                    Tpetra::getDefaultComm());
  }
};

DiscResponseSpec responseSpec(std::vector<int> harmonics, double preload, double kn, double kt) {
  DiscResponseSpec s;
  s.engineOrder = kEngineOrder;
  s.harmonics = std::move(harmonics);
  s.contact.law = ShroudContactSpec::Law::PerPair;  // the limits' stiffness is each pair's
  s.contact.preload = preload, s.contact.kn = kn, s.contact.kt = kt;
  s.excitation.amplitude = 20.0;
  return s;
}

// Harmonic 1 of every DOF as complex amplitudes X = c - i s.
Eigen::VectorXcd harmonicOne(const hbm::HarmonicBalanceSystem& hb, const Eigen::VectorXd& X) {
  const int nc = hb.numCoefficients(), c = hb.aft().harmonics().cosIndex(1);
  Eigen::VectorXcd x(hb.numDofs());
  for (int a = 0; a < hb.numDofs(); ++a) x(a) = {X(a * nc + c), -X(a * nc + c + 1)};
  return x;
}

// The linear responses at harmonic 1, formed directly: free A F, stuck (I + A T^H K T)^{-1} A F.
struct LinearLimits {
  Eigen::VectorXcd free, stuck;
};
LinearLimits linearLimits(const mesh::Mesh& mesh, const DiscReducedModels& models, const DiscResponseSpec& spec,
                          double omega) {
  const int N = models.sectors, n = 3 * int(models.retainedNodes.size());
  const long p = (long(kEngineOrder) % N + N) % N;  // harmonic 1's phase index
  const rom::SectorReceptance receptance(N, models.models);
  const Eigen::MatrixXcd A = receptance.compliance(omega, p);
  Eigen::VectorXcd F = Eigen::VectorXcd::Zero(n);
  const auto index = [&](mesh::Index node) {
    return int(std::find(models.retainedNodes.begin(), models.retainedNodes.end(), node) - models.retainedNodes.begin());
  };
  const Eigen::Vector3d d = spec.excitation.direction.normalized();
  for (auto node : mesh.nodeSet(spec.excitation.nodeSet))
    for (int c = 0; c < 3; ++c) F(3 * index(node) + c) = spec.excitation.amplitude * d(c);
  // Relative motion of pair i: E^T (Q x_next(left) - x(right)), x_next = e^{-i a} x.
  const auto& left = mesh.nodeSet(spec.contact.leftSet);
  const auto& right = mesh.nodeSet(spec.contact.rightSet);
  const Eigen::Matrix3d E = shroudContactFrame(mesh, models, spec.contact), Q = models.sector.rotation();
  const double a = 2 * M_PI * double(p) / N;
  const std::complex<double> next(std::cos(a), -std::sin(a));
  Eigen::MatrixXcd T = Eigen::MatrixXcd::Zero(3 * long(left.size()), n);
  for (std::size_t i = 0; i < left.size(); ++i) {
    T.block(3 * long(i), 3 * index(right[i]), 3, 3) -= E.transpose().cast<std::complex<double>>();
    T.block(3 * long(i), 3 * index(left[i]), 3, 3) += next * (E.transpose() * Q).cast<std::complex<double>>();
  }
  // A gap pair's linear limit: its normal spring when it never opens (an
  // interference larger than the motion), nothing when it never closes.
  Eigen::VectorXcd k(3 * long(left.size()));
  for (std::size_t i = 0; i < left.size(); ++i)
    k.segment(3 * long(i), 3) << spec.contact.kt, spec.contact.kt, spec.contact.kn;
  for (int i : spec.gap.pairs) k.segment(3 * long(i), 3) << 0.0, 0.0, spec.gap.clearance < 0 ? spec.gap.kn : 0.0;
  LinearLimits out;
  out.free = A * F;
  const Eigen::MatrixXcd S = Eigen::MatrixXcd::Identity(n, n) + A * T.adjoint() * k.asDiagonal() * T;
  out.stuck = S.partialPivLu().solve(out.free);
  return out;
}

Eigen::VectorXd solveAt(ForcedResponseSetup& setup, double omega) {
  setup.parameter = ForcedResponseSetup::Parameter::ForceScale;
  setup.omega = omega;
  const auto problem = continuationProblem(setup);
  Eigen::VectorXd X = setup.system->linearizedSolution(omega);
  const auto result = continuation::solveNewton(problem, X, 1.0, 1e-9, 60);
  EXPECT_TRUE(result.converged) << "Newton at " << omega / (2 * M_PI) << " Hz: residual " << result.residualNorm;
  return X;
}

}  // namespace

TEST(DiscFriction, LinearLimitsAndFrictionDampingBetweenThem) {
  Timer total;
  Disc disc(10000.0, {0, 1});
  std::printf("reduced models (ND 0, 3; %zu retained nodes) in %.1f s\n", disc.models.retainedNodes.size(),
              total.seconds());

  // 1. Contacts that cannot slip: the stuck linear response, at three frequencies.
  auto stuckSpec = responseSpec({0, 1}, 1e5, 1e4, 1e4);
  stuckSpec.condensed = false;  // parts 1 and 2 compare every retained DOF with the linear limits
  auto stuck = makeDiscForcedResponse(disc.mesh, disc.models, stuckSpec, 1.0);
  const auto estimate = estimateResonance(stuck, disc.models);
  std::printf("ND %d: free %.2f Hz, stuck %.2f Hz\n", estimate.nodalDiameter, estimate.freeHz, estimate.stuckHz);
  ASSERT_GT(estimate.stuckHz, estimate.freeHz);
  // Without a preload the contacts linearised at rest carry nothing; the disc's estimate
  // closes them: the stuck resonance of any preload (it was the free one).
  const auto unloaded = estimateDiscResonance(disc.mesh, disc.models, responseSpec({0, 1}, 0.0, 1e4, 1e4));
  std::printf("no preload: stuck %.4f Hz (huge preload %.4f Hz)\n", unloaded.stuckHz, estimate.stuckHz);
  // The same linear system: its peak amplitude to rounding; its frequency, a maximum
  // located by comparing amplitudes each good to rounding, only to about sqrt(rounding)
  // relative (1.5e-8) times the peak's shape: 1.3e-8 apart with a threaded BLAS.
  EXPECT_NEAR(unloaded.stuckAmplitude, estimate.stuckAmplitude, 1e-10 * estimate.stuckAmplitude);
  EXPECT_NEAR(unloaded.stuckHz, estimate.stuckHz, 1e-7 * estimate.stuckHz);
  for (double f : {0.5 * estimate.stuckHz, 0.99 * estimate.stuckHz, 1.2 * estimate.stuckHz}) {
    Timer t;
    const double w = 2 * M_PI * f;
    const Eigen::VectorXd X = solveAt(stuck, w);
    const Eigen::VectorXcd x = harmonicOne(*stuck.system, X);
    const auto ref = linearLimits(disc.mesh, disc.models, stuckSpec, w);
    const double err = (x - ref.stuck).norm() / ref.stuck.norm();
    std::printf("huge preload, %.1f Hz: harmonic balance vs stuck linear response %.2e (%.2f s)\n", f, err, t.seconds());
    EXPECT_LT(err, 1e-7);
    // Stuck contacts make the disc a linear damped structure: Hill's method on the
    // reduced model's modal realization must find it stable.
    Timer th;
    const auto fl = hbm::hillStability(*stuck.system, X, w);
    std::printf("  Hill's method: %d of %d eigenvalues in |Im| <= w/2, max Re %.4e (%.2f s)\n",
                int(fl.exponents.size()), int(fl.all.size()), fl.maxRealPart, th.seconds());
    EXPECT_TRUE(fl.stable);
  }

  // 2. No friction (mu = 0) and no normal stiffness (kn = 0): the contact carries only its
  //    constant preload, a static pair of forces; harmonic 1 is the free (shroud open) response.
  auto freeSpec = responseSpec({0, 1}, 1.0, 0.0, 1e4);
  freeSpec.contact.mu = 0.0;
  freeSpec.condensed = false;
  auto open = makeDiscForcedResponse(disc.mesh, disc.models, freeSpec, 1.0);
  for (double f : {0.8 * estimate.freeHz, estimate.freeHz, 2 * estimate.freeHz}) {
    const double w = 2 * M_PI * f;
    const Eigen::VectorXcd x = harmonicOne(*open.system, solveAt(open, w));
    const auto ref = linearLimits(disc.mesh, disc.models, freeSpec, w);
    const double err = (x - ref.free).norm() / ref.free.norm();
    std::printf("mu = 0, kn = 0, %.1f Hz: harmonic balance vs free response %.2e\n", f, err);
    EXPECT_LT(err, 1e-8);
  }

  // 3. In between: friction-damped peaks, below the stuck limit's peak (friction dissipates),
  //    between the free and stuck resonances, moving up with the preload.
  const int dofOut = stuck.outputDofs.front();
  const double stuckPeak =
      std::abs(linearLimits(disc.mesh, disc.models, stuckSpec, 2 * M_PI * estimate.stuckHz).stuck(dofOut));
  const double freePeak = std::abs(linearLimits(disc.mesh, disc.models, freeSpec, 2 * M_PI * estimate.freeHz).free(dofOut));
  std::printf("linear peaks at the output DOF: stuck %.4e mm at %.2f Hz, free %.4e mm at %.2f Hz\n", stuckPeak,
              estimate.stuckHz, freePeak, estimate.freeHz);
  double previousHz = 0;
  for (double preload : {2.0, 5.0, 20.0}) {
    Timer t;
    auto spec = responseSpec({0, 1}, preload, 1e4, 1e4);
    auto setup = makeDiscForcedResponse(disc.mesh, disc.models, spec, 0.9 * estimate.freeHz);
    setup.continuation.from = 1.0;
    setup.continuation.to = 1.1 * estimate.stuckHz / (0.9 * estimate.freeHz);
    const auto branch = traceForcedResponse(setup);
    ASSERT_TRUE(branch.finished) << "preload " << preload << ": " << branch.stopReason;
    const auto& hb = *setup.system;  // condensed (the product's default): its own index of the output DOF
    const int nc = hb.numCoefficients(), out = setup.outputDofs.front();
    double peak = 0, peakHz = 0;
    for (const auto& pt : branch.points) {
      const double m = hbm::peakMagnitude(hb.aft().harmonics(), Eigen::VectorXd(pt.x.segment(out * nc, nc)));
      if (m > peak) peak = m, peakHz = setup.apply(pt.parameter).first / (2 * M_PI);
    }
    const auto limits = linearLimits(disc.mesh, disc.models, spec, 2 * M_PI * peakHz);
    const double stuckAmp = std::abs(limits.stuck(dofOut)), freeAmp = std::abs(limits.free(dofOut));
    std::printf("preload %5.1f N: peak %.4e mm at %.2f Hz (stuck there %.4e, free %.4e); %zu points, %.1f s\n", preload,
                peak, peakHz, stuckAmp, freeAmp, branch.points.size(), t.seconds());
    EXPECT_GT(peakHz, estimate.freeHz);
    EXPECT_LT(peakHz, estimate.stuckHz);
    EXPECT_GT(peakHz, previousHz) << "the peak must move up with the preload";
    EXPECT_LT(peak, stuckPeak);
    EXPECT_GT(peak, std::max(stuckAmp, freeAmp)) << "at its own resonance the response exceeds both linear ones there";
    previousHz = peakHz;
  }
  std::printf("total %.1f s\n", total.seconds());
}

TEST(DiscFriction, StiffStuckContactsTieTheShroud) {
  // Without prestress (the two configurations prestress differently), ND 3 only.
  Timer t;
  Disc disc(0.0, {1});
  auto spec = responseSpec({1}, 1e9, 1e9, 1e9);
  auto setup = makeDiscForcedResponse(disc.mesh, disc.models, spec, 1.0);
  const auto estimate = estimateResonance(setup, disc.models);
  // The fixed-shroud modes: disc and shroud faces under the cyclic constraint.
  const auto tied = cyclic::makeCyclicSector(disc.mesh, disc.spec.sectors, {}, {"disc_left", "shroud_left"},
                                             {"disc_right", "shroud_right"});
  cyclic::CyclicModalProblem problem;
  problem.fixedNodeSets = {"bore"};
  problem.nodalDiameters = {estimate.nodalDiameter};
  problem.modesPerNodalDiameter = 3;
  const auto modes = cyclic::solveCyclicModes(disc.mesh, tied, problem, Tpetra::getDefaultComm());
  double nearest = 1e300;
  for (double f : modes.front().frequenciesHz)
    if (std::abs(f - estimate.stuckHz) < std::abs(nearest - estimate.stuckHz)) nearest = f;
  const double rel = std::abs(estimate.stuckHz - nearest) / nearest;
  std::printf("ND %d: stuck contacts (k = 1e9 N/mm) resonate at %.3f Hz, the fixed-shroud mode is at %.3f Hz: %.2e "
              "(%.1f s)\n",
              estimate.nodalDiameter, estimate.stuckHz, nearest, rel, t.seconds());
  EXPECT_LT(rel, 1e-3);
}

// Gap elements in place of the friction contacts at the first and last pairs
// (the seed's modified shroud, 8.6), the other contacts stuck: an interference
// of 1 mm (never opens) and a clearance of 1 mm (never closes) against their
// linear references; the two must differ, or the gaps would not be there.
// Harmonic 1 alone: with the static part on, the stuck contacts' 1e5 N preloads
// deform the shroud statically, the gaps' mean approach is no longer the
// interference, and the 1 mm case is no longer linear (1e-2 and 0.35 off).
TEST(DiscFriction, GapElementsBetweenTheirLimits) {
  Timer total;
  Disc disc(10000.0, {1});
  auto spec = responseSpec({1}, 1e5, 1e4, 1e4);
  const int pairs = int(disc.mesh.nodeSet(spec.contact.leftSet).size());
  spec.gap.pairs = {0, pairs - 1};
  spec.gap.kn = 1e4;
  spec.condensed = false;  // every retained DOF against the linear limit
  Eigen::VectorXcd closedResponse, openResponse;
  for (double clearance : {-1.0, 1.0}) {
    spec.gap.clearance = clearance;
    auto setup = makeDiscForcedResponse(disc.mesh, disc.models, spec, 1.0);
    const auto estimate = estimateResonance(setup, disc.models);
    for (double f : {0.7 * estimate.stuckHz, 0.99 * estimate.stuckHz}) {
      Timer t;
      const double w = 2 * M_PI * f;
      const Eigen::VectorXcd x = harmonicOne(*setup.system, solveAt(setup, w));
      const auto ref = linearLimits(disc.mesh, disc.models, spec, w);
      const double err = (x - ref.stuck).norm() / ref.stuck.norm();
      std::printf("gaps at pairs 0 and %d, clearance %+.1f mm, %.1f Hz: harmonic balance vs linear limit %.2e (%.2f s)\n",
                  pairs - 1, clearance, f, err, t.seconds());
      EXPECT_LT(err, 1e-7);
      if (f == 0.7 * estimate.stuckHz) (clearance < 0 ? closedResponse : openResponse) = x;
    }
  }
  const double apart = (closedResponse - openResponse).norm() / closedResponse.norm();
  std::printf("closed and open gaps differ by %.2e; %.1f s\n", apart, total.seconds());
  EXPECT_GT(apart, 1e-4);
}

// Error against run time in the harmonics and the time samples, near the
// friction-damped peak of the demo's contact values (H = 1 curve): Newton at
// fixed frequencies for H = 1..4 (harmonics 0..H, each started from the level
// below; H = 5 costs minutes per Newton solve here) and, at H = 2, for 128..2048
// samples; the finest levels are the references.
//  - On the flank (0.7 x the H = 1 peak frequency) raising H must converge:
//    the stick-slip and lift-off corners make the force only C0 in time, its
//    harmonics decay algebraically, so the error falls, if not monotonically.
//  - At the H = 1 peak frequency itself the amplitude is printed, not bounded:
//    on a sharp resonance a shift of the peak with H changes it by a factor.
//  - Samples: the march quantises the stick-slip events to the sample grid, an
//    O(1/N) error that oscillates with where the events fall (not halving per
//    doubling); it must stay below 1e-3 from 256 samples on and far below the
//    harmonic truncation error.
TEST(DiscFriction, HarmonicAndSampleRefinementNearThePeak) {
  Timer total;
  const std::vector<int> all{0, 1, 2, 3, 4};
  Disc disc(10000.0, all);
  auto spec = responseSpec({0, 1}, 5.0, 1e4, 1e4);
  auto h1 = makeDiscForcedResponse(disc.mesh, disc.models, spec, 1.0);
  const auto estimate = estimateResonance(h1, disc.models);
  h1 = makeDiscForcedResponse(disc.mesh, disc.models, spec, 0.9 * estimate.freeHz);
  h1.continuation.from = 1.0;
  h1.continuation.to = 1.1 * estimate.stuckHz / (0.9 * estimate.freeHz);
  h1.continuation.initialStep = 0.002, h1.continuation.maxStep = 0.02, h1.continuation.minStep = 1e-7;
  h1.continuation.tolerance = 1e-8, h1.continuation.arcLengthScaling = false;
  const auto branch = traceForcedResponse(h1);
  ASSERT_TRUE(branch.finished) << branch.stopReason;
  const int dofOut = h1.outputDofs.front();
  double peakHz = 0, best = 0;
  for (const auto& pt : branch.points) {
    const int nc = h1.system->numCoefficients();
    const double m = hbm::peakMagnitude(h1.system->aft().harmonics(), Eigen::VectorXd(pt.x.segment(dofOut * nc, nc)));
    if (m > best) best = m, peakHz = h1.apply(pt.parameter).first / (2 * M_PI);
  }
  std::printf("H = 1 peak %.4e mm at %.2f Hz (%zu points, %.1f s)\n", best, peakHz, branch.points.size(),
              total.seconds());

  // One level: Newton at w from the previous level's solution carried over.
  struct Level {
    int H, samples;
    double amplitude, seconds;
  };
  Eigen::VectorXd previous;
  hbm::HarmonicSet previousSet({0, 1});
  auto solveLevel = [&](double w, int H, int samples) {
    auto s = spec;
    s.harmonics.assign(all.begin(), all.begin() + H + 1);
    s.samples = samples;
    auto setup = makeDiscForcedResponse(disc.mesh, disc.models, s, 1.0);
    const auto& hb = *setup.system;
    Timer t;
    Eigen::VectorXd X = previous.size() == 0 ? hb.linearizedSolution(w)
                                             : hbm::transferCoefficients(previous, hb.numDofs(), previousSet,
                                                                         hb.aft().harmonics());
    setup.parameter = ForcedResponseSetup::Parameter::ForceScale;
    setup.omega = w;
    const auto result = continuation::solveNewton(continuationProblem(setup), X, 1.0, 1e-9, 40);
    EXPECT_TRUE(result.converged) << "H = " << H << ", " << samples << " samples: residual " << result.residualNorm;
    previous = X, previousSet = hb.aft().harmonics();
    const int nc = hb.numCoefficients();
    return Level{H, samples, hbm::peakMagnitude(hb.aft().harmonics(), Eigen::VectorXd(X.segment(dofOut * nc, nc))),
                 t.seconds()};
  };
  auto harmonicsTable = [&](double hz) {
    previous.resize(0);
    std::vector<Level> byH;
    for (int H = 1; H <= 4; ++H) byH.push_back(solveLevel(2 * M_PI * hz, H, 512));
    std::printf("harmonics at %.2f Hz (512 samples): H, max|x(t)|, difference to H = 4, Newton time\n", hz);
    for (const auto& l : byH)
      std::printf("  %d  %.6e  %.2e  %.2f s\n", l.H, l.amplitude, std::abs(l.amplitude / byH.back().amplitude - 1),
                  l.seconds);
    std::fflush(stdout);
    return byH;
  };
  const auto flank = harmonicsTable(0.7 * peakHz);
  const auto errH = [&](int H) { return std::abs(flank[std::size_t(H - 1)].amplitude / flank.back().amplitude - 1); };
  EXPECT_LT(errH(2), errH(1)) << "raising H must converge on the flank";
  EXPECT_LT(errH(3), errH(1)) << "raising H must converge on the flank";
  const auto atPeak = harmonicsTable(peakHz);

  std::vector<Level> byN;  // from the H = 4 solution at the peak, carried over (from rest Newton fails at H = 2)
  for (int samples : {128, 256, 512, 1024, 2048}) byN.push_back(solveLevel(2 * M_PI * peakHz, 2, samples));
  std::printf("samples at H = 2, %.2f Hz: N, max|x(t)|, difference to N = 2048, Newton time\n", peakHz);
  const double truncation = std::abs(atPeak[1].amplitude / atPeak[2].amplitude - 1);  // H = 2 against H = 3 there
  for (std::size_t i = 0; i < byN.size(); ++i) {
    const double err = std::abs(byN[i].amplitude / byN.back().amplitude - 1);
    std::printf("  %4d  %.6e  %.2e  %.2f s\n", byN[i].samples, byN[i].amplitude, err, byN[i].seconds);
    if (byN[i].samples >= 256) {
      EXPECT_LT(err, 1e-3) << byN[i].samples << " samples";
      EXPECT_LT(err, 0.01 * truncation) << byN[i].samples << " samples: the samples must not limit the accuracy";
    }
  }
  std::printf("total %.1f s\n", total.seconds());
}

// The resonance peak followed over the preload (disc::followDiscPeak, issue 21) reaches
// the linear limits' peaks at both ends, six decades each way from 5 N. The contacts carry
// a constant normal load (kn = 0), so the slip force mu N0 alone sets the friction: at
// N0 = 1e-6 N (slip force 4e-7 N against a 20 N excitation) the contacts are free, at
// 1e6 N stuck, and each limit is the linear response formed in complex arithmetic
// (linearLimits), its peak located by golden section near the followed peak's
// frequency. Harmonic 1 alone: the measure max|x(t)| is then |x_1|, the linear limits'
// quantity. About 26 s (its own ctest entry, disc_peak_preload_limits).
TEST(DiscFriction, PeakFollowedOverPreloadReachesTheLinearLimits) {
  Timer total;
  Disc disc(10000.0, {0, 1});
  auto spec = responseSpec({1}, 5.0, 0.0, 1e4);
  DiscSweepOptions sweep;
  sweep.harmonicsCheckTo = -1;
  sweep.stability = ForcedResponseSetup::Stability::Never;
  const auto reference = solveDiscForcedResponse(disc.mesh, disc.models, spec, sweep);
  std::printf("reference (5 N, kn = 0, H = 1): %zu points, %.2f..%.2f Hz, peak %.6e at %.3f Hz, %.1f s (%s)\n",
              reference.curve.branch.points.size(), reference.fromHz, reference.toHz, reference.curve.peak,
              reference.curve.peakOmega / (2 * M_PI), total.seconds(), reference.curve.branch.stopReason.c_str());
  ASSERT_TRUE(reference.curve.branch.finished) << reference.curve.branch.stopReason;
  DiscPeakFollowingSpec following;
  following.parameter = DiscStudyParameter::Preload;
  following.from = 1e-6, following.to = 1e6, following.values = 25;
  Timer tf;
  const auto followed = followDiscPeak(disc.mesh, disc.models, spec, reference.setup, reference.curve,
                                       reference.fromHz, reference.toHz, following);
  std::printf("followed over the preload: %zu values in %.1f s\n", followed.curve.points.size(), tf.seconds());
  for (const auto& q : followed.curve.points)
    std::printf("  preload %10.4g N: %.8e mm at %9.4f Hz%s\n", q.parameter, q.measure, q.frequency / (2 * M_PI),
                q.jump ? " (jump)" : "");
  ASSERT_TRUE(followed.curve.complete) << followed.curve.stopReason;
  ASSERT_GE(followed.curve.points.size(), 2u);
  // The output DOF among the retained DOFs (the linear limits' index; the condensed
  // system numbers its coordinates otherwise).
  auto retained = spec;
  retained.condensed = false;
  const int dofOut = makeDiscForcedResponse(disc.mesh, disc.models, retained, 1.0).outputDofs.front();
  ASSERT_EQ(followed.curve.points.front().parameter, following.from);
  ASSERT_EQ(followed.curve.points.back().parameter, following.to);
  // The linear peak of one limit near hz: golden section on |x(w)| over hz (1 +- 5 %).
  auto linearPeak = [&](bool stuck, double hz) {
    auto amplitude = [&](double f) {
      const auto l = linearLimits(disc.mesh, disc.models, spec, 2 * M_PI * f);
      return std::abs((stuck ? l.stuck : l.free)(dofOut));
    };
    double a = 0.95 * hz, b = 1.05 * hz;
    const double g = 0.5 * (std::sqrt(5.0) - 1);
    double c = b - g * (b - a), d = a + g * (b - a), fc = amplitude(c), fd = amplitude(d);
    while (b - a > 1e-9 * hz) {
      if (fc > fd) b = d, d = c, fd = fc, c = b - g * (b - a), fc = amplitude(c);
      else a = c, c = d, fc = fd, d = a + g * (b - a), fd = amplitude(d);
    }
    EXPECT_GT(a, 0.951 * hz) << "the linear peak is not inside the bracket around " << hz << " Hz";
    EXPECT_LT(b, 1.049 * hz) << "the linear peak is not inside the bracket around " << hz << " Hz";
    return std::pair<double, double>{0.5 * (a + b), amplitude(0.5 * (a + b))};
  };
  for (const bool stuck : {false, true}) {
    const auto& end = stuck ? followed.curve.points.back() : followed.curve.points.front();
    const double hz = end.frequency / (2 * M_PI);
    const auto [peakHz, peak] = linearPeak(stuck, hz);
    const double errAmplitude = std::abs(end.measure / peak - 1), errHz = std::abs(hz / peakHz - 1);
    std::printf("%s limit (preload %g N): followed %.8e mm at %.4f Hz, linear %.8e mm at %.4f Hz: %.2e, %.2e\n",
                stuck ? "stuck" : "free", end.parameter, end.measure, hz, peak, peakHz, errAmplitude, errHz);
    // The peak search's tolerance (1e-7 in frequency) and the sampled measure (max over 256
    // samples of a harmonic: 1 - cos(pi / 256) = 7.5e-5 below |x_1| at worst).
    EXPECT_LT(errAmplitude, 1e-4);
    EXPECT_LT(errHz, 1e-5);
  }
  // Towards the free limit the friction's damping falls with the slip force (at large slip
  // a Jenkins element's equivalent damping is 4 mu N0 / (pi a)): the deficit below the free
  // peak shrinks about in proportion to the preload over the grid's first decade.
  const auto& first = followed.curve.points[0];
  const auto& decade = followed.curve.points[2];
  ASSERT_NEAR(decade.parameter / first.parameter, 10.0, 1e-9);
  const auto [freeHz, freePeak] = linearPeak(false, first.frequency / (2 * M_PI));
  const double deficitFirst = 1 - first.measure / freePeak, deficitDecade = 1 - decade.measure / freePeak;
  std::printf("deficit below the free peak: %.3e at %g N, %.3e at %g N (ratio %.2f)\n", deficitFirst, first.parameter,
              deficitDecade, decade.parameter, deficitDecade / deficitFirst);
  EXPECT_GT(deficitFirst, 0);
  EXPECT_GT(deficitDecade / deficitFirst, 5.0);
  EXPECT_LT(deficitDecade / deficitFirst, 20.0);
  std::printf("total %.1f s\n", total.seconds());
}

// The resonance peak followed over the rotational speed (disc::followDiscPeak, issue 21):
// the prestress, the modes and the reduced models change with the speed and are built
// again at each value of the grid (modelsAtSpeed), so there is no interpolation error
// between speeds. The reference: at the grid's far end the models built anew there and
// the frequency curve traced over the reference band (solveDiscForcedResponse), whose
// top the followed peak must meet (1e-4 in amplitude, 1e-5 in frequency: the peak search
// holds 1e-7 of the frequency, the curve's top is located between its points, and at H = 1
// the top is smooth; measured 9e-9 and 6e-9); centrifugal stiffening moves the peak up
// in frequency with the speed. Friction at 5 N, harmonic 1. About 15 s.
TEST(DiscFriction, PeakFollowedOverSpeedMeetsTheCurveAtAnotherSpeed) {
  Timer total;
  Disc disc(10000.0, {0, 1});
  const auto spec = responseSpec({1}, 5.0, 1e4, 1e4);
  DiscSweepOptions sweep;
  sweep.harmonicsCheckTo = -1;
  sweep.stability = ForcedResponseSetup::Stability::Never;
  const auto reference = solveDiscForcedResponse(disc.mesh, disc.models, spec, sweep);
  ASSERT_TRUE(reference.curve.branch.finished) << reference.curve.branch.stopReason;
  EXPECT_EQ(disc.models.rpm, 10000.0);
  const auto nds = nodalDiametersFor(disc.spec.sectors, kEngineOrder, spec.harmonics);
  auto modelsAt = [&](double rpm) {
    auto ms = disc.spec;
    ms.rpm = rpm;
    return buildDiscReducedModels(disc.mesh, ms, nds, "", Tpetra::getDefaultComm());
  };
  DiscPeakFollowingSpec following;
  following.parameter = DiscStudyParameter::Speed;
  following.from = 6000, following.to = 10000, following.values = 3;
  int builds = 0;
  following.modelsAtSpeed = [&](double rpm) {
    ++builds;
    return modelsAt(rpm);
  };
  Timer tf;
  const auto followed = followDiscPeak(disc.mesh, disc.models, spec, reference.setup, reference.curve,
                                       reference.fromHz, reference.toHz, following);
  std::printf("followed over the speed: %zu values, %d model builds, %.1f s\n", followed.curve.points.size(), builds,
              tf.seconds());
  for (const auto& q : followed.curve.points)
    std::printf("  %7.0f rpm: %.8e mm at %9.4f Hz%s\n", q.parameter, q.measure, q.frequency / (2 * M_PI),
                q.jump ? " (jump)" : "");
  ASSERT_TRUE(followed.curve.complete) << followed.curve.stopReason;
  ASSERT_EQ(followed.curve.points.size(), 3u);
  EXPECT_EQ(builds, 2);  // 6000 and 8000 rpm; 10000 is the models given
  EXPECT_EQ(followed.curve.optimum, -1);  // an operating condition: no optimum marked
  const auto& slow = followed.curve.points.front();
  ASSERT_EQ(slow.parameter, 6000.0);
  EXPECT_LT(slow.frequency, followed.curve.points.back().frequency);  // centrifugal stiffening
  // The curve at 6000 rpm on models built anew there.
  const auto models6000 = modelsAt(6000);
  EXPECT_EQ(models6000.rpm, 6000.0);
  DiscSweepOptions band = sweep;
  band.fromHz = reference.fromHz, band.toHz = reference.toHz;
  const auto curve = solveDiscForcedResponse(disc.mesh, models6000, spec, band);
  ASSERT_TRUE(curve.curve.branch.finished) << curve.curve.branch.stopReason;
  const double curveHz = curve.curve.peakOmega / (2 * M_PI), followedHz = slow.frequency / (2 * M_PI);
  std::printf("6000 rpm: followed %.8e mm at %.4f Hz, curve %.8e mm at %.4f Hz (%zu points): %.2e, %.2e\n",
              slow.measure, followedHz, curve.curve.peak, curveHz, curve.curve.branch.points.size(),
              std::abs(curve.curve.peak / slow.measure - 1), std::abs(curveHz / followedHz - 1));
  EXPECT_NEAR(curve.curve.peak / slow.measure, 1.0, 1e-4);
  EXPECT_NEAR(curveHz / followedHz, 1.0, 1e-5);
  // Bad ranges named.
  auto bad = following;
  bad.from = -1;
  EXPECT_THROW(followDiscPeak(disc.mesh, disc.models, spec, reference.setup, reference.curve, reference.fromHz,
                              reference.toHz, bad),
               InputError);
  bad = following;
  bad.modelsAtSpeed = nullptr;
  EXPECT_THROW(followDiscPeak(disc.mesh, disc.models, spec, reference.setup, reference.curve, reference.fromHz,
                              reference.toHz, bad),
               InputError);
  std::printf("total %.1f s\n", total.seconds());
}
