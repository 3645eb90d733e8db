#include "cyclone/hbm/NonlinearElement.hpp"

#include "cyclone/core/Error.hpp"

namespace cyclone::hbm {

std::shared_ptr<const NonlinearElement> NonlinearElement::withParameter(const std::string& name, double) const {
  throw InputError("nonlinear element", "this element has no parameter '" + name + "' to vary");
}

}  // namespace cyclone::hbm
