// Modal scenes through the library entry point: frequencies per nodal diameter and
// speed, LOBPCG against shift-invert, bad modal keys named, a free sector's rigid-body
// modes.
#include <Tpetra_Core.hpp>
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "cyclone/core/Log.hpp"
#include "cyclone/scenes/SceneRunner.hpp"

#include "test_scene_support.hpp"

using namespace cyclone;
using namespace cyclone::scene_tests;  // the helpers and fs (std::filesystem)

TEST(Scenes, ModalSceneWritesFrequenciesPerNodalDiameter) {
  log::setQuiet(true);
  const auto dir = freshDir("modal");
  const std::string yaml =
      "cyclone:\n  analysis: modal\n  mesh:\n    shrouded_sector:\n      sectors: 12\n      mesh_size: 12.0\n"
      "  constraints:\n    fixed_node_sets: [bore]\n  cyclic:\n    configuration: cantilever\n"
      "  modal:\n    nodal_diameters: [0, 3, 6]\n    modes_per_nd: 2\n    speeds_rpm: [0, 12000]\n";
  scenes::SceneOverrides o;
  o.outputDirectory = dir.string();
  const auto summary = scenes::runSceneText(yaml, "modal.yaml", o, Tpetra::getDefaultComm());
  for (const auto& p : summary.written) EXPECT_TRUE(fs::exists(p)) << p;
  // Rows: per speed, ND 0 and 6 (= N/2) single (2 modes), ND 3 pairs (4 modes).
  auto f = readFrequencies(dir);
  auto at = [&](double rpm, int nd) { return f[std::make_pair(rpm, nd)]; };
  EXPECT_EQ(f.size(), 6u);
  EXPECT_EQ(at(0.0, 0).size(), 2u);
  EXPECT_EQ(at(0.0, 3).size(), 4u);
  EXPECT_EQ(at(0.0, 6).size(), 2u);
  EXPECT_NEAR(at(0.0, 3)[0] / at(0.0, 3)[1], 1.0, 1e-8);  // a travelling-wave pair
  // Centrifugal stiffening raises the first blade-dominated frequency of each ND.
  for (int nd : {0, 3, 6}) EXPECT_GT(at(12000.0, nd)[0], at(0.0, nd)[0]) << "ND " << nd;
}

// eigen_solver: lobpcg (LOBPCG + MueLu, no factorization) gives the shift-invert
// frequencies of the same scene (1e-8: see regression/verification/cyclic_lobpcg.cpp).
TEST(Scenes, ModalSceneByLobpcgMatchesShiftInvert) {
  log::setQuiet(true);
  const std::string yaml =
      "cyclone:\n  analysis: modal\n  mesh:\n    shrouded_sector:\n      sectors: 12\n      mesh_size: 12.0\n"
      "  constraints:\n    fixed_node_sets: [bore]\n"
      "  modal:\n    nodal_diameters: [0, 6]\n    modes_per_nd: 2\n    prestress: none\n";
  std::map<std::pair<double, int>, std::vector<double>> f[2];
  for (int i = 0; i < 2; ++i) {
    const auto dir = freshDir(i ? "lobpcg" : "shift_invert");
    scenes::SceneOverrides o;
    o.outputDirectory = dir.string();
    scenes::runSceneText(yaml + (i ? "    eigen_solver: lobpcg\n" : "    eigen_solver: shift_invert\n"), "modal.yaml", o,
                         Tpetra::getDefaultComm());
    f[i] = readFrequencies(dir);
  }
  ASSERT_EQ(f[0].size(), 2u);
  for (const auto& [key, reference] : f[0]) {
    ASSERT_EQ(f[1][key].size(), reference.size()) << "ND " << key.second;
    for (std::size_t m = 0; m < reference.size(); ++m)
      EXPECT_NEAR(f[1][key][m] / reference[m], 1.0, 1e-8) << "ND " << key.second << " mode " << m + 1;
  }
}

TEST(Scenes, ModalBadNodalDiameterAndConfigurationAreNamed) {
  const auto dir = freshDir("modalbad");
  const std::string base =
      "cyclone:\n  analysis: modal\n  mesh:\n    shrouded_sector:\n      sectors: 12\n      mesh_size: 12.0\n"
      "  constraints:\n    fixed_node_sets: [bore]\n";
  auto msg = failure(base + "  modal:\n    nodal_diameters: [7]\n", dir);
  EXPECT_NE(msg.find("nodal_diameters"), std::string::npos) << msg;
  EXPECT_NE(msg.find("0..6"), std::string::npos) << msg;
  msg = failure(base + "  modal:\n    modes_per_nd: 100000\n", dir);
  EXPECT_NE(msg.find("modal/modes_per_nd"), std::string::npos) << msg;
  EXPECT_NE(msg.find("more than half the sector's"), std::string::npos) << msg;
  msg = failure(base + "  modal:\n    nodal_diameters: [1, 3, 1]\n", dir);
  EXPECT_NE(msg.find("modal/nodal_diameters"), std::string::npos) << msg;
  EXPECT_NE(msg.find("nodal diameter 1 is listed twice"), std::string::npos) << msg;
  msg = failure(base + "  modal:\n    eigen_solver: arpack\n", dir);
  EXPECT_NE(msg.find("eigen_solver"), std::string::npos) << msg;
  EXPECT_NE(msg.find("lobpcg"), std::string::npos) << msg;
  msg = failure(base + "  modal:\n    eigen_solver: lobpcg\n    shift: -1.0\n", dir);
  EXPECT_NE(msg.find("shift_invert only"), std::string::npos) << msg;
  for (const char* threads : {"0", "-2", "many", "2.5", "2000"}) {
    msg = failure(base + "  modal:\n    threads: " + threads + "\n", dir);
    EXPECT_NE(msg.find("modal/threads"), std::string::npos) << threads << ": " << msg;
    EXPECT_NE(msg.find("auto or a count of threads from 1 to 1024"), std::string::npos) << threads << ": " << msg;
  }
  msg = failure(base + "  cyclic:\n    configuration: glued\n", dir);
  EXPECT_NE(msg.find("configuration"), std::string::npos) << msg;
  msg = failure(base + "  cyclic:\n    sectors: 1\n", dir);
  EXPECT_NE(msg.find("at least 2 sectors"), std::string::npos) << msg;
  msg = failure(base + "  cyclic:\n    sectors: 13\n", dir);  // faces do not match a 13-sector rotation
  EXPECT_NE(msg.find("do not match"), std::string::npos) << msg;
  // A zero density (issue 20: the eigen-solver spun for minutes): rejected before any work.
  msg = failure(base + "  material:\n    rho: 0.0\n", dir);
  EXPECT_NE(msg.find("material/rho"), std::string::npos) << msg;
  EXPECT_NE(msg.find("must be positive for modes"), std::string::npos) << msg;
  msg = failure(base + "  material:\n    mass_quadrature: lumped\n", dir);
  EXPECT_NE(msg.find("material/mass_quadrature"), std::string::npos) << msg;
  EXPECT_NE(msg.find("exact (the default) or stiffness_rule"), std::string::npos) << msg;
  EXPECT_FALSE(fs::exists(dir / "frequencies.csv"));
}

TEST(Scenes, ModalWithoutConstraintsReportsRigidBodyModes) {
  // A free sector: k = 0 keeps the rotation about the axis and the axial
  // translation, k = 1 the in-plane translations and the two tilts (a pair each).
  log::setQuiet(true);
  const auto dir = freshDir("free");
  const std::string yaml =
      "cyclone:\n  analysis: modal\n  mesh:\n    shrouded_sector:\n      sectors: 12\n      mesh_size: 12.0\n"
      "  cyclic:\n    configuration: fixed_shroud\n"
      "  modal:\n    nodal_diameters: [0, 1, 2]\n    modes_per_nd: 3\n    prestress: none\n";
  scenes::SceneOverrides o;
  o.outputDirectory = dir.string();
  const auto summary = scenes::runSceneText(yaml, "free.yaml", o, Tpetra::getDefaultComm());
  std::string all;
  for (const auto& line : summary.computed) all += line + "\n";
  EXPECT_NE(all.find("rigid-body modes ND 0: 2, ND 1: 4"), std::string::npos) << all;
}
