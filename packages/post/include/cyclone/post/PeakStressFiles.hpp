#pragma once
// The files of the sector's vibration at a point of a disc curve
// (disc::solveDiscPeakVibration): the whole field per harmonic with the stresses and the
// Goodman-Haigh safety factor as an Exodus file, one period as time steps for ParaView,
// every node's cycle worst first as CSV, and the Goodman-Haigh diagram.
#include <string>
#include <vector>

#include "cyclone/fatigue/GoodmanHaigh.hpp"
#include "cyclone/fatigue/SectorVibration.hpp"
#include "cyclone/mesh/Mesh.hpp"

namespace cyclone::post {

/// Displacement per harmonic (u_h<k>_re/_im_<x|y|z>) and, with `map`, the mean and
/// alternating stresses and the safety factor (capped at 1e3) per node; one step at `hz`.
void writePeakResponseExodus(const std::string& path, const mesh::Mesh& mesh, const fatigue::SectorVibration& v,
                             const fatigue::FatigueMap* map, double hz);

/// One period at `hz` as `steps` time steps: displacement and von Mises stress.
void writeVibrationAnimationExodus(const std::string& path, const mesh::Mesh& mesh, const fatigue::SectorVibration& v,
                                   int steps, double hz);

/// node,x,y,z,mean_vm_signed,alternating_vm,alternating_principal,max_vm,safety_factor in `order`.
void writeFatigueNodeTable(const std::string& path, const mesh::Mesh& mesh, const fatigue::FatigueMap& map,
                           const std::vector<std::size_t>& order);

/// The (modified) Goodman line, every node's cycle and the critical node with its safety factor.
void writeGoodmanDiagram(const std::string& path, const fatigue::FatigueMap& map, const fatigue::FatigueMaterial& m,
                         const std::string& unit, const std::string& title);

}  // namespace cyclone::post
