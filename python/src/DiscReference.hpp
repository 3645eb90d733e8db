#pragma once
// The disc's reference curve kept for the calls that start from it (the peak following,
// the stresses at the peak, the value-list studies), as a disc scene keeps `solved` for
// its later stages (drivers/src/DiscStages.cpp): the solved response with the mesh,
// models, spec and sweep options it was traced with, held alive while Python holds the
// response.
#include <memory>

#include "cyclone/disc/DiscForcedResponse.hpp"
#include "cyclone/disc/DiscReducedModels.hpp"
#include "cyclone/mesh/Mesh.hpp"

namespace cyclone::python {

struct DiscReference {
  std::shared_ptr<const mesh::Mesh> mesh;
  std::shared_ptr<const disc::DiscReducedModels> models;
  disc::DiscResponseSpec spec;
  disc::DiscForcedResponse solved;
  disc::DiscSweepOptions sweep;  ///< the studies trace their curves with the same options
};

}  // namespace cyclone::python
