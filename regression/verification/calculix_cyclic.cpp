// Verification against CalculiX run in the test: the same built-in sector mesh
// and case as a ccx deck with *CYCLIC SYMMETRY MODEL, a *STATIC NLGEOM step with
// CENTRIF (Newton to 1e-9: *CONTROLS) and a perturbation *FREQUENCY step with
// *SELECT CYCLIC SYMMETRY MODES. Every frequency per nodal diameter is compared, at
// rest and at 10000 rpm, fixed shroud and cantilever. Same mesh and element (C3D10),
// but ccx integrates C3D10's mass and centrifugal load with its 4-point stiffness rule
// where Cyclone's default is exact (14 points): with that rule (material
// mass_quadrature: stiffness_rule) the two codes agree to the digits ccx prints
// (1e-6), and with the exact rule to the quadrature's difference (2e-5 at these
// modes, docs/verification.md).
#include <Tpetra_Core.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "CalculixCyclic.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/cyclic/CyclicModalAnalysis.hpp"
#include "cyclone/cyclic/CyclicTransform.hpp"
#include "cyclone/mesh/AbaqusIO.hpp"
#include "cyclone/mesh/ShroudedSectorGenerator.hpp"

using namespace cyclone;
namespace fs = std::filesystem;

namespace {

const int kSectors = 12;
const int kFamilies = 2;

void compare(const std::vector<std::string>& left, const std::vector<std::string>& right, double rpm,
             const char* name) {
  log::setQuiet(getenv("CYCLONE_VERBOSE") == nullptr);
  mesh::ShroudedSectorParameters p;
  p.sectors = kSectors;
  p.meshSize = 8.0;
  const auto mesh = mesh::generateShroudedSector(p);
  const auto sector = cyclic::makeCyclicSector(mesh, kSectors, {}, left, right);
  Timer timer;
  auto solve = [&](fe::MassQuadrature quadrature) {
    cyclic::CyclicModalProblem problem;
    problem.fixedNodeSets = {"bore"};
    problem.modesPerNodalDiameter = kFamilies;
    problem.material.massQuadrature = quadrature;
    if (rpm > 0)
      problem.prestress = std::make_shared<const cyclic::PrestressState>(
          cyclic::solveNonlinearPrestress(mesh, cyclic::cyclicTransform(mesh, sector, 0, {"bore"}), problem.material,
                                          rpm, mesh::RotationAxis{}, Tpetra::getDefaultComm()));
    return cyclic::solveCyclicModes(mesh, sector, problem, Tpetra::getDefaultComm());
  };
  const auto exact = solve(fe::MassQuadrature::Exact), matched = solve(fe::MassQuadrature::StiffnessRule);
  const double tOurs = timer.seconds();
  timer.restart();
  regression::CalculixCyclicCase c;
  c.directory = (fs::temp_directory_path() / ("cyclone_ccx_cyclic_" + std::string(name) + std::to_string(int(rpm)))).string();
  c.left = left;
  c.right = right;
  c.sectors = kSectors;
  c.rpm = rpm;
  c.material = fe::IsotropicElastic{};
  c.modesPerNd = kFamilies;
  c.maxNd = kSectors / 2;
  c.tightNewton = true;
  const auto ccx = regression::runCalculixCyclic(mesh, c).frequenciesHz;
  auto worstAgainstCcx = [&](const std::vector<cyclic::NodalDiameterModes>& ours, double tolerance, const char* rule) {
    double worst = 0;
    for (const auto& hm : ours) {
      EXPECT_EQ(ccx.count(hm.nodalDiameter), 1u) << "ccx gave no modes for ND " << hm.nodalDiameter;
      if (!ccx.count(hm.nodalDiameter)) continue;
      const auto& theirs = ccx.at(hm.nodalDiameter);
      EXPECT_GE(theirs.size(), std::size_t(kFamilies));
      for (int j = 0; j < kFamilies && j < int(theirs.size()); ++j) {
        const double mine = hm.frequenciesHz[j * hm.copies];
        worst = std::max(worst, std::abs(mine / theirs[j] - 1));
        if (getenv("CYCLONE_VERBOSE"))
          std::printf("%s ND %d family %d: %.7g %.7g\n", rule, hm.nodalDiameter, j + 1, mine, theirs[j]);
        EXPECT_NEAR(mine / theirs[j], 1.0, tolerance)
            << name << " " << rpm << " rpm, " << rule << ", ND " << hm.nodalDiameter << " family " << j + 1;
      }
    }
    return worst;
  };
  const double worstMatched = worstAgainstCcx(matched, 1e-6, "ccx's mass rule");
  const double worstExact = worstAgainstCcx(exact, 2e-5, "exact mass");
  std::printf("%s at %5.0f rpm: ND 0..%d x %d families, max |f_cyclone / f_ccx - 1| = %.1e with ccx's 4-point mass "
              "rule, %.1e with the exact one (cyclone %.1f s for both, ccx %.1f s)\n",
              name, rpm, kSectors / 2, kFamilies, worstMatched, worstExact, tOurs, timer.seconds());
}

}  // namespace

TEST(CalculixCyclic, FixedShroudAtRest) {
  compare({"disc_left", "shroud_left"}, {"disc_right", "shroud_right"}, 0, "fixed shroud");
}
TEST(CalculixCyclic, FixedShroudNlgeom10000rpm) {
  compare({"disc_left", "shroud_left"}, {"disc_right", "shroud_right"}, 10000, "fixed shroud");
}
TEST(CalculixCyclic, CantileverAtRest) { compare({"disc_left"}, {"disc_right"}, 0, "cantilever"); }
TEST(CalculixCyclic, CantileverNlgeom10000rpm) { compare({"disc_left"}, {"disc_right"}, 10000, "cantilever"); }
