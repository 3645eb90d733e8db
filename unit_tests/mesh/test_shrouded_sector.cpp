// The built-in shrouded sector: its volume against the closed-form volume of
// the CAD solid, periodic side faces, named sets, and parameter errors.
#include <gtest/gtest.h>

#include <cmath>

#include "MeshTestSupport.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/mesh/RotatedNodePairing.hpp"
#include "cyclone/mesh/ShroudedSectorGenerator.hpp"

using namespace cyclone::mesh;

namespace {

// Volume of the solid: disc and shroud annular sectors, plus the blade plate
// between the rim and tip cylinders: over the plate's section (chord x
// thickness, turned by the stagger about the radial axis), the radial extent at
// tangential offset y is sqrt(r_tip^2 - y^2) - sqrt(r_rim^2 - y^2).
double closedFormVolume(const ShroudedSectorParameters& p) {
  const double alpha = 2 * M_PI / p.sectors;
  const double disc = 0.5 * alpha * (p.rimRadius * p.rimRadius - p.boreRadius * p.boreRadius) * p.discThickness;
  const double rOut = p.tipRadius() + p.shroudThickness;
  const double shroud = 0.5 * alpha * (rOut * rOut - p.tipRadius() * p.tipRadius()) * p.shroudWidth;
  // 2D Gauss-Legendre (20 x 20 points) over the section in its own axes (t across, c along the chord).
  const double xg[5] = {0.1488743389816312, 0.4333953941292472, 0.6794095682990244, 0.8650633666889845,
                        0.9739065285171717};
  const double wg[5] = {0.2955242247147529, 0.2692667193099963, 0.2190863625159820, 0.1494513491505806,
                        0.0666713443086881};
  std::vector<std::pair<double, double>> rule;  // 10-point rule on [-1, 1]
  for (int i = 0; i < 5; ++i) rule.push_back({xg[i], wg[i]}), rule.push_back({-xg[i], wg[i]});
  const double g = p.bladeStaggerDeg * M_PI / 180;
  double blade = 0;
  for (auto [a, wa] : rule)
    for (auto [b, wb] : rule) {
      const double t = 0.5 * p.bladeThickness * a, c = 0.5 * p.bladeChord * b;
      const double y = t * std::cos(g) - c * std::sin(g);  // rotation about the radial x axis
      blade += wa * wb * 0.25 * p.bladeThickness * p.bladeChord *
               (std::sqrt(p.tipRadius() * p.tipRadius() - y * y) - std::sqrt(p.rimRadius * p.rimRadius - y * y));
    }
  return disc + shroud + blade;
}

}  // namespace

TEST(ShroudedSector, VolumeMatchesTheClosedFormSolid) {
  cyclone::log::setQuiet(true);
  ShroudedSectorParameters p;
  p.meshSize = 5.0;
  const Mesh mesh = generateShroudedSector(p);
  ASSERT_EQ(mesh.blocks.size(), 1u);
  EXPECT_EQ(mesh.blocks[0].type, ElementType::Tet10);
  const double exact = closedFormVolume(p);
  const double fe = cyclone::mesh::testing::meshVolume(mesh);
  std::printf("sector volume: mesh %.6f, closed form %.6f, relative error %.2e\n", fe, exact, fe / exact - 1);
  // Quadratic tets on the cylinders: geometric error O(h^3) per face, 1e-8 measured.
  EXPECT_NEAR(fe / exact, 1.0, 1e-6);
}

TEST(ShroudedSector, SideFacesArePeriodicAndSetsAreWhereTheyBelong) {
  ShroudedSectorParameters p;
  p.meshSize = 8.0;
  p.sectors = 30;
  p.bladeChord = 15.0;
  const Mesh mesh = generateShroudedSector(p);
  const double alpha = 2 * M_PI / p.sectors;
  for (auto [l, r] : {std::pair{"disc_left", "disc_right"}, std::pair{"shroud_left", "shroud_right"}}) {
    const auto& left = mesh.nodeSet(l);
    const auto& right = mesh.nodeSet(r);
    ASSERT_EQ(left.size(), right.size()) << l;
    const auto pairs = pairRotatedNodes(mesh, left, right, alpha, RotationAxis{}, 1e-6, l);
    EXPECT_LT(pairs.maxDistance, 1e-9 * p.tipRadius()) << l;
  }
  // Contact pairs are ordered: right[i] is the rotated left[i].
  const auto& cl = mesh.nodeSet("shroud_contact_left");
  const auto& cr = mesh.nodeSet("shroud_contact_right");
  ASSERT_EQ(cl.size(), mesh.nodeSet("shroud_left").size());
  for (std::size_t i = 0; i < cl.size(); ++i) {
    const auto x = rotate(mesh.coords[cl[i]], alpha, RotationAxis{});
    for (int d = 0; d < 3; ++d) EXPECT_NEAR(x[d], mesh.coords[cr[i]][d], 1e-9 * p.tipRadius());
  }
  for (auto n : mesh.nodeSet("bore")) EXPECT_NEAR(std::hypot(mesh.coords[n][0], mesh.coords[n][1]), p.boreRadius, 1e-6);
  for (auto n : mesh.nodeSet("shroud_left"))
    EXPECT_GE(std::hypot(mesh.coords[n][0], mesh.coords[n][1]), p.tipRadius() - 1e-6);
  const auto mid = mesh.coords[mesh.nodeSet("mid_blade").at(0)];
  EXPECT_NEAR(std::hypot(mid[0], mid[1]), p.rimRadius + 0.5 * p.bladeHeight, p.meshSize);
  EXPECT_GT(mesh.nodeSet("bore").size(), 3u);
}

TEST(ShroudedSector, RefinementAddsElementsAndTet4Works) {
  ShroudedSectorParameters p;
  p.meshSize = 10.0;
  p.elementOrder = 1;
  const Mesh coarse = generateShroudedSector(p);
  EXPECT_EQ(coarse.blocks[0].type, ElementType::Tet4);
  p.meshSize = 5.0;
  const Mesh fine = generateShroudedSector(p);
  EXPECT_GT(fine.numElements(), 2 * coarse.numElements());
}

TEST(ShroudedSector, ImpossibleParametersNameTheParameter) {
  ShroudedSectorParameters p;
  p.sectors = 90;  // the blade no longer fits in the sector
  cyclone::mesh::testing::expectInputError([&] { generateShroudedSector(p); }, {"blade_chord", "sector"});
  p = {};
  p.rimRadius = 30;
  cyclone::mesh::testing::expectInputError([&] { generateShroudedSector(p); }, {"rim_radius"});
  p = {};
  p.meshSize = -1;
  cyclone::mesh::testing::expectInputError([&] { generateShroudedSector(p); }, {"mesh_size"});
  p = {};
  p.elementOrder = 3;
  cyclone::mesh::testing::expectInputError([&] { generateShroudedSector(p); }, {"element_order"});
}

TEST(RotatedNodePairing, MismatchListsTheNodeAndItsDistance) {
  Mesh mesh;
  mesh.source = "two faces";
  mesh.coords = {{1, 0, 0}, {2, 0, 1}, {0, 1, 0}, {0, 2, 1.001}};
  mesh.assignDefaultIds();
  const auto ok = pairRotatedNodes(mesh, {0}, {2}, M_PI / 2, RotationAxis{}, 1e-9, "faces");
  EXPECT_EQ(ok.right.at(0), 2);
  cyclone::mesh::testing::expectInputError(
      [&] { pairRotatedNodes(mesh, {0, 1}, {2, 3}, M_PI / 2, RotationAxis{}, 1e-6, "shroud faces"); },
      {"two faces", "shroud faces", "1 left nodes without a partner", "node 2", "0.001"});
}
