// Benchmark (a program, not a test): the cost of every reduced-model kind for
// the default disc (built-in shrouded sector, N = 24, titanium, bore fixed,
// nonlinear prestress at 10 000 rpm) at a medium mesh, cantilever (only the disc
// faces paired), retained DOFs = shroud_contact_left, shroud_contact_right and
// mid_blade, for the nodal diameters that engine order 3 with harmonics 1..5
// needs (3, 6, 9, 12 = N/2; harmonic 5 lands on 15 = 24 - 9). Per nodal diameter
// and kind: build time (eigen-solution, static solves, reduction) and time per
// frequency evaluation; and, unless --no-reference, the error against one
// full-FE solve half way between the first two natural frequencies.
//   build/regression/rom_benchmark [--mesh-size 4] [--modes 20] [--no-reference]
#include <Tpetra_Core.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <set>

#include "cyclone/core/Timer.hpp"
#include "cyclone/cyclic/CyclicTransform.hpp"
#include "cyclone/mesh/ShroudedSectorGenerator.hpp"
#include "cyclone/rom/BoundaryReduction.hpp"
#include "cyclone/rom/CraigBamptonModel.hpp"
#include "cyclone/rom/NodalDiameterModel.hpp"
#include "cyclone/rom/GuyanModel.hpp"

using namespace cyclone;

namespace {

constexpr double kRpm = 10000, kEta = 0.005;
constexpr int kEngineOrder = 3, kHarmonics = 5;

// Seconds per evaluation of A(w), over `count` frequencies (at least 0.2 s in all).
double evaluationSeconds(const rom::ComplianceModel& model, double omega) {
  Timer timer;
  int count = 0;
  do {
    model.compliance(omega * (1 + 1e-3 * count));
    ++count;
  } while (timer.seconds() < 0.2 && count < 1000);
  return timer.seconds() / count;
}

}  // namespace

int main(int argc, char** argv) {
  Tpetra::ScopeGuard scope(&argc, &argv);
  double meshSize = 4;
  int modes = 20;
  bool reference = true;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--mesh-size") && i + 1 < argc) meshSize = std::atof(argv[++i]);
    else if (!std::strcmp(argv[i], "--modes") && i + 1 < argc) modes = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--no-reference")) reference = false;
    else {
      std::fprintf(stderr, "usage: rom_benchmark [--mesh-size h] [--modes m] [--no-reference]\n");
      return 2;
    }
  }
  const auto comm = Tpetra::getDefaultComm();
  Timer total;
  mesh::ShroudedSectorParameters p;  // the default disc
  p.meshSize = meshSize;
  const auto mesh = mesh::generateShroudedSector(p);
  const auto sector = cyclic::makeCyclicSector(mesh, p.sectors, {}, {"disc_left"}, {"disc_right"});
  rom::NodalDiameterModelProblem problem;
  problem.fixedNodeSets = {"bore"};
  problem.retainedNodeSets = {"shroud_contact_left", "shroud_contact_right", "mid_blade"};
  problem.lossFactor = kEta;
  Timer timer;
  const auto k0 = cyclic::cyclicTransform(mesh, sector, 0, problem.fixedNodeSets);
  const auto prestress = cyclic::solveNonlinearPrestress(mesh, k0, problem.material, kRpm, mesh::RotationAxis{}, comm);
  problem.prestress = std::make_shared<const cyclic::PrestressState>(prestress);
  std::printf("default disc N = %d, mesh size %g: %zu nodes; nonlinear prestress at %.0f rpm %.1f s; eta = %g, "
              "%d modes (pairs count once) for hybrid, truncation and Craig-Bampton\n",
              p.sectors, meshSize, std::size_t(mesh.numNodes()), kRpm, timer.seconds(), kEta, modes);

  std::set<int> diameters;  // harmonic h of EO lives on nodal diameter h EO mod N, folded into 0..N/2
  for (int h = 1; h <= kHarmonics; ++h) {
    const int k = (h * kEngineOrder) % p.sectors;
    diameters.insert(std::min(k, p.sectors - k));
  }
  std::printf("%4s %10s %9s %-14s %12s %12s %12s\n", "ND", "equations", "retained", "kind", "build [s]", "eval [s]",
              "error");
  for (int k : diameters) {
    problem.nodalDiameter = k;
    timer.restart();
    const rom::NodalDiameterModel full(mesh, sector, problem, comm);
    const double assembly = timer.seconds();
    const auto retainedModes = full.modes(modes);
    const auto A0 = full.staticCompliance(0.0, retainedModes);
    const rom::HybridFrfModel hybrid(retainedModes, A0, kEta);
    const auto truncation = rom::HybridFrfModel::modalTruncation(retainedModes, kEta);
    timer.restart();
    const auto guyanReduction = rom::reduceOntoRetainedDofs(full, 0);
    const rom::GuyanModel guyan(guyanReduction, kEta);
    const double guyanBuild = timer.seconds();
    timer.restart();
    const auto cbReduction = rom::reduceOntoRetainedDofs(full, modes);
    const rom::CraigBamptonModel cb(cbReduction, modes, kEta);
    const double cbBuild = timer.seconds();

    const int c = full.copies();
    const double w1 = std::sqrt(retainedModes.eigenvalues[0]), w2 = std::sqrt(retainedModes.eigenvalues[c]);
    const double omega = 0.5 * (w1 + w2);  // between the first two families
    Eigen::MatrixXcd Aref;
    double fullEval = 0;
    if (reference) {
      timer.restart();
      Aref = full.compliance(omega);
      fullEval = timer.seconds();
    }
    const auto error = [&](const rom::ComplianceModel& model) {
      return reference ? (model.compliance(omega) - Aref).norm() / Aref.norm() : std::nan("");
    };
    const auto row = [&](const char* kind, double build, const rom::ComplianceModel& model) {
      std::printf("%4d %10lld %9ld %-14s %12.2f %12.2e %12.2e\n", k, full.equations(), long(full.size()), kind, build,
                  evaluationSeconds(model, omega), error(model));
    };
    std::printf("%4d %10lld %9ld %-14s %12.2f %12.2e %12s   (first frequencies %.1f, %.1f Hz)\n", k,
                full.equations(), long(full.size()), "full FE", assembly, fullEval, "reference", w1 / (2 * M_PI),
                w2 / (2 * M_PI));
    row("hybrid", retainedModes.seconds + A0.seconds, hybrid);
    row("truncation", retainedModes.seconds, truncation);
    row("Guyan", guyanBuild, guyan);
    row("Craig-Bampton", cbBuild, cb);
    std::printf("     (modes %.2f s, static compliance %.2f s; Craig-Bampton: constraint modes %.2f s, "
                "fixed-interface modes %.2f s)\n",
                retainedModes.seconds, A0.seconds, cbReduction.staticSeconds, cbReduction.modesSeconds);
    std::fflush(stdout);
  }
  std::printf("total %.1f s\n", total.seconds());
  return 0;
}
