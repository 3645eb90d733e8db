#include "cyclone/cyclic/ModalSweep.hpp"

#include <optional>
#include <sstream>

#include "cyclone/core/Error.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/core/PeakMemory.hpp"
#include "cyclone/cyclic/CyclicTransform.hpp"

namespace cyclone::cyclic {

std::vector<SpeedModes> solveModalSweep(const mesh::Mesh& mesh, const CyclicSector& sector,
                                        const ModalSweepProblem& problem, linalg::CommPtr comm,
                                        const ModalSweepVisitor& visit) {
  const auto& speeds = problem.speedsRpm;
  if (speeds.empty()) throw InputError("speeds_rpm", "needs at least one speed");
  for (std::size_t i = 0; i < speeds.size(); ++i) {
    if (!(speeds[i] >= 0)) throw InputError("speeds_rpm", "speeds must be non-negative");
    if (i > 0 && !(speeds[i] > speeds[i - 1])) throw InputError("speeds_rpm", "speeds must increase");
  }
  std::vector<SpeedModes> results;
  CyclicModalProblem modes = problem.modes;
  for (double rpm : speeds) {
    modes.prestress.reset();
    if (problem.prestress != PrestressKind::None && rpm > 0) {
      const auto k0 = cyclicTransform(mesh, sector, 0, modes.fixedNodeSets);
      modes.prestress = std::make_shared<const PrestressState>(
          problem.prestress == PrestressKind::Linear
              ? solveLinearPrestress(mesh, k0, modes.material, rpm, problem.axis, comm)
              : solveNonlinearPrestress(mesh, k0, modes.material, rpm, problem.axis, comm));
    }
    releaseFreedMemory();  // the prestress's assembly and factor: 100 MB kept by malloc at 42k DOFs
    std::ostringstream what;
    what << "modes at " << rpm << " rpm" << (modes.prestress ? " (prestressed, spin softening; Coriolis neglected)" : "");
    log::info(what.str());
    SpeedModes sm{rpm, solveCyclicModes(mesh, sector, modes, comm)};
    if (visit) visit(modes.prestress.get(), sm);
    results.push_back(std::move(sm));
  }
  return results;
}

}  // namespace cyclone::cyclic
