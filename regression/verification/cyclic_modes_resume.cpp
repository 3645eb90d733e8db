// A cyclic modal sweep killed part way resumes per nodal diameter (issue 20): with
// the results of some nodal diameters kept by an earlier run, the sweep reads those
// back and solves only the others, and its answer is the uninterrupted sweep's bit
// for bit (frequencies and shapes, prestressed sector). A damaged saved result is
// solved again; another material (or prestress) files every result under other keys.
#include <Tpetra_Core.hpp>
#include <gtest/gtest.h>

#include <cstdio>
#include <map>

#include "cyclone/core/Log.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/cyclic/CyclicModalAnalysis.hpp"
#include "cyclone/cyclic/CyclicTransform.hpp"
#include "cyclone/mesh/ShroudedSectorGenerator.hpp"

using namespace cyclone;

namespace {

class MemoryResults : public ResultCheckpoints {
public:
  std::optional<std::vector<double>> load(const std::string& key) override {
    const auto it = kept.find(key);
    if (it == kept.end()) return std::nullopt;
    return it->second;
  }
  void save(const std::string& key, const std::vector<double>& values) override {
    kept[key] = values;
    order.push_back(key);
  }
  std::map<std::string, std::vector<double>> kept;
  std::vector<std::string> order;  // keys in the order saved (nodal diameter order on one rank)
};

void expectSame(const std::vector<cyclic::NodalDiameterModes>& a, const std::vector<cyclic::NodalDiameterModes>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].nodalDiameter, b[i].nodalDiameter);
    EXPECT_EQ(a[i].frequenciesHz, b[i].frequenciesHz) << "ND " << a[i].nodalDiameter;
    ASSERT_EQ(a[i].shapes.size(), b[i].shapes.size()) << "ND " << a[i].nodalDiameter;
    for (std::size_t j = 0; j < a[i].shapes.size(); ++j) {
      EXPECT_EQ(a[i].shapes[j].real, b[i].shapes[j].real) << "ND " << a[i].nodalDiameter;
      EXPECT_EQ(a[i].shapes[j].imag, b[i].shapes[j].imag) << "ND " << a[i].nodalDiameter;
    }
  }
}

}  // namespace

TEST(CyclicModesResume, AResumedSweepSolvesOnlyWhatWasMissing) {
  log::setQuiet(true);
  const auto comm = Tpetra::getDefaultComm();
  mesh::ShroudedSectorParameters p;
  p.sectors = 12;
  p.meshSize = 12.0;
  const auto sectorMesh = mesh::generateShroudedSector(p);
  const auto sector = cyclic::makeCyclicSector(sectorMesh, p.sectors, {}, {"disc_left", "shroud_left"},
                                               {"disc_right", "shroud_right"});
  cyclic::CyclicModalProblem problem;
  problem.fixedNodeSets = {"bore"};
  problem.modesPerNodalDiameter = 4;
  mesh::RotationAxis axis;
  const auto k0 = cyclic::cyclicTransform(sectorMesh, sector, 0, problem.fixedNodeSets);
  const auto prestress = cyclic::solveLinearPrestress(sectorMesh, k0, problem.material, 10000, axis, comm);
  problem.prestress = std::make_shared<const cyclic::PrestressState>(prestress);

  Timer timer;
  const auto uninterrupted = cyclic::solveCyclicModes(sectorMesh, sector, problem, comm);
  const double whole = timer.seconds();
  auto first = std::make_shared<MemoryResults>();
  problem.checkpoints = first;
  const auto saved = cyclic::solveCyclicModes(sectorMesh, sector, problem, comm);
  expectSame(saved, uninterrupted);
  ASSERT_EQ(first->order.size(), uninterrupted.size());  // one result per nodal diameter

  // "Killed" after 4 nodal diameters: the resumed sweep reads those and solves the rest.
  auto resumed = std::make_shared<MemoryResults>();
  for (std::size_t i = 0; i < 4; ++i) resumed->kept[first->order[i]] = first->kept[first->order[i]];
  // One more saved but damaged (cut short, as a file whose writer died would not be:
  // the files are renamed into place; a reader must still not trust a short one).
  auto damaged = first->kept[first->order[5]];
  damaged.resize(damaged.size() / 2);
  resumed->kept[first->order[5]] = damaged;
  problem.checkpoints = resumed;
  timer.restart();
  const auto continued = cyclic::solveCyclicModes(sectorMesh, sector, problem, comm);
  const double rest = timer.seconds();
  expectSame(continued, uninterrupted);
  EXPECT_EQ(resumed->order.size(), uninterrupted.size() - 4);  // the damaged one solved again
  std::printf("%zu nodal diameters: uninterrupted %.2f s; resumed with 4 kept and 1 damaged %.2f s (solved %zu), "
              "the same frequencies and shapes bit for bit\n",
              uninterrupted.size(), whole, rest, resumed->order.size());

  // Another material: nothing kept applies.
  auto other = std::make_shared<MemoryResults>();
  other->kept = first->kept;
  problem.checkpoints = other;
  problem.material.E *= 1.01;
  problem.nodalDiameters = {0, 1};
  const auto stiffer = cyclic::solveCyclicModes(sectorMesh, sector, problem, comm);
  EXPECT_EQ(other->order.size(), 2u);
  EXPECT_GT(stiffer[0].frequenciesHz[0], uninterrupted[0].frequenciesHz[0]);
}
