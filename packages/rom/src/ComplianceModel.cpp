#include "cyclone/rom/ComplianceModel.hpp"

#include "cyclone/core/Error.hpp"

namespace cyclone::rom {

Eigen::MatrixXcd ComplianceModel::loadResponse(double) const {
  throw InputError("loads", "this reduced model carries no load patterns (the excitation part is built for the "
                            "full FE, hybrid and truncation models from load patterns given with the FE model)");
}

}  // namespace cyclone::rom
