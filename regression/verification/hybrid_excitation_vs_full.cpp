// Verification: the excitation part of the hybrid model (seed eqs. 5.27-5.35),
// the response at the retained DOFs to loads that do not act there,
//   x_r(w) = A_rf(w) f = A0_rf f / (1 + i eta) + sum_j phi_r,j (phi_j^T f) [...],
// A0_rf f from one extra right-hand side of the static solve, against the full
// FE response G^T ((1 + i eta) K - w^2 M)^{-1} f (a complex solve per frequency)
// on the case of the reduced-model proofs (N = 8, cantilever, 10 000 rpm, k = 2,
// eta = 0.005) over a band covering the first 5 families. Load patterns: a force
// at the non-retained node farthest from the axis (real-form copy 0); a load
// distributed over the shroud's left face on both copies; a unit force at a
// retained DOF (its response is that DOF's compliance column: the check of the
// load assembly against the unit-load one). Prints error and time against modes.
#include <Tpetra_Core.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "ShroudedSectorCase.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/rom/NodalDiameterModel.hpp"
#include "cyclone/rom/HybridFrfModel.hpp"

using namespace cyclone;
using regression::relativeError;

namespace {

constexpr int kHarmonic = 2;
constexpr double kEta = 0.005;
constexpr int kFamilies = 5;

struct Reference {
  regression::ShroudedSectorCase sector{{"bore"}, kHarmonic, kEta};
  mesh::Index tipNode = -1;
  Eigen::Index retainedDof = -1;  // the retained DOF the third pattern loads
  std::unique_ptr<rom::NodalDiameterModel> full;
  rom::RetainedModes modes;
  std::vector<double> band;
  std::vector<Eigen::MatrixXcd> response;  // full FE x_r per band frequency, one column per pattern
  double secondsPerFrequency = 0;

  Reference() {
    auto& mesh = sector.mesh;
    const auto& retained = [&] {
      std::vector<mesh::Index> nodes = mesh.nodeSet("rom_contact");
      nodes.insert(nodes.end(), mesh.nodeSet("mid_blade").begin(), mesh.nodeSet("mid_blade").end());
      return nodes;
    }();
    double farthest = 0;
    for (mesh::Index n = 0; n < mesh.numNodes(); ++n) {
      const auto& x = mesh.coords[std::size_t(n)];
      const double r = std::hypot(x[0], x[1]);
      if (r > farthest && std::find(retained.begin(), retained.end(), n) == retained.end()) farthest = r, tipNode = n;
    }
    rom::LoadPattern tip{"tip_force", {{tipNode, 0, Eigen::Vector3d(0.3, -0.5, 1.0)}}};
    rom::LoadPattern face{"shroud_face", {}};
    const auto& faceNodes = mesh.nodeSet("shroud_left");
    for (mesh::Index n : faceNodes) {  // a uniform axial load on copy 0, half of it on copy 1
      face.forces.push_back({n, 0, Eigen::Vector3d(0, 0, 1.0 / double(faceNodes.size()))});
      face.forces.push_back({n, 1, Eigen::Vector3d(0, 0, 0.5 / double(faceNodes.size()))});
    }
    // The mid-blade node's y direction in copy 1: retained DOF (1 * nodes + last) * 3 + 1.
    const mesh::Index mid = mesh.nodeSet("mid_blade").front();
    retainedDof = (1 * Eigen::Index(retained.size()) + Eigen::Index(retained.size()) - 1) * 3 + 1;
    rom::LoadPattern unit{"unit_at_retained", {{mid, 1, Eigen::Vector3d(0, 1, 0)}}};
    auto problem = sector.problem;
    problem.loads = {tip, face, unit};
    full = std::make_unique<rom::NodalDiameterModel>(mesh, sector.sector, problem, Tpetra::getDefaultComm());
    modes = full->modes(40);
    band = regression::frequencyBand(modes, kFamilies);
    Timer timer;
    for (double w : band) response.push_back(full->loadResponse(w));
    secondsPerFrequency = timer.seconds() / double(band.size());
  }
};

const Reference& reference() {
  static const Reference* r = new Reference;  // never freed: Tpetra must not outlive Kokkos
  return *r;
}

// Largest relative error of pattern `p` over the band.
double worstError(const rom::ComplianceModel& model, const Reference& ref, Eigen::Index p) {
  double worst = 0;
  for (std::size_t i = 0; i < ref.band.size(); ++i)
    worst = std::max(worst, relativeError(model.loadResponse(ref.band[i]).col(p), ref.response[i].col(p)));
  return worst;
}

}  // namespace

TEST(HybridExcitation, UnitLoadAtARetainedDofIsItsComplianceColumn) {
  const auto& ref = reference();
  ASSERT_EQ(ref.full->numLoads(), 3);
  double worst = 0;
  for (std::size_t i : {std::size_t(0), std::size_t(2)}) {
    const Eigen::MatrixXcd A = ref.full->compliance(ref.band[i]);
    worst = std::max(worst, relativeError(ref.response[i].col(2), A.col(ref.retainedDof)));
  }
  std::printf("full FE: load-pattern response against the compliance column: %.3e\n", worst);
  EXPECT_LT(worst, 1e-12);
}

TEST(HybridExcitation, ConvergesToFullFeResponse) {
  const auto& ref = reference();
  std::printf("load at node %lld (r farthest from the axis, not retained) and over shroud_left; full FE: %.3f s "
              "per frequency, %zu frequencies over %d families\n",
              (long long)ref.tipNode, ref.secondsPerFrequency, ref.band.size(), kFamilies);
  std::printf("%-12s %6s %14s %14s %14s %12s\n", "kind", "modes", "tip force", "shroud face", "unit@retained",
              "build [s]");
  double previousTip = 1e300, previousFace = 1e300;
  for (int m : {5, 10, 20, 40}) {
    Timer timer;
    const auto kept = ref.modes.first(m);
    const rom::HybridFrfModel hybrid(kept, ref.full->staticCompliance(0.0, kept), kEta);
    const double build = timer.seconds();
    const auto truncation = rom::HybridFrfModel::modalTruncation(kept, kEta);
    const double tip = worstError(hybrid, ref, 0), face = worstError(hybrid, ref, 1), unit = worstError(hybrid, ref, 2);
    std::printf("%-12s %6d %14.3e %14.3e %14.3e %12.3f\n", "hybrid", m, tip, face, unit, build);
    std::printf("%-12s %6d %14.3e %14.3e %14.3e\n", "truncation", m, worstError(truncation, ref, 0),
                worstError(truncation, ref, 1), worstError(truncation, ref, 2));
    EXPECT_LT(tip, previousTip) << m;
    EXPECT_LT(face, previousFace) << m;
    previousTip = tip, previousFace = face;
    if (m >= 20) {
      EXPECT_LT(tip, 1e-3) << m;
      EXPECT_LT(face, 1e-3) << m;
      EXPECT_LT(unit, 1e-3) << m;
      // Without the static part the dropped modes' share stays.
      EXPECT_GT(worstError(truncation, ref, 0), 10 * tip) << m;
    }
    // The pattern at a retained DOF is the hybrid compliance's own column.
    const double w = ref.band[3];
    EXPECT_LT(relativeError(hybrid.loadResponse(w).col(2), hybrid.compliance(w).col(ref.retainedDof)), 1e-12);
  }
}

TEST(HybridExcitation, BadLoadsAreNamed) {
  const auto& s = reference().sector;
  const auto expectInputError = [&](const rom::LoadPattern& load, const std::string& where) {
    auto problem = s.problem;
    problem.loads = {load};
    try {
      rom::NodalDiameterModel(s.mesh, s.sector, problem, Tpetra::getDefaultComm());
      ADD_FAILURE() << "accepted: expected an InputError at " << where;
    } catch (const InputError& e) {
      EXPECT_EQ(e.where(), where) << e.what();
    }
  };
  expectInputError({"empty", {}}, "loads/empty");
  expectInputError({"far", {{s.mesh.numNodes(), 0, Eigen::Vector3d(1, 0, 0)}}}, "loads/far");
  expectInputError({"copy", {{0, 2, Eigen::Vector3d(1, 0, 0)}}}, "loads/copy");
  // A model without load patterns has no excitation part.
  const rom::NodalDiameterModel plain(s.mesh, s.sector, s.problem, Tpetra::getDefaultComm());
  EXPECT_EQ(plain.numLoads(), 0);
  EXPECT_THROW(plain.loadResponse(100.0), InputError);
}
