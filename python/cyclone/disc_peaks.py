"""The disc's resonance peak followed over a parameter from a forced response's curve, as
a disc scene's disc_response/peak_studies (docs/scenes.md): the curve's prominent peaks
followed down and up a grid from the response's own value of the parameter (a peak
search per value), or the largest continued by LOCA (method "continuation"); the
optimum's peak found again with more harmonics (its truncation error).

    response = cyclone.disc.forced_response(sector, models, engine_order=3, preload=20000.0, ...)
    peaks = cyclone.disc.follow_peak(response, "preload", (10000.0, 40000.0), values=8)
    peaks.parameter, peaks.hz, peaks.peak, peaks.optimum, peaks.end"""

import numpy as np

from . import _core, arrays
from .errors import InputError
from .peaks import FollowedPeaks

PARAMETERS = ("preload", "mu", "contact_stiffness", "force", "loss_factor", "clearance", "speed")


class DiscFollowedPeaks(FollowedPeaks):
    """FollowedPeaks (peak: max |x(t)| of the response node's first DOF, mm), and: grid (the
    values followed), reference_value (the response's, where the following starts),
    force_beyond[i] (the contact forces' harmonics above H over those kept at peak i; -1 not
    known), optimum_check (the optimum's peak with each raise of the harmonics: max_harmonic,
    found, value, hz), optimum_check_change (their largest relative change; -1: a level not
    found), warnings. peak_<name>.csv's columns: parameter, hz, peak, jump, optimum, force_beyond."""

    def __init__(self, raw):
        super().__init__(raw, raw["num_dofs"], raw["num_coefficients"])
        self.grid = raw["grid"]
        self.reference_value = raw["reference_value"]
        self.starting_peaks = raw["starting_peaks"]
        self.warnings = list(raw["warnings"])
        self.by_force = raw["by_force"]
        self.continued = raw["continued"]
        self.force_beyond = raw["force_beyond"]
        self.optimum_check = list(raw["optimum_check"])
        self.optimum_check_change = raw["optimum_check_change"]


def follow_peak(response, parameter, range, values=24, method="peak_search", phase_step=0.1, optimum_raises=2):
    """The peak of `response` (cyclone.disc.forced_response's) followed over `parameter`
    ("preload", "mu", "contact_stiffness" (kn = kt), "force" (the excitation's scale),
    "loss_factor" (the models'), "clearance" (mm, the gap elements'), "speed" (rpm: the
    models built again at each, in the models' cache)) from range[0] to range[1], which
    must contain the response's value; `values` evenly in log (linearly for the clearance
    and the speed), 3..400. The peak_studies keys; returns a DiscFollowedPeaks."""
    reference = getattr(response, "_reference", None)
    if reference is None:
        raise InputError("response", "must be a cyclone.disc.forced_response result")
    if parameter not in PARAMETERS:
        raise InputError("parameter", f"{parameter!r}: must be one of {', '.join(PARAMETERS)}")
    try:
        start, end = (arrays.finite_number(v, "range") for v in range)
    except (TypeError, ValueError):
        raise InputError("range", f"must be (from, to), got {range!r}") from None
    if not isinstance(values, (int, np.integer)) or not 3 <= values <= 400:
        raise InputError("values", f"{values!r}: must be an int in 3..400")
    if method == "continuation" and values != 24:
        raise InputError("values", "is not used by method continuation (LOCA's steps are the points): leave it out")
    spec = _core.DiscFollowSpec()
    spec.parameter, spec.start, spec.end, spec.values = parameter, start, end, int(values)
    spec.method, spec.phase_step = method, arrays.finite_number(phase_step, "phase_step")
    spec.optimum_raises = int(optimum_raises)
    models = response._models
    return DiscFollowedPeaks(_core.disc_follow_peak(reference, spec, models._spec, models._cache))
