// The shift-invert modal path that projects the sector's matrices (assembled once per
// speed) onto each nodal diameter, complex Hermitian for travelling-wave pairs, against
// the per-ND path that assembles K_k, M_k on the cyclic transform and factors the real
// 2-copy form: the same frequencies to 1e-8 and the same mode subspaces (MAC 1 - 1e-8),
// every nodal diameter including 0 and N/2; each mode's Rayleigh quotient on the
// sector's physical matrices equals its frequency (a vector with its own value). Two sectors: the default disc (tet10, NLGEOM
// prestress at 10000 rpm) and an annular plate sector of HEX20 (linear prestress). The
// default disc's and the given shift's projected runs solve their nodal diameters on 2
// threads.
#include <Tpetra_Core.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "BoxMesh.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/cyclic/CyclicModalAnalysis.hpp"
#include "cyclone/cyclic/CyclicTransform.hpp"
#include "cyclone/cyclic/SectorMatrices.hpp"
#include "cyclone/mesh/ShroudedSectorGenerator.hpp"

using namespace cyclone;

namespace {

using Shape = std::vector<std::array<double, 3>>;

// The real-form M inner product of two complex nodal shapes (a + ib):
// a_u^T M a_v + b_u^T M b_v, with M the sector's physical mass matrix.
double massProduct(const cyclic::SectorMatrices& sector, const std::vector<double>& M, const Shape& au, const Shape& bu,
                   const Shape& av, const Shape& bv) {
  auto flat = [](const Shape& s) {
    Eigen::VectorXd v(3 * s.size());
    for (std::size_t n = 0; n < s.size(); ++n)
      for (int d = 0; d < 3; ++d) v(3 * n + d) = s[n][d];
    return v;
  };
  auto times = [&](const Shape& s) {
    const Eigen::VectorXd x = flat(s);
    Eigen::VectorXd y(x.size());
    sector.multiply(M, x.data(), y.data());
    return y;
  };
  return flat(au).dot(times(av)) + flat(bu).dot(times(bv));
}

void compare(const mesh::Mesh& mesh, const cyclic::CyclicSector& sector, const cyclic::CyclicModalProblem& problem,
             const char* name) {
  const auto comm = Tpetra::getDefaultComm();
  Timer timer;
  const auto projected = cyclic::solveCyclicModes(mesh, sector, problem, comm);
  const double tProjected = timer.seconds();
  const auto matrices = cyclic::assembleSectorMatrices(mesh, problem.material, problem.prestress.get());
  const auto& M = matrices.m;
  double worstFrequency = 0, worstMac = 0, worstQuotient = 0, tAssembled = 0;
  for (const auto& hm : projected) {
    timer.restart();
    const auto op = cyclic::assembleNodalDiameterOperators(mesh, sector, hm.nodalDiameter, problem.material,
                                                      problem.fixedNodeSets, problem.prestress.get(), comm);
    const auto ref = cyclic::solveNodalDiameterModes(op, problem.modesPerNodalDiameter, problem.shift);
    tAssembled += timer.seconds();
    ASSERT_EQ(ref.frequenciesHz.size(), hm.frequenciesHz.size()) << name << " ND " << hm.nodalDiameter;
    std::vector<Shape> refA, refB;
    for (std::size_t i = 0; i < ref.frequenciesHz.size(); ++i) {
      refA.push_back(op.assembler->nodalField(*ref.modes, int(i), 0));
      refB.push_back(hm.copies == 2 ? op.assembler->nodalField(*ref.modes, int(i), 1)
                                    : Shape(mesh.numNodes(), {0, 0, 0}));
    }
    for (std::size_t i = 0; i < hm.frequenciesHz.size(); ++i) {
      const auto shape = hm.shapes[i];
      const double rel = std::abs(hm.frequenciesHz[i] / ref.frequenciesHz[i] - 1);
      worstFrequency = std::max(worstFrequency, rel);
      EXPECT_LT(rel, 1e-8) << name << " ND " << hm.nodalDiameter << " mode " << i + 1;
      // MAC against the reference modes of the same eigenvalue (a pair spans a plane
      // in which either code may pick any basis): the M-norm share of the mode inside
      // that span. The reference modes are M-orthonormal.
      double inside = 0;
      for (std::size_t j = 0; j < ref.frequenciesHz.size(); ++j) {
        if (std::abs(ref.frequenciesHz[j] / hm.frequenciesHz[i] - 1) > 1e-6) continue;
        const double c = massProduct(matrices, M, refA[j], refB[j], shape.real, shape.imag);
        inside += c * c;
      }
      const double self = massProduct(matrices, M, shape.real, shape.imag, shape.real, shape.imag);
      const double mac = inside / self;
      // Each shape with its own frequency: the Rayleigh quotient of the physical field.
      const double quotient =
          std::sqrt(massProduct(matrices, matrices.k, shape.real, shape.imag, shape.real, shape.imag) /
                    self) / (2 * M_PI);
      worstQuotient = std::max(worstQuotient, std::abs(quotient / hm.frequenciesHz[i] - 1));
      EXPECT_LT(std::abs(quotient / hm.frequenciesHz[i] - 1), 1e-8) << name << " ND " << hm.nodalDiameter << " mode " << i + 1;
      worstMac = std::max(worstMac, std::abs(1 - mac));
      EXPECT_GT(mac, 1 - 1e-8) << name << " ND " << hm.nodalDiameter << " mode " << i + 1;
    }
  }
  std::printf("%s: ND %d..%d, %d modes per ND: max |f / f_assembled - 1| = %.1e, max |1 - MAC| = %.1e, "
              "max |Rayleigh quotient / f - 1| = %.1e; projected %.2f s, assembled per ND %.2f s\n",
              name, projected.front().nodalDiameter, projected.back().nodalDiameter, problem.modesPerNodalDiameter, worstFrequency,
              worstMac, worstQuotient, tProjected, tAssembled);
}

}  // namespace

namespace {
void compareDefaultDisc(int modesPerNd, std::vector<int> nodalDiameters = {}) {
  log::setQuiet(getenv("CYCLONE_VERBOSE") == nullptr);
  mesh::ShroudedSectorParameters p;  // the built-in default disc: 24 sectors, tet10
  const auto mesh = mesh::generateShroudedSector(p);
  const auto sector = cyclic::makeCyclicSector(mesh, p.sectors, {}, {"disc_left", "shroud_left"},
                                               {"disc_right", "shroud_right"});
  cyclic::CyclicModalProblem problem;
  problem.fixedNodeSets = {"bore"};
  problem.modesPerNodalDiameter = modesPerNd;
  problem.nodalDiameters = std::move(nodalDiameters);
  // The nodal diameters on 2 threads: the threaded path against the assembled one
  // (that threads leave the answer unchanged to every digit: modal_mpi).
  problem.threads = 2;
  const auto state = cyclic::solveNonlinearPrestress(mesh, cyclic::cyclicTransform(mesh, sector, 0, {"bore"}),
                                                     problem.material, 10000, mesh::RotationAxis{}, Tpetra::getDefaultComm());
  problem.prestress = std::make_shared<const cyclic::PrestressState>(state);
  compare(mesh, sector, problem,
          ("default disc, tet10, NLGEOM 10000 rpm, " + std::to_string(modesPerNd) + " modes per ND").c_str());
}
}  // namespace

TEST(CyclicProjectedVsAssembled, DefaultDiscNlgeom10000rpm) { compareDefaultDisc(5); }

// The demo's request (3 per ND): at ND 4 the paired start block [v, Jv] loses the
// lowest pair (Anasazi listed 2406 Hz, its vectors spanned 4086 Hz), and the solve is
// repeated from an unpaired start; the frequencies must still be the assembled path's.
TEST(CyclicProjectedVsAssembled, DefaultDiscNlgeom10000rpmThreeModes) { compareDefaultDisc(3, {4}); }

namespace {
void compareHex20AnnularSector(double shift) {
  log::setQuiet(getenv("CYCLONE_VERBOSE") == nullptr);
  const int sectors = 18;
  const double alpha = 2 * M_PI / sectors;
  auto mesh = test_support::makeBoxMesh(0.1, alpha, 0.01, 6, 3, 2, mesh::ElementType::Hex20);
  for (auto& x : mesh.coords) {
    const double r = 0.1 + x[0], t = x[1] - alpha / 2;
    x = {r * std::cos(t), r * std::sin(t), x[2]};
  }
  const auto sector = cyclic::makeCyclicSector(mesh, sectors, {}, {"y0"}, {"y1"});
  cyclic::CyclicModalProblem problem;
  problem.material = fe::IsotropicElastic{"steel", 2e11, 0.3, 7800};
  problem.fixedNodeSets = {"x0"};
  problem.modesPerNodalDiameter = 4;
  if (!std::isnan(shift)) problem.shift = shift;
  if (!std::isnan(shift)) problem.threads = 2;  // a given shift's M projection, on threads
  const auto state = cyclic::solveLinearPrestress(mesh, cyclic::cyclicTransform(mesh, sector, 0, {"x0"}),
                                                  problem.material, 20000, mesh::RotationAxis{}, Tpetra::getDefaultComm());
  problem.prestress = std::make_shared<const cyclic::PrestressState>(state);
  compare(mesh, sector, problem,
          std::isnan(shift) ? "annular sector, HEX20, linear prestress 20000 rpm"
                            : "annular sector, HEX20, linear prestress 20000 rpm, shift -1e5");
}
}  // namespace

TEST(CyclicProjectedVsAssembled, Hex20AnnularSectorLinearPrestress) { compareHex20AnnularSector(std::nan("")); }

// A given shift (K - sigma M factored, sigma < 0): the projected path forms T^H M T only
// then (NodalDiameterForm projects K alone otherwise and applies M through the sector's
// matrices); the same frequencies and modes as the assembled path with that shift.
TEST(CyclicProjectedVsAssembled, Hex20AnnularSectorWithAShift) { compareHex20AnnularSector(-1.0e5); }
