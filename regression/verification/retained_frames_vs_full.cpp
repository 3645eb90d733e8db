// Verification: retained DOFs in chosen directions of given local frames, on
// the case of the reduced-model proofs (built-in sector N = 8, cantilever,
// 10 000 rpm linear prestress, k = 2, eta = 0.005). The contact nodes keep 2
// directions (0 and 2) of an oblique orthonormal frame, the mid-blade node its
// global y only. The reference is the full FE compliance in x, y, z (unit loads
// at the nodes along the axes) turned into the frame by the test itself:
// A_frame = T^T A_xyz T, T holding the frame vectors; against it
//   - the full FE model in the frame (unit loads along the frame vectors);
//   - the hybrid model and modal truncation built in the frame;
//   - Guyan and Craig-Bampton with the chosen directions as the boundary and the
//     others condensed (exact at zero frequency; Craig-Bampton converging; the
//     subset's Guyan frequencies at or above those with all 3 directions kept,
//     its Ritz space being a subspace);
//   - Guyan with all 3 frame directions equal to T^T A_Guyan,xyz T (same Ritz space);
// and the frame and direction checks name the set.
#include <Tpetra_Core.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>

#include "ShroudedSectorCase.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/rom/BoundaryReduction.hpp"
#include "cyclone/rom/CraigBamptonModel.hpp"
#include "cyclone/rom/NodalDiameterModel.hpp"
#include "cyclone/rom/GuyanModel.hpp"

using namespace cyclone;
using regression::relativeError;

namespace {

constexpr int kHarmonic = 2;
constexpr double kEta = 0.005;
constexpr int kFamilies = 5;

// An oblique orthonormal frame: rows are its unit vectors (a rotation by 0.7 rad about (1, 2, 3)).
Eigen::Matrix3d obliqueFrame() {
  return Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix().transpose();
}

rom::RetainedDirections contactDirections(std::vector<int> directions) {
  rom::RetainedDirections d;
  d.directions = std::move(directions);
  d.frame = obliqueFrame();
  return d;
}

struct Reference {
  regression::ShroudedSectorCase sector{{"bore"}, kHarmonic, kEta};
  std::unique_ptr<rom::NodalDiameterModel> xyz;  // all 3 global directions: the reference
  rom::RetainedModes modes;
  std::vector<double> band;
  std::vector<Eigen::MatrixXcd> compliance;  // A_xyz over the band

  Reference() {
    xyz = std::make_unique<rom::NodalDiameterModel>(sector.mesh, sector.sector, sector.problem,
                                                     Tpetra::getDefaultComm());
    modes = xyz->modes(20);
    band = regression::frequencyBand(modes, kFamilies);
    for (double w : band) compliance.push_back(xyz->compliance(w));
  }

  // The problem with the contact nodes in the oblique frame (`contact` directions) and
  // mid_blade in `midBlade` global directions.
  rom::NodalDiameterModelProblem framed(std::vector<int> contact, std::vector<int> midBlade) const {
    auto p = sector.problem;
    p.retainedDirections["rom_contact"] = contactDirections(std::move(contact));
    rom::RetainedDirections mid;
    mid.directions = std::move(midBlade);
    p.retainedDirections["mid_blade"] = mid;
    return p;
  }

  // T: the xyz model's retained DOFs x the framed ones, built here from the sets and the
  // frame (not from the model under test): column = the DOF's unit vector at its node's rows.
  Eigen::MatrixXd transform(const std::vector<int>& contact, const std::vector<int>& midBlade) const {
    const auto& contactNodes = sector.mesh.nodeSet("rom_contact");
    const auto& midNodes = sector.mesh.nodeSet("mid_blade");
    const auto nn = Eigen::Index(xyz->retainedNodes().size());
    EXPECT_EQ(std::size_t(nn), contactNodes.size() + midNodes.size());
    const Eigen::Index perCopy =
        Eigen::Index(contactNodes.size() * contact.size() + midNodes.size() * midBlade.size());
    const int copies = xyz->copies();
    Eigen::MatrixXd T = Eigen::MatrixXd::Zero(xyz->size(), perCopy * copies);
    const Eigen::Matrix3d R = obliqueFrame();
    for (int c = 0; c < copies; ++c) {
      Eigen::Index col = c * perCopy;
      for (Eigen::Index i = 0; i < nn; ++i) {
        const bool isContact = std::size_t(i) < contactNodes.size();
        for (int j : isContact ? contact : midBlade) {
          const Eigen::Vector3d axis = isContact ? Eigen::Vector3d(R.row(j)) : Eigen::Vector3d::Unit(j);
          T.block((c * nn + i) * 3, col++, 3, 1) = axis;
        }
      }
    }
    return T;
  }
};

const Reference& reference() {
  static const Reference* r = new Reference;  // never freed: Tpetra must not outlive Kokkos
  return *r;
}

double worstError(const rom::ComplianceModel& model, const Reference& ref, const Eigen::MatrixXd& T) {
  double worst = 0;
  for (std::size_t i = 0; i < ref.band.size(); ++i)
    worst = std::max(worst, relativeError(model.compliance(ref.band[i]), T.transpose() * ref.compliance[i] * T));
  return worst;
}

const std::vector<int> kContact{0, 2}, kMidBlade{1};

}  // namespace

TEST(RetainedFrames, FullModelInFrameIsTheRotatedCompliance) {
  Timer timer;
  const auto& ref = reference();
  const auto& s = ref.sector;
  const rom::NodalDiameterModel framed(s.mesh, s.sector, ref.framed(kContact, kMidBlade), Tpetra::getDefaultComm());
  const Eigen::MatrixXd T = ref.transform(kContact, kMidBlade);
  ASSERT_EQ(framed.size(), T.cols());
  ASSERT_EQ(framed.size(), 2 * (4 * 2 + 1));  // 4 contact nodes x 2 directions + mid-blade y, 2 copies
  EXPECT_EQ(framed.retainedNodes(), ref.xyz->retainedNodes());
  double worst = relativeError(framed.zeroFrequencyCompliance(),
                               T.transpose() * ref.xyz->zeroFrequencyCompliance() * T);
  for (std::size_t i : {std::size_t(0), std::size_t(2), std::size_t(6)})  // below, on and between resonances
    worst = std::max(worst, relativeError(framed.compliance(ref.band[i]), T.transpose() * ref.compliance[i] * T));
  std::printf("full FE in the frame against T^T A_xyz T: %.3e (%.1f s with the reference)\n", worst, timer.seconds());
  EXPECT_LT(worst, 1e-9);
}

TEST(RetainedFrames, ReducedModelsInFrameAgainstFull) {
  const auto& ref = reference();
  const auto& s = ref.sector;
  const auto comm = Tpetra::getDefaultComm();
  const rom::NodalDiameterModel framed(s.mesh, s.sector, ref.framed(kContact, kMidBlade), comm);
  const Eigen::MatrixXd T = ref.transform(kContact, kMidBlade);
  const Eigen::MatrixXd Az = T.transpose() * ref.xyz->zeroFrequencyCompliance() * T;

  // Guyan's and Craig-Bampton's static compliance is exact: against the reference's it
  // differs by the rounding of its own path (the interior factored, the Schur complement
  // K_g inverted): 1.1e-10 once the mid-blade point became a mesh node with smaller
  // elements beside it, where the hybrid's (the reference's own factor) stays at 4e-15;
  // far below the truncation errors the test tells apart (1e-3 and above).
  constexpr double kStaticRounding = 1e-9;

  // Compliance models: the hybrid model and truncation in the frame (20 modes).
  Timer timer;
  const auto modes = framed.modes(20);
  const rom::HybridFrfModel hybrid(modes, framed.staticCompliance(0.0, modes), kEta);
  const auto truncation = rom::HybridFrfModel::modalTruncation(modes, kEta);
  const double hybridError = worstError(hybrid, ref, T), truncationError = worstError(truncation, ref, T);
  std::printf("in the frame (%ld DOFs), %zu frequencies over %d families:\n  hybrid 20 modes %.3e, truncation "
              "20 modes %.3e (%.1f s)\n",
              long(framed.size()), ref.band.size(), kFamilies, hybridError, truncationError, timer.seconds());
  EXPECT_LT(hybridError, 1e-3);
  EXPECT_GT(truncationError, 10 * hybridError) << "the static correction must show in the frame too";
  const double hybridZero = relativeError(hybrid.zeroFrequencyCompliance(), Az);
  std::printf("  hybrid at zero frequency %.3e\n", hybridZero);
  EXPECT_LT(hybridZero, 1e-10);

  // Guyan with the chosen directions as boundary, the rest condensed.
  timer.restart();
  const rom::GuyanModel guyan(rom::reduceOntoRetainedDofs(framed, 0), kEta);
  const double guyanZero = relativeError(guyan.zeroFrequencyCompliance(), Az);
  const double guyanError = worstError(guyan, ref, T);
  std::printf("  Guyan %.3e, at zero frequency %.3e (%.1f s)\n", guyanError, guyanZero, timer.seconds());
  EXPECT_LT(guyanZero, kStaticRounding);
  // Fewer boundary DOFs, a subspace of the Ritz space with all 3 global directions:
  // its eigenvalues at or above that model's, which are at or above the full model's.
  const rom::GuyanModel guyanXyz(rom::reduceOntoRetainedDofs(*ref.xyz, 0), kEta);
  for (int j = 0; j < kFamilies * framed.copies(); ++j) {
    EXPECT_GE(guyan.modes().eigenvalues[std::size_t(j)], guyanXyz.modes().eigenvalues[std::size_t(j)] * (1 - 1e-10)) << j;
    EXPECT_GE(guyanXyz.modes().eigenvalues[std::size_t(j)], ref.modes.eigenvalues[std::size_t(j)] * (1 - 1e-10)) << j;
  }
  std::printf("  first Guyan frequency: subset in frame %.4f Hz, xyz %.4f Hz, full %.4f Hz\n",
              std::sqrt(guyan.modes().eigenvalues[0]) / (2 * M_PI), std::sqrt(guyanXyz.modes().eigenvalues[0]) / (2 * M_PI),
              std::sqrt(ref.modes.eigenvalues[0]) / (2 * M_PI));

  // Craig-Bampton converging as interface modes are added.
  timer.restart();
  const auto reduction = rom::reduceOntoRetainedDofs(framed, 40);
  double previous = 1e300;
  for (int m : {10, 20, 40}) {
    const rom::CraigBamptonModel cb(reduction, m, kEta);
    const double error = worstError(cb, ref, T);
    std::printf("  Craig-Bampton %d interface modes %.3e, at zero frequency %.3e\n", m, error,
                relativeError(cb.zeroFrequencyCompliance(), Az));
    EXPECT_LT(error, previous);
    EXPECT_LT(relativeError(cb.zeroFrequencyCompliance(), Az), kStaticRounding);
    previous = error;
  }
  std::printf("  (reduction with 40 interface modes and the 3 models: %.1f s)\n", timer.seconds());
  EXPECT_LT(previous, 1e-2);
  EXPECT_GT(guyanError, 10 * previous);
}

TEST(RetainedFrames, GuyanWithAllFrameDirectionsIsTheRotatedGuyan) {
  // Same boundary DOFs, only rotated: the same Ritz space, so A = T^T A_Guyan,xyz T.
  const auto& ref = reference();
  const auto& s = ref.sector;
  const std::vector<int> all{0, 1, 2};
  const rom::NodalDiameterModel framed(s.mesh, s.sector, ref.framed(all, all), Tpetra::getDefaultComm());
  const Eigen::MatrixXd T = ref.transform(all, all);
  const rom::GuyanModel guyan(rom::reduceOntoRetainedDofs(framed, 0), kEta);
  const rom::GuyanModel guyanXyz(rom::reduceOntoRetainedDofs(*ref.xyz, 0), kEta);
  const double stiffness = (guyan.stiffness() - T.transpose() * guyanXyz.stiffness() * T).norm() / guyan.stiffness().norm();
  const double mass = (guyan.mass() - T.transpose() * guyanXyz.mass() * T).norm() / guyan.mass().norm();
  double worst = 0;
  for (double w : ref.band) worst = std::max(worst, relativeError(guyan.compliance(w), T.transpose() * guyanXyz.compliance(w) * T));
  std::printf("Guyan in the frame (all 3 directions) against T^T (Guyan in x, y, z) T: K_g %.3e, M_g %.3e, "
              "compliance over the band %.3e (the modal form near resonances amplifies round-off by 1 / eta)\n",
              stiffness, mass, worst);
  EXPECT_LT(stiffness, 1e-11);
  EXPECT_LT(mass, 1e-11);
  EXPECT_LT(worst, 1e-7);
}

TEST(RetainedFrames, BadFramesAndDirectionsAreNamed) {
  const auto& s = reference().sector;
  const auto expectInputError = [&](rom::NodalDiameterModelProblem problem, const std::string& where) {
    try {
      rom::NodalDiameterModel(s.mesh, s.sector, problem, Tpetra::getDefaultComm());
      ADD_FAILURE() << "accepted: expected an InputError at " << where;
    } catch (const InputError& e) {
      EXPECT_EQ(e.where(), where) << e.what();
    }
  };
  auto problem = s.problem;
  auto d = contactDirections({0, 2});
  d.frame.row(1) *= 1.01;  // not unit length
  problem.retainedDirections["rom_contact"] = d;
  expectInputError(problem, "retained/rom_contact/frame");
  d = contactDirections({0, 2});
  d.frame.row(2) = d.frame.row(0);  // not perpendicular
  problem.retainedDirections["rom_contact"] = d;
  expectInputError(problem, "retained/rom_contact/frame");
  problem.retainedDirections["rom_contact"] = contactDirections({0, 0});
  expectInputError(problem, "retained/rom_contact/directions");
  problem.retainedDirections["rom_contact"] = contactDirections({3});
  expectInputError(problem, "retained/rom_contact/directions");
  problem.retainedDirections["rom_contact"] = contactDirections({});
  expectInputError(problem, "retained/rom_contact/directions");
  problem = s.problem;
  problem.retainedDirections["bore"] = contactDirections({0});
  expectInputError(problem, "retained/bore");  // not a retained set
  // A node retained twice with different choices.
  auto mesh = s.mesh;
  mesh.nodeSets["contact_again"] = {mesh.nodeSet("rom_contact").front()};
  problem = s.problem;
  problem.retainedNodeSets.push_back("contact_again");
  problem.retainedDirections["contact_again"] = contactDirections({1});
  try {
    rom::NodalDiameterModel(mesh, s.sector, problem, Tpetra::getDefaultComm());
    ADD_FAILURE() << "a node retained with two frames was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "retained/contact_again") << e.what();
  }
}

// Retained means: the contact nodes as two weighted means (a left-face pair and a
// right-face pair, as a contact patch's mean motion of each side), the mid-blade node as
// itself. The reference is again the xyz model's compliance turned by the test: the
// mean's column of T holds its weights at its nodes' rows. Against it the full FE model
// at the means (its loads spread by the weights), its static compliance (on this two-copy
// nodal diameter, copy 1's loads solved as copy 0's rotated) and the hybrid model; Guyan
// refuses a mean (a boundary DOF is one unknown).
TEST(RetainedFrames, MeansOfNodesAreTheWeightedCompliance) {
  const auto& ref = reference();
  const auto& s = ref.sector;
  const auto comm = Tpetra::getDefaultComm();
  const auto& contact = s.mesh.nodeSet("rom_contact");  // left, left, right, right
  ASSERT_EQ(contact.size(), 4u);
  std::vector<rom::RetainedMean> means{{"left pair", {contact[0], contact[1]}, {0.25, 0.75}},
                                       {"right pair", {contact[2], contact[3]}, {0.6, 0.4}}};
  auto problem = s.problem;
  problem.retainedNodeSets = {"mid_blade"};
  problem.retainedMeans = means;
  const rom::NodalDiameterModel meaned(s.mesh, s.sector, problem, comm);
  ASSERT_EQ(meaned.copies(), 2);
  ASSERT_EQ(meaned.size(), 2 * (3 + 2 * 3));

  // T from the sets and weights: the xyz model retains rom_contact's nodes then mid_blade's.
  const auto& nodes = ref.xyz->retainedNodes();
  const auto nn = Eigen::Index(nodes.size());
  const auto row = [&](mesh::Index node, int d, int c) {
    const auto i = Eigen::Index(std::find(nodes.begin(), nodes.end(), node) - nodes.begin());
    EXPECT_LT(i, nn);
    return (c * nn + i) * 3 + d;
  };
  const Eigen::Index perCopy = meaned.size() / 2;
  Eigen::MatrixXd T = Eigen::MatrixXd::Zero(ref.xyz->size(), meaned.size());
  for (int c = 0; c < 2; ++c) {
    Eigen::Index col = c * perCopy;
    for (int d = 0; d < 3; ++d) T(row(s.mesh.nodeSet("mid_blade").front(), d, c), col++) = 1;
    for (const auto& m : means)
      for (int d = 0; d < 3; ++d, ++col)
        for (std::size_t i = 0; i < m.nodes.size(); ++i) T(row(m.nodes[i], d, c), col) = m.weights[i];
  }

  Timer timer;
  double full = relativeError(meaned.zeroFrequencyCompliance(), T.transpose() * ref.xyz->zeroFrequencyCompliance() * T);
  for (std::size_t i : {std::size_t(0), std::size_t(2), std::size_t(6)})
    full = std::max(full, relativeError(meaned.compliance(ref.band[i]), T.transpose() * ref.compliance[i] * T));
  const auto modes = meaned.modes(20);
  const rom::HybridFrfModel hybrid(modes, meaned.staticCompliance(0.0, modes), kEta);
  const auto truncation = rom::HybridFrfModel::modalTruncation(modes, kEta);
  const double hybridError = worstError(hybrid, ref, T), truncationError = worstError(truncation, ref, T);
  const double hybridZero = relativeError(hybrid.zeroFrequencyCompliance(), T.transpose() * ref.xyz->zeroFrequencyCompliance() * T);
  std::printf("retained means (%ld DOFs): full FE against T^T A_xyz T %.3e; hybrid 20 modes %.3e (at zero frequency "
              "%.3e), truncation %.3e (%.1f s)\n",
              long(meaned.size()), full, hybridError, hybridZero, truncationError, timer.seconds());
  EXPECT_LT(full, 1e-9);
  EXPECT_LT(hybridZero, 1e-10);
  EXPECT_LT(hybridError, 1e-3);
  EXPECT_GT(truncationError, 10 * hybridError);
  EXPECT_THROW(rom::reduceOntoRetainedDofs(meaned, 0), InputError);

  // A mean's weights are checked, naming it.
  auto bad = problem;
  bad.retainedMeans[1].weights = {0.5, -0.5};
  try {
    rom::NodalDiameterModel(s.mesh, s.sector, bad, comm);
    ADD_FAILURE() << "a negative weight was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("retained/means/right pair"), std::string::npos) << e.what();
  }
}
