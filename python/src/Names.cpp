#include "Names.hpp"

#include "cyclone/core/Error.hpp"

namespace cyclone::python {

response::ForcedResponseSetup::Stability stabilityFromName(const std::string& name) {
  using Stability = response::ForcedResponseSetup::Stability;
  if (name == "auto") return Stability::Auto;
  if (name == "always") return Stability::Always;
  if (name == "never") return Stability::Never;
  throw InputError("stability", "'" + name + "': must be auto, always or never");
}

cyclic::PrestressKind prestressFromName(const std::string& name) {
  if (name == "linear") return cyclic::PrestressKind::Linear;
  if (name == "nonlinear") return cyclic::PrestressKind::Nonlinear;
  if (name == "none") return cyclic::PrestressKind::None;
  throw InputError("prestress", "'" + name + "': must be linear, nonlinear or none");
}

}  // namespace cyclone::python
