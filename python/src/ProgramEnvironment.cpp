#include "ProgramEnvironment.hpp"

#include <pybind11/pybind11.h>

#include <memory>

#include "Bindings.hpp"
#include "cyclone/fe/Environment.hpp"

namespace py = pybind11;

namespace cyclone::python {

namespace {

std::unique_ptr<Environment>& environmentHolder() {
  static std::unique_ptr<Environment> environment;
  return environment;
}

}  // namespace

linalg::CommPtr environmentComm() {
  auto& holder = environmentHolder();
  if (!holder) {  // MPI_Init may run once per process: made once, kept
    static int argc = 1;
    static char name[] = "python";
    static char* args[] = {name, nullptr};
    static char** argv = args;
    holder = std::make_unique<Environment>(argc, argv);
  }
  return holder->comm();
}

void bindEnvironment(py::module_&) {
  // MPI and Kokkos end before the interpreter does (after the scripts' objects, which
  // hold no distributed data: meshes, dense reduced models, frequencies).
  py::module_::import("atexit").attr("register")(py::cpp_function([] { environmentHolder().reset(); }));
}

}  // namespace cyclone::python
