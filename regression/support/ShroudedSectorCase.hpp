#pragma once
// The reduced-model verifications' common case: the built-in shrouded sector,
// coarse (N = 8, a thin disc ring), cantilever (only the disc faces paired, shroud
// faces free), retained DOFs at two nodes of each shroud contact face and the
// mid-blade node, linear prestress at 10 000 rpm when held at the bore, structural
// damping eta; and the frequency band over the first natural frequencies.
#include <Tpetra_Core.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "cyclone/cyclic/CyclicTransform.hpp"
#include "cyclone/mesh/ShroudedSectorGenerator.hpp"
#include "cyclone/rom/NodalDiameterModel.hpp"

namespace cyclone::regression {

struct ShroudedSectorCase {
  static constexpr double kRpm = 10000;
  mesh::Mesh mesh;
  cyclic::CyclicSector sector;
  cyclic::PrestressState prestress;
  rom::NodalDiameterModelProblem problem;

  ShroudedSectorCase(std::vector<std::string> fixedSets, int harmonic, double lossFactor) {
    mesh::ShroudedSectorParameters p;
    p.sectors = 8;
    p.meshSize = 14.0;
    // The slow label runs the same proofs on a finer mesh (CYCLONE_ROM_TEST_MESH_SIZE).
    if (const char* h = std::getenv("CYCLONE_ROM_TEST_MESH_SIZE")) p.meshSize = std::stod(h);
    p.boreRadius = 70.0;  // a thin disc ring: fewer equations for the complex reference solves
    mesh = mesh::generateShroudedSector(p);
    const auto& left = mesh.nodeSet("shroud_contact_left");
    const auto& right = mesh.nodeSet("shroud_contact_right");
    mesh.nodeSets["rom_contact"] = {left.front(), left[left.size() / 2], right.front(), right[right.size() / 2]};
    sector = cyclic::makeCyclicSector(mesh, p.sectors, {}, {"disc_left"}, {"disc_right"});  // cantilever
    problem.nodalDiameter = harmonic;
    problem.fixedNodeSets = fixedSets;
    problem.retainedNodeSets = {"rom_contact", "mid_blade"};
    problem.lossFactor = lossFactor;
    if (!fixedSets.empty()) {
      const auto k0 = cyclic::cyclicTransform(mesh, sector, 0, fixedSets);
      prestress = cyclic::solveLinearPrestress(mesh, k0, problem.material, kRpm, mesh::RotationAxis{}, Tpetra::getDefaultComm());
      problem.prestress = std::make_shared<const cyclic::PrestressState>(prestress);
    }
  }
};

inline double relativeError(const Eigen::MatrixXcd& A, const Eigen::MatrixXcd& ref) {
  return (A - ref).norm() / ref.norm();
}

/// The largest relative error against `full` at 0.5, 1.5 and 2.5 times a frequency
/// (a free sector's first elastic one: away from the rigid-body modes at rest).
inline double worstErrorAround(const rom::ComplianceModel& model, const rom::ComplianceModel& full, double omega) {
  double worst = 0;
  for (double f : {0.5, 1.5, 2.5}) worst = std::max(worst, relativeError(model.compliance(f * omega), full.compliance(f * omega)));
  return worst;
}

/// Frequencies (rad/s) over the first `families` natural frequencies: below the
/// first, on each, 0.2 % below it, and half way to the next.
inline std::vector<double> frequencyBand(const rom::RetainedModes& modes, int families) {
  std::vector<double> w;
  const auto natural = [&](int j) { return std::sqrt(modes.eigenvalues[std::size_t(j * modes.copies)]); };
  w.push_back(0.5 * natural(0));
  for (int j = 0; j < families; ++j) {
    for (double f : {0.998, 1.0}) w.push_back(f * natural(j));
    w.push_back(0.5 * (natural(j) + natural(j + 1)));
  }
  return w;
}

}  // namespace cyclone::regression
