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
class HarmonicsTarget:
    """What harmonics="auto" came to (response::HarmonicsTarget): the curve first traced with
    harmonics 0..traced_harmonic, the level `reached` whose last two raises of H changed the
    peak by at most `tolerance` (the larger of the two: change; -1 both where not met), and
    whether the curve was traced again with harmonics 0..reached (or, not met, the highest
    level whose peak was found), in retrace_seconds; text: the summary's line."""

    tolerance: float
    traced_harmonic: int
    reached: int
    change: float
    retraced: bool
    retrace_seconds: float
    text: str


class TimeDomainEnding(str, enum.Enum):
    """How the time domain's run ended (hbm::TravellingWaveResponse::Ending): the motion
    repeats, its amplitude is steady while it still drifts, or neither within the periods."""

    PERIODIC = "periodic"
    STEADY_AMPLITUDE = "steady_amplitude"
    NOT_STEADY = "not_steady"


@dataclass(frozen=True)
class PeakInTime:
    """The peak checked in the time domain (disc::PeakInTime, disc_peak_in_time.csv): the
    ring of reduced sectors integrated at the traced curve's largest point (hz), from the
    harmonic balance's periodic state there (its max |x(t)|: harmonic_balance, mm);
    amplitude_history: max |x(t)| of the output DOF per period from the start; last_amplitude
    over the last period, largest and smallest over the last half of the run (steady: the
    last); sectors: those integrated; text: the summary's second line."""

    hz: float
    harmonic_balance: float
    steady: bool
    ending: TimeDomainEnding
    periods: int
    steps_per_period: int
    sectors: int
    last_amplitude: float
    largest: float
    smallest: float
    amplitude_history: np.ndarray = field(repr=False)
    seconds: float
    text: str

    @property
    def difference(self):
        """largest / harmonic_balance - 1."""
        return self.largest / self.harmonic_balance - 1 if self.harmonic_balance > 0 else 0.0


@dataclass(frozen=True)
class DiscResponse:
    curve: ForcedResponse
    headline: Headline
    estimate: dict  # nodal_diameter, free_hz, stuck_hz, stuck_amplitude (None when not made)
    from_hz: float
    to_hz: float
    warnings: list
    library_seconds: float  # the library's call alone (the binding's overhead: docs/studies/python_overhead.md)
    harmonics_target: HarmonicsTarget = None  # harmonics="auto"'s outcome (None: harmonics given)
    time_domain_check: PeakInTime = None  # None: not asked, or no peak found
    _reference: object = field(default=None, repr=False)  # the curve as the library keeps it (follow_peak starts from it)
    _models: object = field(default=None, repr=False)


def forced_response(mesh, models, engine_order, harmonics=(0, 1, 2, 3), preload=0.0, kn=1e4 / 2.4, kt=1e4 / 2.4,
                    mu=0.4, law="per_area", patches=0, amplitude=1.0, direction=(0.0, 0.0, 1.0),
                    excitation_node_set="mid_blade", response_node_sets=("mid_blade",), samples=0,
                    frequency_range_hz=None, family=1, stability="auto", harmonics_check_to=0, gap=None,
                    engine=None, tolerance=None, harmonics_tolerance=None, harmonics_max=None, time_domain_check=None,
                    **steps):
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
    what it leaves incomplete; named: that engine alone; the disc's tolerance 1e-8).
    harmonics="auto": harmonics by an error target, as the scenes' `harmonics: auto`: the
    curve is traced with 0..1, the harmonics check raises H up to harmonics_max (None: 48;
    3..64) until each of the last two raises changed the peak by at most harmonics_tolerance
    (None: 0.01; 0 < it < 0.5), and the curve is traced again with those harmonics (the one
    returned; harmonics_target says what happened). `models` must hold the nodal diameters
    of harmonics 0..harmonics_max (nodal_diameters_for; an InputError naming models before
    the trace otherwise). time_domain_check: the peak integrated in time, a dict as the
    scenes' disc_response/time_domain_check: {"periods": 600 (>= 100), "steps_per_period":
    1024 (>= 16), at most 65536 steps a period and 2e7 steps in all}, the result's time_domain_check (a PeakInTime; None without a peak); its
    models must hold every nodal diameter the engine order reaches (harmonics 0..4 for EO 3
    on 24 sectors)."""
    spec = _core.DiscResponseSpec()
    spec.engine_order = arrays.integer(engine_order, "engine_order")
    # harmonics: auto as the scenes' (SceneReaders.cpp: readHarmonicList, readHarmonicsTarget,
    # readHarmonicsCheckTo): from 0..1, the check to harmonics_max, the target's keys refused
    # without it.
    auto = isinstance(harmonics, str)
    if auto and harmonics != "auto":
        raise InputError("harmonics", f"{harmonics!r}: 'auto' (by an error target), an int H (0..H) or a list")
    tolerance_target = 0.0
    if auto:
        tolerance_target = 0.01 if harmonics_tolerance is None else arrays.finite_number(harmonics_tolerance,
                                                                                          "harmonics_tolerance")
        if not 0 < tolerance_target < 0.5:
            raise InputError("harmonics_tolerance", f"{tolerance_target}: a relative change of the peak between "
                                                    "harmonic counts, 0 < tolerance < 0.5")
        harmonics_max = arrays.integer(48 if harmonics_max is None else harmonics_max, "harmonics_max", 3, 64,
                                       " (two raises from H = 1 meet the tolerance at H = 3 at the earliest; beyond "
                                       "64 a shroud's contact law is resolved by its samples, not by more harmonics)")
        if harmonics_check_to:
            raise InputError("harmonics_check_to", "with harmonics='auto' the check runs to harmonics_max")
        harmonics_check_to = harmonics_max
        spec.harmonics = [0, 1]
    else:
        for key, value in (("harmonics_tolerance", harmonics_tolerance), ("harmonics_max", harmonics_max)):
            if value is not None:
                raise InputError(key, "applies to harmonics='auto' only")
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
    time_domain = _time_domain_options(time_domain_check)
    # The models a scene builds for these keys (DiscSceneReaders.cpp): without them the
    # target's check stopped at H = 1 with a line of text, the time domain failed after the trace.
    sectors = models._core.sectors
    if 1 <= spec.engine_order < sectors:
        if auto:
            _check_models_hold(models, nodal_diameters_for(sectors, spec.engine_order, range(harmonics_max + 1)),
                               f"harmonics='auto' raises H up to harmonics_max = {harmonics_max}")
        if time_domain is not None:
            step = np.gcd(spec.engine_order, sectors)
            _check_models_hold(models, sorted({min(q, sectors - q) for q in range(0, sectors, step)}),
                               f"time_domain_check integrates every sector engine order {spec.engine_order} tells apart")
    raw = _core.disc_forced_response(mesh._core, models._core, spec, from_hz, to_hz, int(family), stability,
                                     int(harmonics_check_to), tolerance_target, time_domain, continuation)
    h = raw["headline"]
    return DiscResponse(
        curve=ForcedResponse(raw["curve"], raw["harmonics"], raw["num_dofs"], raw["output_dofs"]),
        headline=Headline(Convergence(h["convergence"]), h["value"], h["hz"], h["max_harmonic"], h["change"], h["text"]),
        estimate=raw["estimate"], from_hz=raw["from_hz"], to_hz=raw["to_hz"], warnings=list(raw["warnings"]),
        library_seconds=raw["library_seconds"],
        harmonics_target=None if raw["harmonics_target"] is None else HarmonicsTarget(**raw["harmonics_target"]),
        time_domain_check=None if raw["peak_in_time"] is None else PeakInTime(
            **{**raw["peak_in_time"], "ending": TimeDomainEnding(raw["peak_in_time"]["ending"])}),
        _reference=raw["reference"], _models=models)


def _check_models_hold(models, needed, why):
    missing = sorted(set(needed) - set(models.nodal_diameters))
    if missing:
        raise InputError("models", f"no model for nodal diameter(s) {missing}: {why}, which needs nodal diameters "
                                   f"{sorted(set(needed))} (reduced_models(..., nodal_diameters=...); the models hold "
                                   f"{models.nodal_diameters})")


def _time_domain_options(check):
    """time_domain_check as the scenes' disc_response/time_domain_check (DiscSweepReaders.cpp):
    None, or its keys with their defaults and refusals."""
    if check is None:
        return None
    if not isinstance(check, dict):
        raise InputError("time_domain_check", f"expects a dict, e.g. {{'periods': 600, 'steps_per_period': 1024}}, "
                                              f"got {check!r}")
    unknown = set(check) - {"periods", "steps_per_period"}
    if unknown:
        raise InputError("time_domain_check", f"unknown keys {sorted(unknown)}: known are periods, steps_per_period")
    periods = arrays.integer(check.get("periods", 600), "time_domain_check/periods")
    if periods < 100:
        raise InputError("time_domain_check/periods", f"{periods}: must be at least 100 (the steadiness is judged "
                                                      "over the last 50)")
    steps = arrays.integer(check.get("steps_per_period", 1024), "time_domain_check/steps_per_period")
    if steps < 16:
        raise InputError("time_domain_check/steps_per_period", f"{steps}: must be at least 16")
    return {"periods": periods, "steps_per_period": steps}
