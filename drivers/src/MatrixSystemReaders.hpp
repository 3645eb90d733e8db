#pragma once
// A matrix scene's system (M, C, K, DOF names, the next-sector coupling) and its
// nonlinear elements with where they act, read from the scene (MatrixSystemReaders.cpp).
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "cyclone/hbm/HarmonicBalanceSystem.hpp"
#include "cyclone/hbm/NonlinearElement.hpp"
#include "cyclone/scenes/SceneSection.hpp"

namespace cyclone::scenes {

// A matrix scene's `system` section: M, C (with Rayleigh and modal damping), K, the DOF
// names and the next-sector coupling of a cyclic system, checked for physics.
struct MatrixSystemInput {
  int n = 0;
  Eigen::MatrixXd M, C, K;
  std::vector<std::string> dofNames;
  hbm::CyclicCoupling coupling;
  bool cyclic() const { return coupling.sectors > 1; }
};

MatrixSystemInput readMatrixSystem(SceneSection& scene);

// A nonlinear element of `nonlinear_elements` and where it acts: w = W^T x (+ W_next^T
// x_next across the sector boundary).
struct PlacedElement {
  std::shared_ptr<const hbm::NonlinearElement> element;
  Eigen::MatrixXd W, Wnext;
};

/// The scene's `nonlinear_elements`, each named in `names` (in the scene's order).
std::vector<PlacedElement> readNonlinearElements(SceneSection& scene, const MatrixSystemInput& in,
                                                 std::vector<std::string>& names);

}  // namespace cyclone::scenes
