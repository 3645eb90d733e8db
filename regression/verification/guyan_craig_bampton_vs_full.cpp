// Verification: Guyan and Craig-Bampton models (and the hybrid FRF model and
// modal truncation alongside) of one nodal diameter of the built-in shrouded
// sector (cantilever, 10 000 rpm linear prestress, k = 2 of N = 8, structural
// damping) against the full FE model with the same K_k, M_k and constraints:
//   - compliance over a band covering the first 5 families: Craig-Bampton
//     converges as fixed-interface modes are added; Guyan keeps its error;
//   - natural frequencies of every Ritz model at or above the full model's
//     (Rayleigh-Ritz), Craig-Bampton's falling as modes are added (nested spaces);
//   - resonance peaks of |A_rr(w)| at the full model's damped peaks and natural
//     frequencies (the seed's failed check);
//   - MAC of the full modes and the reduced model's modes at the retained DOFs;
//   - zero-frequency compliance exact for Guyan and Craig-Bampton;
//   - bad input for the boundary reduction.
// Prints error and run time against the modes retained for each kind.
#include <Tpetra_Core.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <functional>
#include <memory>

#include "ShroudedSectorCase.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/post/Mac.hpp"
#include "cyclone/rom/BoundaryReduction.hpp"
#include "cyclone/rom/CraigBamptonModel.hpp"
#include "cyclone/rom/NodalDiameterModel.hpp"
#include "cyclone/rom/GuyanModel.hpp"
#include "cyclone/solvers/ModalSolver.hpp"

using namespace cyclone;
using regression::relativeError;

namespace {

constexpr int kHarmonic = 2;
constexpr double kEta = 0.005;
constexpr int kFamilies = 5;       // the band: the first 5 natural frequencies (families at this k)
constexpr int kFullModes = 40;     // distinct natural frequencies of the full model
const std::vector<int> kInterfaceModes = {5, 10, 20, 40, 80};
constexpr int kPeakFamilies = 3;  // the peak check costs 2 or 3 full solves per family

// The full model, its modes and its compliance over the band: built once, shared by the tests.
struct Reference {
  regression::ShroudedSectorCase sector{{"bore"}, kHarmonic, kEta};
  std::unique_ptr<rom::NodalDiameterModel> full;
  rom::RetainedModes modes;
  std::vector<double> band;
  std::vector<Eigen::MatrixXcd> compliance;
  double fullSecondsPerFrequency = 0;

  Reference() {
    full = std::make_unique<rom::NodalDiameterModel>(sector.mesh, sector.sector, sector.problem,
                                                      Tpetra::getDefaultComm());
    modes = full->modes(kFullModes);
    band = regression::frequencyBand(modes, kFamilies);
    Timer timer;
    for (double w : band) compliance.push_back(full->compliance(w));
    fullSecondsPerFrequency = timer.seconds() / double(band.size());
  }
  double natural(int family) const { return std::sqrt(modes.eigenvalues[std::size_t(family * modes.copies)]); }
};

const Reference& reference() {
  // Never freed: Tpetra objects must not outlive Kokkos, which ends before static destructors run.
  static const Reference* r = new Reference;
  return *r;
}

double worstError(const rom::ComplianceModel& model, const Reference& ref, double* secondsPerFrequency = nullptr) {
  double worst = 0;
  Timer timer;
  for (std::size_t i = 0; i < ref.band.size(); ++i)
    worst = std::max(worst, relativeError(model.compliance(ref.band[i]), ref.compliance[i]));
  if (secondsPerFrequency) *secondsPerFrequency = timer.seconds() / double(ref.band.size());
  return worst;
}

// Largest relative distance of the first `count` eigenvalues below the full model's
// (positive: every reduced eigenvalue at or above, as Rayleigh-Ritz requires).
double worstBoundMargin(const rom::RetainedModes& reduced, const rom::RetainedModes& full, int count) {
  double margin = 1e300;
  for (int j = 0; j < count; ++j)
    margin = std::min(margin, reduced.eigenvalues[std::size_t(j)] / full.eigenvalues[std::size_t(j)] - 1);
  return margin;
}

// Pair-subspace MAC of family j (its `copies` real-form columns) between two mode sets.
double familyMac(const rom::RetainedModes& a, const rom::RetainedModes& b, int family) {
  const int c = a.copies;
  return post::subspaceMac(a.shapes.middleCols(family * c, c), b.shapes.middleCols(family * c, c));
}

// The frequency of the largest |f| in [lo, hi] by golden section (f unimodal there).
double peakFrequency(const std::function<double(double)>& magnitude, double lo, double hi, int iterations) {
  const double g = 0.5 * (std::sqrt(5.0) - 1);
  double a = lo, b = hi, x1 = b - g * (b - a), x2 = a + g * (b - a);
  double f1 = magnitude(x1), f2 = magnitude(x2);
  for (int i = 0; i < iterations; ++i) {
    if (f1 > f2) {
      b = x2, x2 = x1, f2 = f1, x1 = b - g * (b - a), f1 = magnitude(x1);
    } else {
      a = x1, x1 = x2, f1 = f2, x2 = a + g * (b - a), f2 = magnitude(x2);
    }
  }
  return 0.5 * (a + b);
}

}  // namespace

namespace {

// Guyan's model (the constraint modes alone): its error over the band, its modes against
// the full model's (Rayleigh-Ritz bound), exact at zero frequency; a row of the table.
void checkGuyan(const Reference& ref, const Eigen::MatrixXd& Az, int familyModes, double& guyanError) {
  const auto& full = *ref.full;
  Timer timer;
  // Guyan: the constraint modes alone.
  const auto guyanReduction = rom::reduceOntoRetainedDofs(full, 0);
  const rom::GuyanModel guyan(guyanReduction, kEta);
  const double guyanBuild = timer.seconds();
  double guyanEval = 0;
  guyanError = worstError(guyan, ref, &guyanEval);
  const auto guyanModes = guyan.modes();
  ASSERT_EQ(guyanModes.numModes(), full.size());
  double guyanMac = 1;
  for (int j = 0; j < kFamilies; ++j) guyanMac = std::min(guyanMac, familyMac(ref.modes, guyanModes, j));
  const double guyanZero = (guyan.zeroFrequencyCompliance() - Az).norm() / Az.norm();
  std::printf("%-14s %6d %12.3e %12.3f %12.2e %14.3e %10.5f %10.2e\n", "Guyan", 0, guyanError, guyanBuild, guyanEval,
              std::sqrt(guyanModes.eigenvalues[std::size_t(familyModes - 1)] /
                        ref.modes.eigenvalues[std::size_t(familyModes - 1)]) - 1,
              guyanMac, guyanZero);
  // Rayleigh-Ritz: every Guyan eigenvalue at or above the full model's, and strictly
  // above (the interior inertia is carried statically only).
  const int bounded = std::min(guyanModes.numModes(), ref.modes.numModes());
  EXPECT_GT(worstBoundMargin(guyanModes, ref.modes, bounded), -1e-10);
  for (int j = 0; j < familyModes; ++j)
    EXPECT_GT(guyanModes.eigenvalues[std::size_t(j)], ref.modes.eigenvalues[std::size_t(j)] * (1 + 1e-6))
        << "Guyan eigenvalue " << j << " must lie above the full model's";
  EXPECT_LT(guyanZero, 1e-10) << "Guyan is exact at zero frequency";

}

// The hybrid model and modal truncation on the same band: rows of the table.
void printHybridAndTruncationRows(const rom::NodalDiameterModel& full, const Reference& ref, const Eigen::MatrixXd& Az) {
  Timer timer;
  // The hybrid model and modal truncation on the same band, for the table.
  for (int m : {5, 10, 20, 40}) {
    timer.restart();
    const auto modes = full.modes(m);
    const auto A0 = full.staticCompliance(0.0, modes);
    const rom::HybridFrfModel hybrid(modes, A0, kEta);
    const double build = timer.seconds();
    double eval = 0;
    const double error = worstError(hybrid, ref, &eval);
    std::printf("%-14s %6d %12.3e %12.3f %12.2e %14s %10s %10.2e\n", "hybrid", m, error, build, eval, "exact",
                "1", (hybrid.zeroFrequencyCompliance() - Az).norm() / Az.norm());
    const auto truncation = rom::HybridFrfModel::modalTruncation(modes, kEta);
    std::printf("%-14s %6d %12.3e %12.3f %12.2e %14s %10s %10.2e\n", "truncation", m, worstError(truncation, ref),
                modes.seconds, eval, "exact", "1", (truncation.zeroFrequencyCompliance() - Az).norm() / Az.norm());
  }
}

}  // namespace

TEST(GuyanCraigBampton, ConvergenceAndRayleighRitzBound) {
  Timer timer;
  const auto& ref = reference();
  const auto& full = *ref.full;
  ASSERT_EQ(full.copies(), 2);
  const int familyModes = kFamilies * full.copies();
  std::printf("shrouded sector N = 8, cantilever, k = %d, %.0f rpm, eta = %g: %lld equations, %ld retained DOFs; "
              "full model set-up, %d modes (%.2f s) and %zu reference frequencies: %.2f s (%.3f s per frequency)\n",
              kHarmonic, regression::ShroudedSectorCase::kRpm, kEta, full.equations(), long(full.size()), kFullModes,
              ref.modes.seconds, ref.band.size(), timer.seconds(), ref.fullSecondsPerFrequency);
  for (int j = 0; j < kFamilies; ++j) std::printf("  natural frequency %d: %.3f Hz\n", j + 1, ref.natural(j) / (2 * M_PI));
  const Eigen::MatrixXd Az = full.zeroFrequencyCompliance();

  std::printf("%-14s %6s %12s %12s %12s %14s %10s %10s\n", "kind", "modes", "max error", "build [s]", "eval [s]",
              "freq err 1..5", "min MAC", "A(0) err");
  double guyanError = 0;
  checkGuyan(ref, Az, familyModes, guyanError);
  if (HasFatalFailure()) return;

  // Craig-Bampton: one reduction per size, so that the build time is that model's own.
  rom::RetainedModes previousModes;
  double previousError = 1e300;
  double cbError = 0;
  for (int m : kInterfaceModes) {
    timer.restart();
    const auto reduction = rom::reduceOntoRetainedDofs(full, m);
    const rom::CraigBamptonModel cb(reduction, m, kEta);
    const double build = timer.seconds();
    double eval = 0;
    cbError = worstError(cb, ref, &eval);
    const auto cbModes = cb.modes();
    ASSERT_EQ(cbModes.numModes(), full.size() + m * full.copies());
    double mac = 1, freqError = 0;
    for (int j = 0; j < kFamilies; ++j) {
      mac = std::min(mac, familyMac(ref.modes, cbModes, j));
      freqError = std::max(freqError, std::sqrt(cbModes.eigenvalues[std::size_t(j * 2)] /
                                                ref.modes.eigenvalues[std::size_t(j * 2)]) - 1);
    }
    const double zero = (cb.zeroFrequencyCompliance() - Az).norm() / Az.norm();
    std::printf("%-14s %6d %12.3e %12.3f %12.2e %14.3e %10.5f %10.2e\n", "Craig-Bampton", m, cbError, build, eval,
                freqError, mac, zero);
    EXPECT_LT(zero, 1e-10) << m << " modes: Craig-Bampton is exact at zero frequency";
    EXPECT_GT(worstBoundMargin(cbModes, ref.modes, std::min(cbModes.numModes(), ref.modes.numModes())), -1e-10)
        << m << " modes: Craig-Bampton eigenvalues below the full model's";
    EXPECT_LT(cbError, previousError * 1.01) << m << " modes: the error must not grow as modes are added";
    if (previousModes.numModes() > 0) {  // nested Ritz spaces: every eigenvalue falls or stays
      for (int j = 0; j < familyModes; ++j) {
        EXPECT_LE(cbModes.eigenvalues[std::size_t(j)], previousModes.eigenvalues[std::size_t(j)] * (1 + 1e-10));
      }
    }
    if (m >= 20) {
      EXPECT_GT(mac, 0.99) << m << " modes: MAC of the first " << kFamilies << " families";
    }
    previousError = cbError;
    previousModes = cbModes;
  }
  EXPECT_LT(cbError, 1e-3) << "Craig-Bampton must converge to the full compliance over the band";
  EXPECT_GT(guyanError, 10 * cbError) << "Guyan's error must show against the converged Craig-Bampton model";

  printHybridAndTruncationRows(full, ref, Az);
  std::printf("full FE: %.3f s per frequency\n", ref.fullSecondsPerFrequency);
}

TEST(GuyanCraigBampton, ResonancePeaksAtFullNaturalFrequencies) {
  const auto& ref = reference();
  const auto& full = *ref.full;
  const int c = full.copies();
  const int m = 40;  // its natural frequencies within 3e-6 of the full model's (the convergence table)
  const rom::CraigBamptonModel cb(rom::reduceOntoRetainedDofs(full, m), m, kEta);
  const auto hybridModes = ref.modes.first(20);
  const rom::HybridFrfModel hybrid(hybridModes, full.staticCompliance(0.0, hybridModes), kEta);
  const rom::GuyanModel guyan(rom::reduceOntoRetainedDofs(full, 0), kEta);
  // A peak mislocated by 1 % of the half-power bandwidth (eta w_j for structural
  // damping) changes the amplitude read at the true peak by (2 x 0.01)^2 = 0.04 %:
  // below what a response curve shows. The seed's error was a visibly wrong peak.
  const double tolerance = 0.01 * kEta;
  std::printf("%7s %12s %14s %14s %14s %16s  (peak/f_j - 1; tolerance %.1e)\n", "family", "f_j [Hz]", "hybrid",
              "Craig-Bampton", "Guyan", "full peak within", tolerance);
  Timer timer;
  for (int j = 0; j < kPeakFamilies; ++j) {
    // The driving point with the largest participation of this family (both copies of the pair).
    Eigen::Index r = 0;
    ref.modes.shapes.middleCols(j * c, c).rowwise().squaredNorm().maxCoeff(&r);
    const double wj = ref.natural(j);
    const auto magnitude = [r](const rom::ComplianceModel& model, double w) { return std::abs(model.compliance(w)(r, r)); };
    // Each reduced model's peak by golden section over two half-power bandwidths
    // (not beyond half way to a neighbour), to 1e-8 relative.
    double half = 2 * kEta * wj;
    if (j > 0) half = std::min(half, 0.5 * (wj - ref.natural(j - 1)));
    half = std::min(half, 0.5 * (ref.natural(j + 1) - wj));
    const auto peak = [&](const rom::ComplianceModel& model) {
      return peakFrequency([&](double w) { return magnitude(model, w); }, wj - half, wj + half, 40);
    };
    const double wHybrid = peak(hybrid), wCb = peak(cb), wGuyan = peak(guyan);
    // The full FE model's damped peak lies in [lo, hi] around both reduced peaks if its
    // magnitude in the middle exceeds both ends (one maximum in so small an interval):
    // three complex solves prove every reduced peak within (hi - lo) of the full one.
    const double lo = std::min(wHybrid, wCb) - 0.25 * tolerance * wj, hi = std::max(wHybrid, wCb) + 0.25 * tolerance * wj;
    // Any point inside will do: the natural frequency, whose full solve the band has, if it is.
    const auto onBand = std::find(ref.band.begin(), ref.band.end(), wj);
    const bool inside = lo < wj && wj < hi && onBand != ref.band.end();
    const double fMid = inside ? std::abs(ref.compliance[std::size_t(onBand - ref.band.begin())](r, r))
                               : magnitude(full, 0.5 * (lo + hi));
    const double fLo = magnitude(full, lo), fHi = magnitude(full, hi);
    std::printf("%7d %12.4f %14.3e %14.3e %14.3e %16.3e\n", j + 1, wj / (2 * M_PI), wHybrid / wj - 1, wCb / wj - 1,
                wGuyan / wj - 1, (hi - lo) / wj);
    EXPECT_GT(fMid, fLo) << "family " << j + 1 << ": the full model's peak is not at the reduced models' peaks";
    EXPECT_GT(fMid, fHi) << "family " << j + 1 << ": the full model's peak is not at the reduced models' peaks";
    EXPECT_LT((hi - lo) / wj, tolerance) << "family " << j + 1;
    // And at the full model's natural frequency: structural damping puts a lone mode's
    // peak exactly there; the other modes' background moves it by far less than eta.
    EXPECT_LT(std::abs(wHybrid / wj - 1), 0.1 * kEta) << "hybrid, family " << j + 1;
    EXPECT_LT(std::abs(wCb / wj - 1), 0.1 * kEta) << "Craig-Bampton, family " << j + 1;
    // The check has teeth: Guyan's resonance comes too high, outside the bracket.
    EXPECT_GT(wGuyan, hi) << "Guyan's peak must lie above the full model's, family " << j + 1;
  }
  std::printf("peak searches and full solves: %.2f s\n", timer.seconds());
}

TEST(GuyanCraigBampton, FreeSectorRigidBodyModes) {
  // No fixed nodes, k = 0: rotation about and translation along the axis. K_ii is
  // held by the retained DOFs, so the reductions exist and work away from w = 0;
  // at w = 0 there is no compliance, for any kind.
  const regression::ShroudedSectorCase s({}, 0, kEta);
  const rom::NodalDiameterModel full(s.mesh, s.sector, s.problem, Tpetra::getDefaultComm());
  const auto modes = full.modes(12, solvers::ModalOptions::automaticShift());
  ASSERT_EQ(modes.numRigidBodyModes(), 2);
  const auto reduction = rom::reduceOntoRetainedDofs(full, 40);
  const rom::GuyanModel guyan(reduction, kEta);
  const rom::CraigBamptonModel cb(reduction, 40, kEta);
  // Two eigenvalues of each Ritz model at round-off level, the third the full model's first elastic one.
  for (const auto& reduced : {guyan.modes(), cb.modes()}) {
    std::printf("free sector k = 0: reduced eigenvalues %.3e %.3e %.6e, full %.6e (rad/s)^2\n", reduced.eigenvalues[0],
                reduced.eigenvalues[1], reduced.eigenvalues[2], modes.eigenvalues[2]);
    EXPECT_LT(std::abs(reduced.eigenvalues[1]), 1e-6 * modes.eigenvalues[2]);
    EXPECT_GE(reduced.eigenvalues[2], modes.eigenvalues[2] * (1 - 1e-10));
  }
  for (const rom::ComplianceModel* model : {static_cast<const rom::ComplianceModel*>(&full),
                                            static_cast<const rom::ComplianceModel*>(&guyan),
                                            static_cast<const rom::ComplianceModel*>(&cb)}) {
    try {
      model->zeroFrequencyCompliance();
      ADD_FAILURE() << "zero-frequency compliance of a free sector was accepted";
    } catch (const InputError& e) {
      std::printf("free sector, zero frequency: %s\n", e.what());
    }
  }
  const double worst = regression::worstErrorAround(cb, full, std::sqrt(modes.eigenvalues[2]));
  std::printf("free sector k = 0, Craig-Bampton with 40 modes: max relative error %.3e\n", worst);
  EXPECT_LT(worst, 1e-3);
}

TEST(GuyanCraigBampton, BadInput) {
  regression::ShroudedSectorCase s({"bore"}, kHarmonic, kEta);
  const auto comm = Tpetra::getDefaultComm();
  const auto expectInputError = [](const std::function<void()>& f, const std::string& where, const std::string& what) {
    try {
      f();
      ADD_FAILURE() << "accepted: expected an InputError at " << where;
    } catch (const InputError& e) {
      std::printf("bad input: %s\n", e.what());
      EXPECT_EQ(e.where(), where);
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
  };
  // A nodal diameter below 0 (above N/2 is in hybrid_frf_vs_full).
  auto problem = s.problem;
  problem.nodalDiameter = -1;
  EXPECT_THROW(rom::NodalDiameterModel(s.mesh, s.sector, problem, comm), InputError);
  // An empty retained set.
  s.mesh.nodeSets["empty"] = {};
  problem = s.problem;
  problem.retainedNodeSets = {"empty"};
  EXPECT_THROW(rom::NodalDiameterModel(s.mesh, s.sector, problem, comm), InputError);

  // Retained DOFs that cannot be boundary coordinates.
  s.mesh.nodeSets["bore_node"] = {s.mesh.nodeSet("bore").front()};
  problem = s.problem;
  problem.retainedNodeSets = {"mid_blade", "bore_node"};
  const rom::NodalDiameterModel heldAtRetained(s.mesh, s.sector, problem, comm);
  expectInputError([&] { rom::reduceOntoRetainedDofs(heldAtRetained, 0); }, "retained", "is fixed");
  // A right disc face node: a combination of left-face unknowns (the full model takes it).
  mesh::Index rightNode = -1;
  for (mesh::Index n : s.mesh.nodeSet("disc_right"))
    if (std::find(s.mesh.nodeSet("bore").begin(), s.mesh.nodeSet("bore").end(), n) == s.mesh.nodeSet("bore").end())
      rightNode = n;
  ASSERT_GE(rightNode, 0);
  s.mesh.nodeSets["right_face_node"] = {rightNode};
  problem.retainedNodeSets = {"mid_blade", "right_face_node"};
  const rom::NodalDiameterModel onRightFace(s.mesh, s.sector, problem, comm);
  EXPECT_GT(onRightFace.zeroFrequencyCompliance().norm(), 0);
  expectInputError([&] { rom::reduceOntoRetainedDofs(onRightFace, 0); }, "retained", "combination of unknowns");

  // Fixed-interface mode counts.
  const rom::NodalDiameterModel model(s.mesh, s.sector, s.problem, comm);
  expectInputError([&] { rom::reduceOntoRetainedDofs(model, -1); }, "fixed_interface_modes", "must be >= 0");
  expectInputError([&] { rom::reduceOntoRetainedDofs(model, int(model.equations())); }, "fixed_interface_modes",
                   "the interior has");
  const auto reduction = rom::reduceOntoRetainedDofs(model, 3);
  expectInputError([&] { rom::CraigBamptonModel(reduction, 0, kEta); }, "fixed_interface_modes", "Guyan");
  expectInputError([&] { rom::CraigBamptonModel(reduction, 4, kEta); }, "fixed_interface_modes", "has 3");
  expectInputError([&] { rom::GuyanModel(reduction, -0.1); }, "loss_factor", ">= 0");

  // Hybrid: w0 above the highest computed mode, and modes of another model.
  const auto modes = model.modes(3);
  expectInputError([&] { model.staticCompliance(2 * std::sqrt(modes.eigenvalues.back()), modes); }, "omega0",
                   "not below the highest computed");
  expectInputError([&] { model.staticCompliance(0.0, onRightFace.modes(3)); }, "modes", "not computed with this model");
}
