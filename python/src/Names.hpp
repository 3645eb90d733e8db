#pragma once
// The library's enums from the names the Python layer passes (the scenes' names), each
// refusal naming the argument.
#include <string>

#include "cyclone/cyclic/Prestress.hpp"
#include "cyclone/response/ForcedResponseSetup.hpp"

namespace cyclone::python {

/// "auto", "always", "never" (InputError naming stability otherwise).
response::ForcedResponseSetup::Stability stabilityFromName(const std::string& name);
/// "linear", "nonlinear", "none" (InputError naming prestress otherwise).
cyclic::PrestressKind prestressFromName(const std::string& name);

}  // namespace cyclone::python
