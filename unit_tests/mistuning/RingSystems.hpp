#pragma once
// The ring tests' harmonic balance systems: the small cyclic sector of the hbm tests
// (test_support::ringMatrices) in the receptance form with its elements (a contact to the
// next sector, a Jenkins element, a cubic spring), a travelling excitation and a static
// load; and the comparison of two rings' residual, Jacobian and stuck response.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

#include "../hbm/RingSector.hpp"
#include "cyclone/hbm/HarmonicBalanceSystem.hpp"

namespace cyclone::test_support {

/// The sector over `model` (cyclic: N, engine order eo), dynamic-stiffness statement.
inline std::unique_ptr<hbm::HarmonicBalanceSystem> receptanceRingSector(std::shared_ptr<const hbm::ReceptanceModel> model,
                                                                        const hbm::HarmonicSet& harmonics, int samples,
                                                                        int N, int eo) {
  auto sector = std::make_unique<hbm::HarmonicBalanceSystem>(std::move(model), harmonics, samples);
  hbm::CyclicCoupling c;
  c.sectors = N, c.engineOrder = eo;
  sector->setCyclic(c);
  sector->useDynamicStiffness(true);
  addRingElements(*sector);
  sector->addExcitation(1, 1, 0.8, 0.1);
  sector->addExcitation(2, 1, 0.2);
  sector->addStaticLoad(2, 0.3);
  return sector;
}

/// `ring` against `reference` at w = 1.1 and 2.9: residual and Jacobian at an arbitrary
/// state, and the stuck (linearised) response, each within 1e-10 (relative).
inline void expectSameRing(const hbm::HarmonicBalanceSystem& ring, const hbm::HarmonicBalanceSystem& reference,
                           const std::string& what) {
  ASSERT_EQ(ring.numUnknowns(), reference.numUnknowns());
  for (double w : {1.1, 2.9}) {
    std::srand(7);
    const Eigen::VectorXd X = 0.5 * Eigen::VectorXd::Random(ring.numUnknowns());
    Eigen::VectorXd R, Rref;
    Eigen::MatrixXd J, Jref;
    ring.residual(X, w, R, &J);
    reference.residual(X, w, Rref, &Jref);
    const double eR = (R - Rref).norm() / Rref.norm(), eJ = (J - Jref).norm() / Jref.norm();
    const Eigen::VectorXd Xl = ring.linearizedSolution(w), Xlref = reference.linearizedSolution(w);
    const double eL = (Xl - Xlref).norm() / Xlref.norm();
    std::printf("%s, w %.1f: residual %.1e, Jacobian %.1e, stuck (linearised) response %.1e\n", what.c_str(), w, eR, eJ,
                eL);
    EXPECT_LT(eR, 1e-10) << w;
    EXPECT_LT(eJ, 1e-10) << w;
    EXPECT_LT(eL, 1e-10) << w;
  }
}

}  // namespace cyclone::test_support
