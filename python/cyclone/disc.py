"""The bladed disc's chain from Python, as the disc scenes run it (docs/scenes.md,
`analysis: [modal, reduced_model, disc_response]`), with the scenes' defaults: the built-in
shrouded sector (or a mesh file), its modes over speeds, the reduced models per nodal diameter at the contact
and excited nodes (cached in HDF5), and the friction-damped forced response with its
headline peak.

    sector = cyclone.disc.shrouded_sector(mesh_size=12.0)
    modes = cyclone.disc.modal_sweep(sector, speeds_rpm=[0.0, 10000.0], modes_per_nd=3)
    nds = cyclone.disc.nodal_diameters_for(sector.sectors, engine_order=3, harmonics=[0, 1, 2])
    models = cyclone.disc.reduced_models(sector, rpm=10000.0, nodal_diameters=nds, cache_directory="reduced_models")
    response = cyclone.disc.forced_response(sector, models, engine_order=3, harmonics=[0, 1], preload=20000.0,
                                            amplitude=20.0, harmonics_check_to=2)
    modes.frequencies_hz(3), response.headline, response.curve.omega, response.curve.max_abs
    peaks = cyclone.disc.follow_peak(response, "preload", (10000.0, 40000.0), values=8)
    curves = cyclone.disc.study(response, "mu", [0.2, 0.4, 0.8])
    stress = cyclone.disc.peak_stress(response, fatigue="Ti-6Al-4V")

Units are the library's: mm, N, s, t (MPa, t/mm^3)."""

import enum
from dataclasses import dataclass, field

import numpy as np

from . import _core, arrays
from .errors import InputError
from .disc_peaks import DiscFollowedPeaks, follow_peak  # noqa: F401 (cyclone.disc's API)
from .disc_static import StaticSolution, static_solve  # noqa: F401 (cyclone.disc's API)
from .disc_stress import PeakStress, peak_stress  # noqa: F401 (cyclone.disc's API)
from .disc_studies import DiscStudy, study  # noqa: F401 (cyclone.disc's API)
from .response import ForcedResponse, set_continuation


class Mesh:
    """A sector's mesh: coordinates (nodes x 3, mm), node_sets (name: node indices from 0),
    and the number of sectors of its disc (None for a file's: give it to reduced_models)."""

    def __init__(self, core, sectors):
        self._core = core
        self.sectors = sectors

    @property
    def num_nodes(self):
        return self._core.num_nodes

    @property
    def num_elements(self):
        return self._core.num_elements

    @property
    def coordinates(self):
        return self._core.coordinates

    @property
    def node_sets(self):
        return {name: np.array(nodes) for name, nodes in self._core.node_sets.items()}

    def __repr__(self):
        return f"<Mesh: {self.num_nodes} nodes, {self.num_elements} elements ({self._core.source})>"


def shrouded_sector(**parameters):
    """The built-in shrouded sector (gmsh): keyword arguments as the scenes'
    mesh/shrouded_sector keys (sectors 24, mesh_size 6.0, element_order 2, ...)."""
    p = _core.ShroudedSectorParameters()
    for key, value in parameters.items():
        if not hasattr(p, key):
            raise InputError(key, "is not a parameter of the shrouded sector")
        setattr(p, key, value)
    return Mesh(_core.shrouded_sector(p), p.sectors)


def read_mesh(path, sectors):
    """A sector's mesh from a file (Exodus II, CalculiX/Abaqus .inp, Gmsh .msh) of a disc of `sectors`."""
    return Mesh(_core.read_mesh(str(path)), int(sectors))


def write_mesh(mesh, path):
    """Writes `mesh` as a mesher would: Abaqus .inp or Exodus II .exo (by the extension),
    its node sets with it."""
    _core.write_mesh(mesh._core, str(path))


@dataclass(frozen=True)
class Material:
    """Isotropic elastic (MPa, t/mm^3); titanium by default, as the scenes'."""

    E: float = 1.16e5
    nu: float = 0.34
    rho: float = 4.507e-9
    name: str = "titanium"


@dataclass(frozen=True)
class CampbellBranch:
    """One family of one nodal diameter tracked over the speeds by MAC (campbell.csv's rows
    of one nd and family): family from 1 in the order at the first speed; worst_mac the
    lowest MAC along the tracking (low: the branch veered)."""

    nd: int
    family: int
    rpm: np.ndarray
    hz: np.ndarray
    worst_mac: float


class ModalSweep:
    """The sector's natural frequencies per speed and nodal diameter (a Campbell diagram's
    data): rpm (speeds), nodal_diameters, and frequencies_hz(k): speeds x modes (Hz,
    ascending; each member of a travelling-wave pair listed, as frequencies.csv);
    shapes(k) (with modal_sweep(shapes=True)): speeds x modes x nodes x 3, complex (the real
    part copy a, the imaginary part copy b; real for ND 0 and N/2), as modes_<rpm>rpm.exo;
    over two or more speeds branches (CampbellBranch, campbell.csv) and resonances: the
    engine orders' crossings {eo, nd, family, rpm, hz: arrays} (resonances.csv)."""

    def __init__(self, raw, campbell, library_seconds):
        self.library_seconds = library_seconds  # the library's calls alone (docs/studies/python_overhead.md)
        self.rpm = np.array([speed[0] for speed in raw])
        self._by_speed = [{k: np.array(f) for k, f in speed[1].items()} for speed in raw]
        self._shapes = [dict(speed[2]) for speed in raw]
        self.nodal_diameters = sorted(self._by_speed[0])
        branches, resonances = campbell
        self.branches = [CampbellBranch(b["nd"], b["family"], b["rpm"], b["hz"], b["worst_mac"]) for b in branches]
        self.resonances = {key: np.array([r[key] for r in resonances], dtype=int if key in ("eo", "nd", "family")
                                         else float) for key in ("eo", "nd", "family", "rpm", "hz")}

    def frequencies_hz(self, nodal_diameter):
        self._check(nodal_diameter)
        return np.array([speed[nodal_diameter] for speed in self._by_speed])

    def shapes(self, nodal_diameter):
        self._check(nodal_diameter)
        if not self._shapes[0]:
            raise InputError("shapes", "were not kept: modal_sweep(..., shapes=True)")
        return np.array([speed[nodal_diameter] for speed in self._shapes])

    def _check(self, nodal_diameter):
        if nodal_diameter not in self._by_speed[0]:
            raise InputError("nodal_diameter", f"{nodal_diameter} was not computed ({self.nodal_diameters})")

    def __repr__(self):
        return f"<ModalSweep: {len(self.rpm)} speeds, ND {self.nodal_diameters}>"


def modal_sweep(mesh, speeds_rpm, modes_per_nd=6, nodal_diameters=None, material=Material(), sectors=None,
                fixed_node_sets=("bore",), configuration="fixed_shroud", prestress="linear", threads=0, shapes=False,
                engine_orders=None):
    """The cyclic modes of the sector at each speed on its centrifugal prestress, as a modal
    scene (docs/scenes.md: modal and cyclic keys): configuration fixed_shroud pairs the disc's
    and the shroud's side faces, cantilever the disc's only; nodal_diameters None: all of
    0..N/2; threads 0: the cores this process may use; shapes: keep the mode shapes as arrays
    (modes x nodes x 3 per speed and nodal diameter: large for a fine mesh); engine_orders:
    the resonances' (None: 1..N, as a scene's diagrams)."""
    if configuration not in ("fixed_shroud", "cantilever"):
        raise InputError("configuration", f"{configuration!r}: must be 'fixed_shroud' or 'cantilever'")
    spec = _core.ModalSweepSpec()
    spec.sectors = int(sectors if sectors is not None else mesh.sectors or 0)
    if spec.sectors < 2:
        raise InputError("sectors", "is required (>= 2) for a mesh read from a file")
    spec.left_sets = ["disc_left"] + (["shroud_left"] if configuration == "fixed_shroud" else [])
    spec.right_sets = ["disc_right"] + (["shroud_right"] if configuration == "fixed_shroud" else [])
    spec.fixed_node_sets = list(fixed_node_sets)
    spec.material, spec.E, spec.nu, spec.rho = material.name, material.E, material.nu, material.rho
    spec.speeds_rpm = [arrays.finite_number(rpm, "speeds_rpm") for rpm in np.atleast_1d(speeds_rpm)]
    if any(b <= a for a, b in zip(spec.speeds_rpm, spec.speeds_rpm[1:])) or min(spec.speeds_rpm) < 0:
        raise InputError("speeds_rpm", "speeds must be non-negative and increase")
    spec.nodal_diameters = [] if nodal_diameters is None else [int(k) for k in nodal_diameters]
    spec.modes_per_nd, spec.prestress, spec.threads = int(modes_per_nd), prestress, int(threads)
    spec.shapes = bool(shapes)
    if engine_orders is not None:
        spec.engine_orders = [int(eo) for eo in engine_orders]
        if min(spec.engine_orders, default=0) < 1:
            raise InputError("engine_orders", "must be positive integers")
    return ModalSweep(*_core.modal_sweep(mesh._core, spec))


@dataclass(frozen=True)
class ModelCheck:
    """A reduced model against the full FE model at one nodal diameter (disc_model_check.csv):
    per frequency hz[i], |A| at the first retained DOF of the excitation's direction,
    reduced[i] and full[i], and error[i], ||A_reduced - A_full||_F / ||A_full||_F
    estimated by 8 random probe columns; reused: read back with a cached model (checked
    when it was built, at checked_at)."""

    nodal_diameter: int
    hz: np.ndarray
    reduced: np.ndarray
    full: np.ndarray
    error: np.ndarray
    reused: bool
    checked_at: str

    @property
    def max_error(self):
        return float(self.error.max())


class ReducedModels:
    """One reduced model per nodal diameter; natural_hz[k]: the cantilevered sector's
    distinct natural frequencies at nodal diameter k (Hz); reused/built: from the cache or
    not; check: a ModelCheck (reduced_models(check_nodal_diameter=k)) or None."""

    def __init__(self, core, spec, cache):
        self._core = core
        self._spec, self._cache = spec, cache  # what the peak's studies build again (over the speed)
        self.nodal_diameters = core.nodal_diameters
        self.natural_hz = {k: np.array(v) for k, v in core.natural_hz.items()}
        self.files = dict(core.files)
        self.reused, self.built, self.seconds = core.reused, core.built, core.seconds
        check = core.check
        self.check = ModelCheck(**check) if check["nodal_diameter"] >= 0 and len(check["hz"]) else None

    def __repr__(self):
        return f"<ReducedModels: ND {self.nodal_diameters}, {self.built} built, {self.reused} reused>"


def nodal_diameters_for(sectors, engine_order, harmonics):
    """The nodal diameters harmonics h of the engine order live on (h EO mod N, folded)."""
    return _core.nodal_diameters_for(int(sectors), int(engine_order), [int(h) for h in harmonics])


def reduced_models(mesh, rpm, nodal_diameters, cache_directory="", material=Material(), sectors=None, modes=20,
                   loss_factor=0.006, kind="hybrid", prestress="nonlinear", omega0=0.0, fixed_node_sets=("bore",),
                   retained_node_sets=("shroud_contact_left", "shroud_contact_right", "mid_blade"),
                   check_nodal_diameter=None, check_frequencies=12):
    """The models of `nodal_diameters` on the prestress at `rpm`, read from `cache_directory`
    where a model of the same inputs is there ("": no cache). The scenes' reduced_model keys;
    check_nodal_diameter: that one of `nodal_diameters` compared with the full FE
    compliance at check_frequencies frequencies (a scene's check_frequencies)."""
    spec = _core.DiscModelSpec()
    spec.material = (material.name, material.E, material.nu, material.rho)
    spec.sectors = int(sectors if sectors is not None else mesh.sectors or 0)
    if spec.sectors < 2:
        raise InputError("sectors", "is required (>= 2) for a mesh read from a file")
    spec.rpm = arrays.finite_number(rpm, "rpm")
    spec.modes, spec.loss_factor, spec.omega0 = int(modes), float(loss_factor), float(omega0)
    spec.kind = kind
    spec.set_prestress(prestress)
    spec.fixed_node_sets, spec.retained_node_sets = list(fixed_node_sets), list(retained_node_sets)
    if check_nodal_diameter is not None:
        if int(check_nodal_diameter) not in [int(k) for k in nodal_diameters]:
            raise InputError("check_nodal_diameter", f"{check_nodal_diameter} is not one of nodal_diameters")
        spec.check_nodal_diameter, spec.check_frequencies = int(check_nodal_diameter), int(check_frequencies)
    return ReducedModels(_core.disc_reduced_models(mesh._core, spec, [int(k) for k in nodal_diameters],
                                                   str(cache_directory)), spec, str(cache_directory))


class Convergence(enum.Enum):
    """The headline peak (disc::DiscHeadline::Convergence): converged to 1 % in the harmonics, or an estimate."""

    NOT_FOUND = "not found"
    ESTIMATE = "estimate"
    CONVERGED = "converged"


@dataclass(frozen=True)
class Headline:
    """The peak a disc run reports: the harmonics check's highest level found (max |x(t)|
    of the response node's first DOF, mm, at hz), its change from the level below."""

    convergence: Convergence
    value: float
    hz: float
    max_harmonic: int
    change: float
    text: str


@dataclass(frozen=True)
class DiscResponse:
    curve: ForcedResponse
    headline: Headline
    estimate: dict  # nodal_diameter, free_hz, stuck_hz, stuck_amplitude (None when not made)
    from_hz: float
    to_hz: float
    warnings: list
    library_seconds: float  # the library's call alone (the binding's overhead: docs/studies/python_overhead.md)
    _reference: object = field(default=None, repr=False)  # the curve as the library keeps it (follow_peak starts from it)
    _models: object = field(default=None, repr=False)


def forced_response(mesh, models, engine_order, harmonics=(0, 1, 2, 3), preload=0.0, kn=1e4 / 2.4, kt=1e4 / 2.4,
                    mu=0.4, law="per_area", patches=0, amplitude=1.0, direction=(0.0, 0.0, 1.0),
                    excitation_node_set="mid_blade", response_node_sets=("mid_blade",), samples=0,
                    frequency_range_hz=None, family=1, stability="auto", harmonics_check_to=0, gap=None,
                    engine=None, tolerance=None, **steps):
    """The friction-damped response of the disc under engine order `engine_order`, the scenes'
    disc_response keys: harmonics (H: 0..H, or a list; it must hold 1), samples (0: the
    automatic count; else 32 and 2 H + 1 at least), the shroud contacts' law (kn, kt per unit
    area and the interface's preload, per_area; or per pair), the excitation (N per node on
    harmonic 1), the range
    (None: 0.9 x free .. 1.1 x stuck of the resonance estimate), harmonics_check_to (0: H + 1),
    gap: gap elements in place of friction contacts at some pairs, a dict as the scenes'
    disc_response/gap: {"pairs": [...] (0-based), "kn": N/mm (1e4), "clearance": mm (0)};
    engine, tolerance and steps (initial_step, min_step, max_step, max_points, turn_angle): the
    scenes' disc_response/continuation (engine None: the predictor-corrector, LOCA retracing
    what it leaves incomplete; named: that engine alone; the disc's tolerance 1e-8)."""
    spec = _core.DiscResponseSpec()
    spec.engine_order = arrays.integer(engine_order, "engine_order")
    spec.harmonics = arrays.harmonic_list(harmonics)
    # As the scenes' disc_response (DiscSceneReaders.cpp): the excitation acts on harmonic 1;
    # samples 0 (the automatic count) or enough for the highest harmonic and the friction law
    # (below 32 its error passes a few percent: 3 samples traced a curve of nonsense).
    if 1 not in spec.harmonics:
        raise InputError("harmonics", f"{spec.harmonics}: must contain harmonic 1: the engine-order excitation acts on it")
    least = max(2 * max(spec.harmonics) + 1, 32)
    spec.samples = arrays.integer(samples, "samples", 0)
    if spec.samples != 0 and not least <= spec.samples <= arrays.MAX_SAMPLES:
        raise InputError("samples", f"{spec.samples}: must lie in {least}..{arrays.MAX_SAMPLES} time samples per period "
                                    f"(2 H + 1 resolve harmonic H = {max(spec.harmonics)}, and the friction contacts "
                                    "need at least 32; 0: the automatic count)")
    spec.response_node_sets = list(response_node_sets)
    spec.set_contact(dict(law=law, kn=arrays.finite_number(kn, "kn"), kt=arrays.finite_number(kt, "kt"),
                          mu=arrays.finite_number(mu, "mu"), preload=arrays.finite_number(preload, "preload"),
                          patches=int(patches)))
    if gap is not None:
        unknown = set(gap) - {"pairs", "kn", "clearance"}
        if unknown:
            raise InputError("gap", f"unknown keys {sorted(unknown)}: known are pairs, kn, clearance")
        pairs = np.atleast_1d(np.asarray(gap.get("pairs", []))).ravel()
        if pairs.size == 0 or not np.issubdtype(pairs.dtype, np.integer):
            raise InputError("gap/pairs", "needs the contact pairs that are gap elements (integers, 0-based)")
        spec.set_gap(dict(pairs=[int(i) for i in pairs], kn=arrays.finite_number(gap.get("kn", 1e4), "gap/kn"),
                          clearance=arrays.finite_number(gap.get("clearance", 0.0), "gap/clearance")))
    spec.set_excitation(dict(node_set=excitation_node_set, direction=arrays.vector(direction, "direction", 3),
                             amplitude=arrays.finite_number(amplitude, "amplitude")))
    if frequency_range_hz is not None and (np.ndim(frequency_range_hz) != 1 or len(frequency_range_hz) != 2):
        raise InputError("frequency_range_hz", f"must be (from, to) in Hz, got {frequency_range_hz!r}")
    from_hz, to_hz = (0.0, 0.0) if frequency_range_hz is None else (
        arrays.finite_number(frequency_range_hz[0], "frequency_range_hz"),
        arrays.finite_number(frequency_range_hz[1], "frequency_range_hz"))
    stability = {True: "always", False: "never"}.get(stability, stability)
    continuation = set_continuation(_core.TraceOptions(), engine, tolerance, steps)
    raw = _core.disc_forced_response(mesh._core, models._core, spec, from_hz, to_hz, int(family), stability,
                                     int(harmonics_check_to), continuation)
    h = raw["headline"]
    return DiscResponse(
        curve=ForcedResponse(raw["curve"], raw["harmonics"], raw["num_dofs"], raw["output_dofs"]),
        headline=Headline(Convergence(h["convergence"]), h["value"], h["hz"], h["max_harmonic"], h["change"], h["text"]),
        estimate=raw["estimate"], from_hz=raw["from_hz"], to_hz=raw["to_hz"], warnings=list(raw["warnings"]),
        library_seconds=raw["library_seconds"], _reference=raw["reference"], _models=models)
