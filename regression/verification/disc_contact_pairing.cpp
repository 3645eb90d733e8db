// The shroud's contact pairs are found by the sector rotation, not by the order of the
// node sets: a mesh tool writes its sets sorted by node id, and such a mesh was refused
// after the reduced models' work ("contact node pairs do not match ... in set order").
// On a small built-in disc (8 sectors, mesh size 12, EO 1 at rest, H = 2, 100 N preload
// against 5 N) the harmonic balance with both contact sets shuffled is the ordered sets'
// system: its residual at the same unknowns (every retained DOF, near the stuck
// resonance, partly slipping and open) agrees to rounding, and Newton from there reaches
// the same solution where the curve starts. (Whole friction curves are no test of this: rounding alone moves the
// path among the sampled law's kinks.) A right node without a partner is refused naming
// the contact and the node, with the mesh and the axis only: before any model is built.
#include <Tpetra_Core.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "cyclone/continuation/NewtonSolve.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/disc/DiscForcedResponse.hpp"
#include "cyclone/disc/ShroudContactLaw.hpp"
#include "cyclone/mesh/ShroudedSectorGenerator.hpp"

using namespace cyclone;

namespace {

// The small disc (8 sectors, mesh size 12) and its reduced models (10 modes) for `spec`'s
// harmonics at EO 1; the unknowns every retained DOF (spec.condensed off), so systems made
// from differently ordered sets share their layout.
struct SmallDisc {
  mesh::ShroudedSectorParameters geometry;
  mesh::Mesh mesh;
  disc::DiscReducedModels models;
  double modelSeconds = 0;
};
SmallDisc smallDisc(disc::DiscResponseSpec& spec) {
  Timer timer;
  SmallDisc d;
  d.geometry.sectors = 8;
  d.geometry.meshSize = 12.0;
  d.mesh = mesh::generateShroudedSector(d.geometry);
  disc::DiscModelSpec modelSpec;
  modelSpec.sectors = d.geometry.sectors;
  modelSpec.modes = 10;
  spec.engineOrder = 1;
  spec.excitation.amplitude = 5.0;
  spec.condensed = false;
  d.models = disc::buildDiscReducedModels(d.mesh, modelSpec, disc::nodalDiametersFor(8, 1, spec.harmonics), "",
                                          Tpetra::getDefaultComm());
  d.modelSeconds = timer.seconds();
  return d;
}

}  // namespace

TEST(DiscContactPairing, ContactSetsInAnyOrderGiveTheSameSystem) {
  log::setQuiet(true);
  disc::DiscResponseSpec spec;
  spec.harmonics = {0, 1, 2};
  spec.contact.preload = 100.0;
  const SmallDisc d = smallDisc(spec);
  const auto& mesh = d.mesh;
  const auto& p = d.geometry;
  const auto& models = d.models;
  const double modelSeconds = d.modelSeconds;

  mesh::Mesh shuffled = mesh;
  std::mt19937 random(7);
  for (const auto& set : {spec.contact.leftSet, spec.contact.rightSet})
    std::shuffle(shuffled.nodeSets.at(set).begin(), shuffled.nodeSets.at(set).end(), random);
  ASSERT_NE(shuffled.nodeSet(spec.contact.leftSet), mesh.nodeSet(spec.contact.leftSet));

  auto ordered = disc::makeDiscForcedResponse(mesh, models, spec);
  auto other = disc::makeDiscForcedResponse(shuffled, models, spec);
  auto estimate = disc::estimateResonance(ordered, models);
  const double omega = 2 * M_PI * estimate.stuckHz;
  // Unknowns near the stuck resonance: the response linearised at rest, doubled, so that
  // contacts slip and open.
  const Eigen::VectorXd X = 2.0 * ordered.system->linearizedSolution(omega);
  Eigen::VectorXd Ra, Rb;
  Eigen::MatrixXd Ja, Jb;
  ordered.system->residual(X, omega, Ra, &Ja);
  other.system->residual(X, omega, Rb, &Jb);
  const double residualDifference = (Ra - Rb).cwiseAbs().maxCoeff() / Ra.cwiseAbs().maxCoeff();
  const double jacobianDifference = (Ja - Jb).cwiseAbs().maxCoeff() / Ja.cwiseAbs().maxCoeff();
  EXPECT_LT(residualDifference, 1e-12);
  EXPECT_LT(jacobianDifference, 1e-12);

  // Newton on each system below the resonances (at 0.9 x the shroud-free one, where the
  // curve starts), from the response linearised there.
  const double below = 0.9 * 2 * M_PI * estimate.freeHz;
  const auto solve = [below](const response::ForcedResponseSetup& setup, Eigen::VectorXd x) {
    const auto problem =
        response::continuationProblem(*setup.system, response::ForcedResponseSetup::Parameter::ForceScale, below);
    const auto newton = continuation::solveNewton(problem, x, 1.0, 1e-8, 100);
    EXPECT_TRUE(newton.converged) << "residual " << newton.residualNorm << " after " << newton.iterations;
    return x;
  };
  const Eigen::VectorXd start = ordered.system->linearizedSolution(below);
  const Eigen::VectorXd a = solve(ordered, start), b = solve(other, start);
  const double solutionDifference = (a - b).cwiseAbs().maxCoeff() / a.cwiseAbs().maxCoeff();
  EXPECT_LT(solutionDifference, 1e-8);
  std::printf("%zu contact pairs, %d unknowns (models %.1f s): at %.3f Hz the shuffled sets' residual %.1e, "
              "Jacobian %.1e, and Newton's solution at %.3f Hz %.1e, from the ordered sets' (relative)\n",
              mesh.nodeSet(spec.contact.leftSet).size(), ordered.system->numUnknowns(), modelSeconds,
              estimate.stuckHz, residualDifference, jacobianDifference, below / (2 * M_PI), solutionDifference);

  // A right node with no partner: refused, naming the contact and the node sets.
  mesh::Mesh broken = mesh;
  broken.nodeSets.at(spec.contact.rightSet).back() = broken.nodeSet("disc_right").front();
  try {
    disc::shroudContactPairs(broken, p.sectors, models.sector.axis, spec.contact);
    ADD_FAILURE() << "a contact node without a partner was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "contact");
    EXPECT_NE(std::string(e.what()).find("shroud_contact_right"), std::string::npos) << e.what();
    std::printf("refused: %s\n", e.what());
  }
}

// The law per unit area on the small disc: each pair's stiffness and preload follow its
// node's tributary area, the interface's totals are the spec's (kn times the face's area,
// the total load), and a continuation in the preload or the stiffness (peak following)
// moves each pair's by its share: the system at another value by the weights equals the
// system made at that value, to rounding.
TEST(DiscContactPairing, LawPerAreaSpreadsTheInterfaceByArea) {
  log::setQuiet(true);
  disc::DiscResponseSpec spec;
  spec.harmonics = {0, 1};
  spec.contact.law = disc::ShroudContactSpec::Law::PerArea;
  spec.contact.kn = spec.contact.kt = 5e3;  // N/mm^3
  spec.contact.preload = 2000.0;            // N over the interface
  const SmallDisc d = smallDisc(spec);
  const auto& mesh = d.mesh;
  const auto& p = d.geometry;
  const auto& models = d.models;
  const auto pairs = disc::shroudContactPairs(mesh, p.sectors, models.sector.axis, spec.contact);
  const auto values = disc::shroudContactValues(mesh, pairs, spec.contact);
  // The shroud's side face: its width times its thickness.
  EXPECT_NEAR(values.totalArea, p.shroudWidth * p.shroudThickness, 1e-9 * values.totalArea);
  EXPECT_NEAR(values.totalKn, spec.contact.kn * values.totalArea, 1e-9 * values.totalKn);
  EXPECT_NEAR(values.totalPreload, spec.contact.preload, 1e-9 * spec.contact.preload);
  const auto [smallest, largest] = std::minmax_element(values.area.begin(), values.area.end());
  std::printf("%s; tributary areas %.4g .. %.4g mm^2\n", values.text.c_str(), *smallest, *largest);

  auto at = [&](disc::DiscResponseSpec s) { return disc::makeDiscForcedResponse(mesh, models, s); };
  auto reference = at(spec);
  const double omega = 2 * M_PI * disc::estimateResonance(reference, models).stuckHz;
  const Eigen::VectorXd X = 2.0 * reference.system->linearizedSolution(omega);
  for (const std::string parameter : {"preload", "stiffness"}) {
    auto following = at(spec);
    const double value = parameter == "preload" ? 700.0 : 8e3;
    std::vector<double> weights = parameter == "preload" ? values.preloadFactor : values.stiffnessFactor;
    response::selectElementParameter(following, "contact", parameter, value, weights);
    following.apply(value);
    auto direct = spec;
    if (parameter == "preload") direct.contact.preload = value;
    else direct.contact.kn = direct.contact.kt = value;
    const auto made = at(direct);
    Eigen::VectorXd Ra, Rb;
    following.system->residual(X, omega, Ra, nullptr);
    made.system->residual(X, omega, Rb, nullptr);
    const double difference = (Ra - Rb).cwiseAbs().maxCoeff() / Rb.cwiseAbs().maxCoeff();
    EXPECT_LT(difference, 1e-12) << parameter;
    std::printf("%s continued to %g: residual %.1e from the system made at that value\n", parameter.c_str(), value,
                difference);
  }
}

// Patches (contact/patches): each patch is one contact on its pairs' motion weighted by
// their tributary areas, its stiffness and load the sum of theirs. The friction law is
// homogeneous in its stiffnesses and load (kn, kt, N0 scaled by c scale its force by c),
// so where every pair moves alike the patched system is the every-pair system: the
// residuals agree to rounding, at a motion whose contacts slip and open. Where the pairs
// move differently they do not (the check can fail), and as many patches as pairs is
// the every-pair system at any motion. A continuation in the preload or the stiffness
// moves each patch's by its factor.
TEST(DiscContactPairing, PatchesAreTheirPairsMovingAlike) {
  log::setQuiet(true);
  disc::DiscResponseSpec spec;
  spec.harmonics = {0, 1, 2};
  spec.contact.law = disc::ShroudContactSpec::Law::PerArea;
  spec.contact.kn = spec.contact.kt = 5e3;  // N/mm^3
  spec.contact.preload = 2000.0;            // N over the interface
  const SmallDisc d = smallDisc(spec);
  const auto& models = d.models;
  const auto pairs = disc::shroudContactPairs(d.mesh, d.geometry.sectors, models.sector.axis, spec.contact);
  const int n = int(pairs.right.size());
  auto patched = spec;
  patched.contact.patches = 4;
  auto one = spec;
  one.contact.patches = n;
  auto every = disc::makeDiscForcedResponse(d.mesh, models, spec);
  const auto four = disc::makeDiscForcedResponse(d.mesh, models, patched);
  const auto single = disc::makeDiscForcedResponse(d.mesh, models, one);
  const auto values = disc::shroudContactValues(d.mesh, pairs, patched.contact);
  const auto all = disc::shroudContactValues(d.mesh, pairs, spec.contact);
  ASSERT_EQ(values.kn.size(), 4u);
  EXPECT_NEAR(values.totalKn, all.totalKn, 1e-12 * all.totalKn);
  EXPECT_NEAR(values.totalPreload, all.totalPreload, 1e-12 * all.totalPreload);
  std::printf("%s\n", values.text.c_str());

  auto& hb = *every.system;
  const int nc = hb.numCoefficients();
  const double omega = 2 * M_PI * disc::estimateResonance(every, models).stuckHz;
  // Near the stuck resonance, doubled: contacts slip and open.
  const Eigen::VectorXd X = 2.0 * hb.linearizedSolution(omega);
  auto retained = [&](mesh::Index node) {
    const auto it = std::find(models.retainedNodes.begin(), models.retainedNodes.end(), node);
    return int(it - models.retainedNodes.begin());
  };
  // Every right node moves as the first right node, every left node as the first left node.
  Eigen::VectorXd alike = X;
  const int r0 = retained(pairs.right[0]), l0 = retained(pairs.left[0]);
  for (int i = 0; i < n; ++i)
    for (const auto& [node, from] : {std::pair{pairs.right[std::size_t(i)], r0}, {pairs.left[std::size_t(i)], l0}})
      alike.segment(3 * retained(node) * nc, 3 * nc) = X.segment(3 * from * nc, 3 * nc);
  auto difference = [&](const response::ForcedResponseSetup& a, const response::ForcedResponseSetup& b,
                         const Eigen::VectorXd& x) {
    Eigen::VectorXd Ra, Rb;
    a.system->residual(x, omega, Ra, nullptr);
    b.system->residual(x, omega, Rb, nullptr);
    return (Ra - Rb).cwiseAbs().maxCoeff() / Ra.cwiseAbs().maxCoeff();
  };
  // The contacts at `alike` are not the linear springs: halving the motion does not halve
  // the residual's change from rest.
  Eigen::VectorXd R0, Rhalf, Rfull;
  hb.residual(Eigen::VectorXd::Zero(X.size()), omega, R0, nullptr);
  hb.residual(0.5 * alike, omega, Rhalf, nullptr);
  hb.residual(alike, omega, Rfull, nullptr);
  const double nonlinearity = (Rfull - R0 - 2 * (Rhalf - R0)).norm() / (Rfull - R0).norm();
  EXPECT_GT(nonlinearity, 1e-3);
  const double movingAlike = difference(every, four, alike), apart = difference(every, four, X),
               onePairEach = difference(every, single, X);
  EXPECT_LT(movingAlike, 1e-12);
  EXPECT_GT(apart, 1e-4);
  EXPECT_LT(onePairEach, 1e-12);
  // A continuation of the preload or stiffness moves each patch's by its factor
  // (DiscPeakFollowing's weights): the system at another value equals the one made there.
  for (const std::string parameter : {"preload", "stiffness"}) {
    auto following = disc::makeDiscForcedResponse(d.mesh, models, patched);
    const double value = parameter == "preload" ? 700.0 : 8e3;
    response::selectElementParameter(following, "contact", parameter, value,
                                     parameter == "preload" ? values.preloadFactor : values.stiffnessFactor);
    following.apply(value);
    auto direct = patched;
    if (parameter == "preload") direct.contact.preload = value;
    else direct.contact.kn = direct.contact.kt = value;
    EXPECT_LT(difference(following, disc::makeDiscForcedResponse(d.mesh, models, direct), X), 1e-12) << parameter;
  }
  std::printf("%d pairs in 4 patches at %.2f Hz: residual %.1e from every pair's where the pairs move alike (the "
              "contacts' nonlinearity there %.2f), %.1e where they do not; %d patches of one pair %.1e\n",
              n, omega / (2 * M_PI), movingAlike, nonlinearity, apart, n, onePairEach);
}
