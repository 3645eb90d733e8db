// The library's errors as the package's exceptions (python/cyclone/errors.py): an
// InputError keeps the place it names (where()) apart from its message, so a script can
// tell which argument or key to fix without parsing text.
#include <pybind11/pybind11.h>

#include "Bindings.hpp"
#include "cyclone/core/Error.hpp"

namespace py = pybind11;

namespace cyclone::python {

namespace {

// Raises cyclone.errors.<name>(args...): the classes live in Python so that they are
// ordinary exception classes (ValueError, RuntimeError subclasses) a user can subclass.
template <class... Args>
void raise(const char* name, Args&&... args) {
  const py::object type = py::module_::import("cyclone.errors").attr(name);
  const py::object error = type(std::forward<Args>(args)...);
  PyErr_SetObject(type.ptr(), error.ptr());
}

}  // namespace

void bindErrors(py::module_&) {
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      raise("InputError", e.where(), e.problem());
    } catch (const SolverError& e) {
      raise("SolverError", e.what());
    }
  });
}

}  // namespace cyclone::python
