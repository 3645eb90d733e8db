// The bladed disc's chain as the disc scenes run it (drivers/src/DiscSceneReaders.cpp,
// DiscStages.cpp): the built-in shrouded sector or a mesh file, the reduced models per
// nodal diameter (cached in HDF5), and the friction-damped forced response with its
// headline (its curve kept, DiscReference.hpp, for the peak following and the stresses).
// The specs are the library's structs with the scenes' defaults; the Python
// layer (python/cyclone/disc.py) fills them by keyword.
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <memory>
#include <string>
#include <vector>

#include "Bindings.hpp"
#include "CurveArrays.hpp"
#include "DiscReference.hpp"
#include "Names.hpp"
#include "ProgramEnvironment.hpp"
#include "TraceSetup.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/disc/DiscForcedResponse.hpp"
#include "cyclone/disc/DiscPeakInTime.hpp"
#include "cyclone/disc/DiscReducedModels.hpp"
#include "cyclone/mesh/AbaqusIO.hpp"
#include "cyclone/mesh/ExodusIO.hpp"
#include "cyclone/mesh/MeshReader.hpp"
#include "cyclone/mesh/ShroudedSectorGenerator.hpp"

namespace py = pybind11;

namespace cyclone::python {

namespace {

py::dict headlineOf(const disc::DiscHeadline& h) {
  py::dict d;
  d["convergence"] = disc::convergenceName(h.convergence);
  d["text"] = h.text;
  d["value"] = h.peak.value;
  d["hz"] = h.peak.hz;
  d["max_harmonic"] = h.peak.maxHarmonic;
  d["change"] = h.peak.change;
  return d;
}

// What harmonics by an error target came to (response::HarmonicsTarget); None when not asked.
py::object harmonicsTargetOf(const response::HarmonicsTarget& t) {
  if (!(t.tolerance > 0)) return py::none();
  return py::dict(py::arg("tolerance") = t.tolerance, py::arg("traced_harmonic") = t.tracedHarmonic,
                  py::arg("reached") = t.reached, py::arg("change") = t.change, py::arg("retraced") = t.retraced,
                  py::arg("retrace_seconds") = t.retraceSeconds, py::arg("text") = t.text);
}

const char* endingName(hbm::TravellingWaveResponse::Ending ending) {
  using E = hbm::TravellingWaveResponse::Ending;
  return ending == E::Periodic ? "periodic" : ending == E::SteadyAmplitude ? "steady_amplitude" : "not_steady";
}

// The peak checked in the time domain (disc::PeakInTime); None when not asked or not made.
py::object peakInTimeOf(const std::optional<disc::PeakInTime>& p) {
  if (!p) return py::none();
  py::dict d;
  d["hz"] = p->hz, d["harmonic_balance"] = p->harmonicBalance, d["steady"] = p->steady();
  d["ending"] = endingName(p->ending);
  d["periods"] = p->periods, d["steps_per_period"] = p->stepsPerPeriod, d["sectors"] = p->sectors;
  d["last_amplitude"] = p->lastAmplitude, d["largest"] = p->largest, d["smallest"] = p->smallest;
  d["amplitude_history"] = py::array(py::cast(p->amplitudeHistory));
  d["seconds"] = p->seconds, d["text"] = p->text;
  return d;
}

py::object estimateOf(const std::optional<disc::ResonanceEstimate>& e) {
  if (!e) return py::none();
  return py::dict(py::arg("nodal_diameter") = e->nodalDiameter, py::arg("free_hz") = e->freeHz,
                  py::arg("stuck_hz") = e->stuckHz, py::arg("stuck_amplitude") = e->stuckAmplitude);
}

void bindMesh(py::module_& m) {
  py::class_<mesh::Mesh, std::shared_ptr<mesh::Mesh>>(m, "Mesh", "A sector's mesh (node indices from 0)")
      .def_property_readonly("num_nodes", &mesh::Mesh::numNodes)
      .def_property_readonly("num_elements", &mesh::Mesh::numElements)
      .def_property_readonly("source", [](const mesh::Mesh& mesh) { return mesh.source; })
      .def_property_readonly("coordinates",
                             [](const mesh::Mesh& mesh) {
                               Eigen::MatrixXd X(mesh.numNodes(), 3);
                               for (mesh::Index i = 0; i < mesh.numNodes(); ++i)
                                 for (int c = 0; c < 3; ++c) X(i, c) = mesh.coords[std::size_t(i)][c];
                               return X;
                             })
      .def_property_readonly("node_sets", [](const mesh::Mesh& mesh) { return mesh.nodeSets; });
  using P = mesh::ShroudedSectorParameters;
  py::class_<P>(m, "ShroudedSectorParameters")
      .def(py::init<>())
      .def_readwrite("sectors", &P::sectors)
      .def_readwrite("bore_radius", &P::boreRadius)
      .def_readwrite("rim_radius", &P::rimRadius)
      .def_readwrite("disc_thickness", &P::discThickness)
      .def_readwrite("blade_height", &P::bladeHeight)
      .def_readwrite("blade_chord", &P::bladeChord)
      .def_readwrite("blade_thickness", &P::bladeThickness)
      .def_readwrite("blade_stagger_deg", &P::bladeStaggerDeg)
      .def_readwrite("shroud_thickness", &P::shroudThickness)
      .def_readwrite("shroud_width", &P::shroudWidth)
      .def_readwrite("mesh_size", &P::meshSize)
      .def_readwrite("element_order", &P::elementOrder);
  m.def("shrouded_sector", [](const P& p) {
    p.validate("shrouded_sector");
    py::gil_scoped_release release;
    return std::make_shared<mesh::Mesh>(mesh::generateShroudedSector(p));
  });
  m.def("read_mesh", [](const std::string& path) {
    py::gil_scoped_release release;
    return std::make_shared<mesh::Mesh>(mesh::readMesh(path));
  });
  // As a mesher would write it, for a script that reads a mesh file (example 01).
  m.def("write_mesh", [](const mesh::Mesh& mesh, const std::string& path) {
    const auto dot = path.rfind('.');
    const std::string ext = dot == std::string::npos ? "" : path.substr(dot);
    if (ext != ".inp" && ext != ".exo") throw InputError("path", "'" + path + "': must end in .inp (Abaqus) or .exo (Exodus II)");
    py::gil_scoped_release release;
    if (ext == ".inp") mesh::writeAbaqusInp(path, mesh);
    else mesh::writeExodus(path, mesh);
  });
}

void bindReducedModels(py::module_& m) {
  using S = disc::DiscModelSpec;
  py::class_<S>(m, "DiscModelSpec")
      .def(py::init<>())
      .def_property(
          "material", [](const S& s) { return py::make_tuple(s.material.name, s.material.E, s.material.nu, s.material.rho); },
          [](S& s, const py::tuple& t) {
            s.material.name = t[0].cast<std::string>(), s.material.E = t[1].cast<double>();
            s.material.nu = t[2].cast<double>(), s.material.rho = t[3].cast<double>();
          })
      .def_readwrite("fixed_node_sets", &S::fixedNodeSets)
      .def_readwrite("sectors", &S::sectors)
      .def_readwrite("left_sets", &S::leftSets)
      .def_readwrite("right_sets", &S::rightSets)
      .def_readwrite("retained_node_sets", &S::retainedNodeSets)
      .def_readwrite("rpm", &S::rpm)
      .def("set_prestress", [](S& s, const std::string& name) { s.prestress = prestressFromName(name); })
      .def_property(
          "kind", [](const S& s) { return disc::reducedModelKindName(s.kind); },
          [](S& s, const std::string& name) { s.kind = disc::reducedModelKindFromName(name, "kind"); })
      .def_readwrite("modes", &S::modes)
      .def_readwrite("omega0", &S::omega0)
      .def_readwrite("loss_factor", &S::lossFactor)
      .def_readwrite("check_nodal_diameter", &S::checkNodalDiameter)
      .def_readwrite("check_frequencies", &S::checkFrequencies);
  using R = disc::DiscReducedModels;
  py::class_<R, std::shared_ptr<R>>(m, "DiscReducedModels")
      .def_readonly("sectors", &R::sectors)
      .def_readonly("rpm", &R::rpm)
      .def_readonly("natural_hz", &R::naturalHz)
      .def_readonly("files", &R::files)
      .def_readonly("reused", &R::reused)
      .def_readonly("built", &R::built)
      .def_readonly("seconds", &R::seconds)
      .def_property_readonly("check",
                             [](const R& r) {
                               const auto& c = r.check;
                               return py::dict(py::arg("nodal_diameter") = c.nodalDiameter,
                                               py::arg("hz") = py::array(py::cast(c.hz)),
                                               py::arg("reduced") = py::array(py::cast(c.reduced)),
                                               py::arg("full") = py::array(py::cast(c.full)),
                                               py::arg("error") = py::array(py::cast(c.error)),
                                               py::arg("reused") = c.reused, py::arg("checked_at") = c.checkedAt);
                             })
      .def_property_readonly("nodal_diameters", [](const R& r) {
        std::vector<int> nds;
        for (const auto& [k, model] : r.models) nds.push_back(k);
        return nds;
      });
  m.def(
      "disc_reduced_models",
      [](const mesh::Mesh& mesh, const S& spec, const std::vector<int>& nodalDiameters, const std::string& cache) {
        spec.material.validate("material");
        auto comm = environmentComm();
        py::gil_scoped_release release;
        return std::make_shared<R>(disc::buildDiscReducedModels(mesh, spec, nodalDiameters, cache, comm));
      },
      py::arg("mesh"), py::arg("spec"), py::arg("nodal_diameters"), py::arg("cache_directory"));
  m.def("nodal_diameters_for", &disc::nodalDiametersFor, py::arg("sectors"), py::arg("engine_order"),
        py::arg("harmonics"));
}

void bindDiscResponse(py::module_& m) {
  py::class_<DiscReference, std::shared_ptr<DiscReference>>(m, "DiscReference",
                                                            "A disc response's curve, kept for the peak's studies");
  using S = disc::DiscResponseSpec;
  py::class_<S>(m, "DiscResponseSpec")
      .def(py::init<>())
      .def_readwrite("engine_order", &S::engineOrder)
      .def_readwrite("harmonics", &S::harmonics)
      .def_readwrite("samples", &S::samples)
      .def_readwrite("response_node_sets", &S::responseNodeSets)
      .def("set_contact",
          [](S& s, const py::dict& c) {
            auto& contact = s.contact;
            const std::string law = c["law"].cast<std::string>();
            if (law != "per_area" && law != "per_pair")
              throw InputError("law", "'" + law + "': must be per_area or per_pair");
            contact.law = law == "per_area" ? disc::ShroudContactSpec::Law::PerArea : disc::ShroudContactSpec::Law::PerPair;
            contact.kn = c["kn"].cast<double>(), contact.kt = c["kt"].cast<double>();
            contact.mu = c["mu"].cast<double>(), contact.preload = c["preload"].cast<double>();
            contact.patches = c["patches"].cast<int>();
          })
      .def("set_gap",
          [](S& s, const py::dict& g) {  // the scenes' disc_response/gap: gap elements at these pairs
            s.gap.pairs = g["pairs"].cast<std::vector<int>>();
            if (s.gap.pairs.empty()) throw InputError("gap/pairs", "needs the contact pairs that are gap elements");
            s.gap.kn = g["kn"].cast<double>(), s.gap.clearance = g["clearance"].cast<double>();
          })
      .def("set_excitation",
          [](S& s, const py::dict& e) {
            s.excitation.nodeSet = e["node_set"].cast<std::string>();
            s.excitation.direction = e["direction"].cast<Eigen::Vector3d>();
            s.excitation.amplitude = e["amplitude"].cast<double>();
          });
  m.def(
      "disc_forced_response",
      [](std::shared_ptr<mesh::Mesh> mesh, std::shared_ptr<disc::DiscReducedModels> models, const S& spec,
         double fromHz, double toHz, int family, const std::string& stability, int harmonicsCheckTo,
         double harmonicsTolerance, const py::object& timeDomainCheck, const TraceOptions& continuation) {
        disc::DiscSweepOptions sweep;  // the scenes' defaults: the disc's continuation, LOCA retracing
        sweep.fromHz = fromHz, sweep.toHz = toHz, sweep.family = family;
        sweep.stability = stabilityFromName(stability);
        sweep.harmonicsCheckTo = harmonicsCheckTo;
        sweep.harmonicsTolerance = harmonicsTolerance;  // > 0: harmonics: auto (harmonicsCheckTo its harmonics_max)
        if (!timeDomainCheck.is_none()) {  // the scenes' disc_response/time_domain_check, checked in disc.py
          disc::PeakInTimeOptions o;
          o.maxPeriods = timeDomainCheck["periods"].cast<int>();
          o.stepsPerPeriod = timeDomainCheck["steps_per_period"].cast<int>();
          try {  // the library's limits (its upper ones too) before the trace, under the argument's key
            disc::checkPeakInTimeOptions(o);
          } catch (const InputError& e) {
            throw InputError("time_domain_check/" + e.where(), e.problem());
          }
          sweep.peakInTime = o;
        }
        applyDiscContinuation(continuation, sweep);
        disc::DiscForcedResponse r;
        Timer library;  // the call as C++ makes it: what the Python layer adds is the rest
        {
          py::gil_scoped_release release;
          r = disc::solveDiscForcedResponse(*mesh, *models, spec, sweep);
        }
        const double librarySeconds = library.seconds();
        py::dict d;
        d["curve"] = curveArrays(*r.setup.system, r.setup.outputDofs, r.curve);
        d["headline"] = headlineOf(r.headline);
        d["estimate"] = estimateOf(r.estimate);
        d["estimate_text"] = r.estimateText;
        d["from_hz"] = r.fromHz, d["to_hz"] = r.toHz;
        d["warnings"] = r.warnings;
        d["output_dofs"] = r.setup.outputDofs;
        d["harmonics"] = r.setup.system->aft().harmonics().harmonics();
        d["num_dofs"] = r.setup.system->numDofs();
        d["library_seconds"] = librarySeconds;
        d["harmonics_target"] = harmonicsTargetOf(r.curve.harmonicsTarget);
        d["peak_in_time"] = peakInTimeOf(r.peakInTime);
        // Traced again with the harmonics that met the target: the calls that start from this
        // curve work with those, as a disc scene's later stages (DiscStages.cpp).
        auto traced = spec;
        if (r.curve.harmonicsTarget.retraced) {
          traced.harmonics = r.setup.system->aft().harmonics().harmonics();
          traced.samples = r.setup.system->aft().numSamples();
        }
        // Kept for the calls that start from this curve (the peak following, the stresses at the peak).
        d["reference"] = std::make_shared<DiscReference>(DiscReference{mesh, models, traced, std::move(r), sweep});
        return d;
      },
      py::arg("mesh"), py::arg("models"), py::arg("spec"), py::arg("from_hz"), py::arg("to_hz"), py::arg("family"),
      py::arg("stability"), py::arg("harmonics_check_to"), py::arg("harmonics_tolerance"),
      py::arg("time_domain_check"), py::arg("continuation"));
}

}  // namespace

void bindDisc(py::module_& m) {
  bindMesh(m);
  bindReducedModels(m);
  bindDiscResponse(m);
}

}  // namespace cyclone::python
