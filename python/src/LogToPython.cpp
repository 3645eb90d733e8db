// The library's progress lines (core/Log.hpp) to Python's logging, logger "cyclone": info
// lines at INFO, warnings at WARNING, so a script shows or silences them as it does its
// own (logging.basicConfig(level=logging.INFO) to see the trace's progress).
#include <pybind11/pybind11.h>

#include "Bindings.hpp"
#include "cyclone/core/LogSink.hpp"

namespace py = pybind11;

namespace cyclone::python {

namespace {

// Called on whatever thread wrote the line, mostly while a long call has released the
// GIL: it takes the GIL for the call into logging. Holds no Python object between calls,
// so nothing is left to release after the interpreter has gone.
void toLogging(log::Level level, const std::string& message) {
  if (!Py_IsInitialized()) return;
  py::gil_scoped_acquire gil;
  try {
    const py::object logger = py::module_::import("logging").attr("getLogger")("cyclone");
    logger.attr(level == log::Level::Warning ? "warning" : "info")(message);
  } catch (py::error_already_set& e) {
    e.discard_as_unraisable("cyclone's log line");  // a broken handler must not stop the computation
  }
}

}  // namespace

void bindLogToPython(py::module_&) { log::setSink(toLogging); }

}  // namespace cyclone::python
