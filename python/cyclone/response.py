"""A forced-response curve as numpy arrays, and the options of its trace.

The trace is the scenes' (cyclone run on `analysis: forced_response`): the first point
found at the start of the range, Cyclone's predictor-corrector over the range with LOCA
retracing what it leaves incomplete, Hill's stability where affordable, the bifurcation
flags, the peak of the first output DOF's max |x(t)| located on the curve, and the
samples and harmonics checks there."""

import enum
from dataclasses import dataclass

import numpy as np

from . import _core, arrays
from .errors import InputError


class BranchEnd(enum.Enum):
    """How a trace ended (continuation::BranchEnd); `stop_reason` says it as a sentence."""

    RUNNING = "running"  # not ended (a checkpoint's trace in progress)
    RANGE_END = "range_end"  # the end of the range reached
    MET_FROM_THE_END = "met_from_the_end"  # the range covered by a sweep from each end
    SINGLE_POINT = "single_point"  # the range is a single point
    RETURNED_TO_START = "returned_to_start"  # folded back and ran out at the bound it started from
    WALL = "wall"  # no step passes a point: the correctors failed down to the smallest step
    POINT_BUDGET = "point_budget"  # max_points spent
    NO_START = "no_start"  # no converged first point
    START_FAILED = "start_failed"  # the residual or Jacobian failed at the first point
    ENGINE_STOPPED = "engine_stopped"  # LOCA stopped

    @property
    def finished(self):
        """The whole range was traced."""
        return self in (BranchEnd.RANGE_END, BranchEnd.MET_FROM_THE_END, BranchEnd.SINGLE_POINT)


class ContinuationEngine(enum.Enum):
    """A continuation engine (continuation::ContinuationOptions::Engine), by its name in scenes."""

    PREDICTOR_CORRECTOR = "predictor_corrector"  # Cyclone's own
    LOCA = "loca"  # Trilinos LOCA


@dataclass(frozen=True)
class Retraces:
    """How a curve that needed more than one trace was obtained (continuation::Branch::retraces);
    stop_reason says the same in words. A curve traced once: its engine, False, 1, ()."""

    engine: ContinuationEngine  # the engine whose trace the curve is
    other_engine_tried: bool  # the other engine traced it again because one left it incomplete
    samples_factor: int  # the kept trace's AFT samples as a multiple of the system's (1: the system's)
    samples_factors_tried: tuple  # every multiple tried beyond 1 (2, then 4), in order

    @classmethod
    def _from_raw(cls, raw):
        return cls(ContinuationEngine(raw["engine"]), bool(raw["other_engine_tried"]), int(raw["samples_factor"]),
                   tuple(int(f) for f in raw["samples_factors_tried"]))


@dataclass(frozen=True)
class Peak:
    """The largest max |x(t)| of the first output DOF on the curve (located on the path, not
    the best of the points' samples)."""

    index: int  # its point
    value: float
    omega: float  # rad/s
    parameter: float  # the continuation parameter there (omega, or the force scale)


class ForcedResponse:
    """A traced curve. Per point i: parameter[i], omega[i] (rad/s), x[i] (the coefficients,
    HarmonicBalance's layout; coefficients[i, dof, slot]), amplitude[i, dof, j] (harmonic
    harmonics[j]: sqrt(cos^2 + sin^2), |mean| for harmonic 0), max_abs[i, k] (max |x(t)| of
    output_dofs[k]), stable[i] (1 stable, 0 unstable, 2 undetermined, -1 not computed),
    leading_exponent[i] (Floquet exponent of largest real part, nan if none), flags[i] ("fold",
    "branch_point", "period_doubling", "neimark_sacker", "turn" or ""), segment[i] (which sweep).
    end (a BranchEnd) and stop_reason say how the trace ended; retraces (a Retraces) whether it
    was traced again, with the other engine or more AFT samples, and which trace was kept; peak
    is the largest response."""

    def __init__(self, raw, harmonics, num_dofs, output_dofs):
        self.harmonics = list(harmonics)
        self.output_dofs = list(output_dofs)
        self.parameter = raw["parameter"]
        self.omega = raw["omega"]
        self.x = raw["x"]
        self.coefficients = self.x.reshape(len(self.omega), num_dofs, self.x.shape[1] // num_dofs)  # also of no point
        self.amplitude = raw["amplitude"]
        self.max_abs = raw["max_abs"]
        self.stable = raw["stable"]
        self.leading_exponent = raw["leading_exponent"]
        self.flags = np.array(raw["flags"], dtype=object)
        self.segment = raw["segment"]
        self.end = BranchEnd(raw["end"])
        self.stop_reason = raw["stop_reason"]
        self.retraces = Retraces._from_raw(raw["retraces"])
        self.start_method = raw["start_method"]
        self.stability_computed = raw["stability_computed"]
        self.stability_note = raw["stability_note"]
        self.samples_check = raw["samples_check"]
        self.harmonics_check = raw["harmonics_check"]
        self.harmonics_check_peak = raw["harmonics_check_peak"] or None
        self.seconds = raw["seconds"]
        self.peak = (Peak(raw["peak_index"], raw["peak"], raw["peak_omega"], raw["peak_parameter"])
                     if len(self.omega) and self.output_dofs else None)

    def __len__(self):
        return len(self.omega)

    @property
    def finished(self):
        return self.end.finished

    def mean(self, dof):
        """The mean (harmonic 0) of `dof` per point (zeros without harmonic 0)."""
        if not isinstance(dof, (int, np.integer)) or not 0 <= dof < self.coefficients.shape[1]:
            raise InputError("dof", f"{dof!r} is not a DOF of the system (0..{self.coefficients.shape[1] - 1})")
        if 0 not in self.harmonics:
            return np.zeros(len(self))
        return self.coefficients[:, dof, 0]

    def amplitude_of(self, dof, harmonic):
        """The amplitude of `harmonic` of `dof` per point."""
        if harmonic not in self.harmonics:
            raise InputError("harmonic", f"{harmonic} is not among the curve's harmonics {self.harmonics}")
        if not isinstance(dof, (int, np.integer)) or not 0 <= dof < self.amplitude.shape[1]:
            raise InputError("dof", f"{dof!r} is not a DOF of the system (0..{self.amplitude.shape[1] - 1})")
        return self.amplitude[:, dof, self.harmonics.index(harmonic)]

    def flagged(self, kind):
        """The points flagged `kind` (e.g. "fold")."""
        return np.flatnonzero(self.flags == kind)

    def __repr__(self):
        peak = f", peak {self.peak.value:.6g} at omega {self.peak.omega:.6g}" if self.peak else ""
        return f"<ForcedResponse: {len(self)} points, {self.end.value}{peak}>"


_STEP_LIMITS = {"initial_step": float, "min_step": float, "max_step": float, "turn_angle": float, "max_points": int}


def trace_options(system, start, end, parameter="omega", omega=None, force_scale=1.0, output_dofs=(0,),
                  stability="auto", harmonics_check=True, engine=None, tolerance=None, **steps):
    """The trace's settings, each checked (InputError naming the argument), as a scene's
    continuation and output keys (docs/scenes.md):

    parameter: "omega" (start, end in rad/s); or at the fixed frequency `omega`: "force_scale"
    (the excitation's scale s), "damping_scale" (C times s), "<element name>/<parameter>" (of
    every element of that name: kt, kn, stiffness, mu, preload of a friction contact; k, gap;
    kt, slip_force; k3; c2); force_scale: s of a curve in another parameter; output_dofs: the DOFs
    whose max |x(t)| is reported, the first one's peak located on the curve; stability:
    "auto" (Hill's method where affordable), "always", "never" (or True/False);
    harmonics_check: True (the peak again with H + 1), False (none) or the highest H to
    check up to; engine: None (the predictor-corrector, LOCA where it stops short),
    "predictor_corrector" or "loca" alone; tolerance: Newton's, relative to the forces
    (1e-14..1e-4; default 1e-10); steps: initial_step, min_step, max_step, max_points, turn_angle."""
    options = _core.TraceOptions()
    # As a scene (ForcedResponseScene.cpp): a curve of nothing vibrating, or of a static
    # load swept in frequency whose "peak" is the range's start, is refused.
    if not any(h >= 1 for _, h, _, _ in system._excitation):
        raise InputError("excitation", "has no force at a harmonic >= 1: nothing vibrates (add_excitation; a "
                                       "constant load is add_static_load)")
    if not isinstance(parameter, str) or (parameter not in ("omega", "force_scale", "damping_scale")
                                          and "/" not in parameter):
        raise InputError("parameter", f"{parameter!r}: must be 'omega', 'force_scale', 'damping_scale' or "
                                      "'<element name>/<parameter>' (e.g. 'contact/preload')")
    options.parameter = parameter
    options.element_names = system.element_names
    options.start, options.end = arrays.finite_number(start, "start"), arrays.finite_number(end, "end")
    if options.start == options.end:
        raise InputError("end", f"equals start ({options.start}): a range needs two different ends")
    if parameter == "omega":
        if omega is not None:
            raise InputError("omega", "is the fixed frequency of a curve in another parameter; a frequency curve runs "
                                      "from start to end")
        if not (options.start > 0 and options.end > 0):
            raise InputError("start" if options.start <= 0 else "end", "the frequency range must be positive (rad/s)")
    else:
        if omega is None or not arrays.finite_number(omega, "omega") > 0:
            raise InputError("omega", f"a {parameter} curve needs its fixed frequency, positive (rad/s)")
        options.omega = float(omega)
    options.force_scale = arrays.finite_number(force_scale, "force_scale")
    output_dofs = [output_dofs] if isinstance(output_dofs, (int, np.integer)) else list(output_dofs)
    options.output_dofs = [system._dof(d, "output_dofs") for d in output_dofs]
    stability = {True: "always", False: "never"}.get(stability, stability)
    if stability not in ("auto", "always", "never"):
        raise InputError("stability", f"{stability!r}: must be 'auto', 'always', 'never', True or False")
    options.stability = stability
    options.harmonics_check_to = _harmonics_check_to(harmonics_check, max(system.harmonics))
    set_continuation(options, engine, tolerance, steps)
    if parameter == "force_scale":
        # The residual is relative to the forces at scale 1, so a point at scale s is solved
        # to tolerance / s of its own forces: near 0 the solution 0 passes.
        smallest = 1e4 * (tolerance if tolerance is not None else 1e-10)
        for key, value in (("start", options.start), ("end", options.end)):
            if value != 0 and abs(value) < smallest:
                raise InputError(key, f"a force scale of {value:g} is solved to the tolerance over it of its own "
                                      f"forces (the residual is relative to the forces at scale 1): start at "
                                      f"{smallest:g} or above, or at 0")
    return options


def set_continuation(options, engine, tolerance, steps):
    """The continuation's keys of a scene (its `continuation` section) on a _core.TraceOptions,
    each checked (InputError naming it): engine None (the predictor-corrector, LOCA where it
    stops short), "predictor_corrector" or "loca" alone; tolerance (1e-14..1e-4); steps."""
    if engine not in (None, "predictor_corrector", "loca"):
        raise InputError("engine", f"{engine!r}: must be None, 'predictor_corrector' or 'loca'")
    options.engine = engine or ""
    if tolerance is not None:
        tolerance = arrays.finite_number(tolerance, "tolerance")
        if not 1e-14 <= tolerance <= 1e-4:
            raise InputError("tolerance", f"{tolerance}: must lie in 1e-14..1e-4, the residual relative to the forces")
        options.tolerance = tolerance
    _set_steps(options, steps, engine)
    return options


def _harmonics_check_to(check, highest):
    if check is True:
        return 0
    if check is False:
        return -1
    if not isinstance(check, (int, np.integer)) or check <= highest:
        raise InputError("harmonics_check", f"{check!r}: True, False or a highest harmonic above the curve's {highest}")
    return int(check)


def _set_steps(options, steps, engine):
    for key, value in steps.items():
        if key not in _STEP_LIMITS:
            raise InputError(key, "is not an option of the trace (" + ", ".join(_STEP_LIMITS) + ")")
        value = _STEP_LIMITS[key](arrays.finite_number(value, key))
        if key == "max_points" and value < 2:
            raise InputError(key, f"{value}: must be at least 2")
        if key == "turn_angle" and not 0 < value < 1.5:
            raise InputError(key, f"{value}: must lie in (0, 1.5) radians")
        if key.endswith("_step"):
            if not value > 0:
                raise InputError(key, f"{value}: must be positive")
            if engine != "loca" and value > 1:
                raise InputError(key, f"{value}: must be at most 1 (the predictor-corrector's steps are in the "
                                      "scaled space x / |x|, p / |end - start|, where 1 spans the whole range)")
        setattr(options, key, value)
    if "min_step" in steps and "max_step" in steps and options.max_step < options.min_step:
        raise InputError("max_step", "must be at least min_step")
