// The reduced model's check against the full FE compliance (disc::buildDiscReducedModels
// with checkNodalDiameter) estimates the Frobenius relative error of the whole compliance
// from a few random probe columns, one solve each, instead of a solve per retained DOF.
// On a small built-in disc (8 sectors, mesh size 12, at rest, ND 1: two copies) the
// estimate is compared, frequency by frequency, with the exact error: both compliances
// formed whole (the full FE one by the model of kind full_fe, a solve per retained DOF).
// A good model (hybrid, 10 modes, exact static correction) and a wrong one (truncation to
// 2 modes: no static correction, most of the stiffness left out) must both be estimated
// within a factor 2 of the exact error, and the wrong one must be caught (its error above
// 10 %, the good one's below 1e-3). Printed: both errors per frequency, both run times.
#include <Tpetra_Core.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "cyclone/core/Log.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/disc/DiscReducedModels.hpp"
#include "cyclone/mesh/ShroudedSectorGenerator.hpp"

using namespace cyclone;

namespace {

constexpr int kNodalDiameter = 1;

struct Checked {
  disc::ReducedModelCheck check;
  std::vector<double> exact;  // per check frequency
  double exactSeconds = 0;
};

// The model of `kind` with `modes` checked by the library, and the exact error at the
// check's frequencies against the full FE compliance formed whole.
Checked checkModel(const mesh::Mesh& mesh, const disc::DiscModelSpec& base, disc::ReducedModelKind kind, int modes,
                   const rom::ComplianceModel& full) {
  disc::DiscModelSpec spec = base;
  spec.kind = kind;
  spec.modes = modes;
  spec.checkNodalDiameter = kNodalDiameter;
  spec.checkFrequencies = 6;
  const auto models = disc::buildDiscReducedModels(mesh, spec, {kNodalDiameter}, "", Tpetra::getDefaultComm());
  Checked out;
  out.check = models.check;
  Timer timer;
  const auto& model = *models.models.at(kNodalDiameter);
  for (double hz : out.check.hz) {
    const Eigen::MatrixXcd Ar = model.compliance(2 * M_PI * hz), Af = full.compliance(2 * M_PI * hz);
    out.exact.push_back((Ar - Af).norm() / Af.norm());
  }
  out.exactSeconds = timer.seconds();
  return out;
}

void expectEstimates(const std::string& name, const Checked& c) {
  ASSERT_EQ(c.check.error.size(), c.exact.size());
  ASSERT_FALSE(c.exact.empty());
  std::printf("%s: check by probes %.2f s, exact (the compliance formed whole) %.2f s\n", name.c_str(),
              c.check.seconds, c.exactSeconds);
  for (std::size_t i = 0; i < c.exact.size(); ++i) {
    std::printf("  %9.2f Hz: estimated %.3e, exact %.3e (ratio %.2f)\n", c.check.hz[i], c.check.error[i], c.exact[i],
                c.check.error[i] / c.exact[i]);
    EXPECT_GT(c.check.error[i], 0.5 * c.exact[i]) << name << " at " << c.check.hz[i] << " Hz";
    EXPECT_LT(c.check.error[i], 2.0 * c.exact[i]) << name << " at " << c.check.hz[i] << " Hz";
  }
}

}  // namespace

TEST(DiscModelCheck, ProbesEstimateTheWholeComplianceErrorAndCatchAWrongModel) {
  log::setQuiet(true);
  mesh::ShroudedSectorParameters p;
  p.sectors = 8;
  p.meshSize = 12.0;
  const auto mesh = mesh::generateShroudedSector(p);
  disc::DiscModelSpec base;
  base.sectors = p.sectors;
  base.prestress = cyclic::PrestressKind::None;
  disc::DiscModelSpec fullSpec = base;
  fullSpec.kind = disc::ReducedModelKind::FullFe;
  const auto full = disc::buildDiscReducedModels(mesh, fullSpec, {kNodalDiameter}, "", Tpetra::getDefaultComm());
  const auto& fullModel = *full.models.at(kNodalDiameter);

  const Checked good = checkModel(mesh, base, disc::ReducedModelKind::Hybrid, 10, fullModel);
  expectEstimates("hybrid, 10 modes", good);
  const Checked wrong = checkModel(mesh, base, disc::ReducedModelKind::Truncation, 2, fullModel);
  expectEstimates("truncation, 2 modes", wrong);
  EXPECT_LT(good.check.maxError(), 1e-3);
  EXPECT_GT(wrong.check.maxError(), 0.1);
}
