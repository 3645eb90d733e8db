"""The disc's value-list studies, as a disc scene's disc_response/studies (docs/scenes.md):
one frequency curve per value of a contact, excitation or model parameter, over the
band of a forced response's curve and with its trace's options (no harmonics check: a
study's truncation error is the response's). A value that reproduces the response is
its curve, not traced again.

    response = cyclone.disc.forced_response(sector, models, engine_order=3, preload=20000.0, ...)
    study = cyclone.disc.study(response, "preload", [10000.0, 20000.0, 40000.0])
    study.values, study.peak_hz, study.peak, study.curves[0].omega"""

import numpy as np

from . import _core, arrays
from .errors import InputError
from .response import ForcedResponse

PARAMETERS = ("preload", "mu", "contact_stiffness", "force", "clearance", "harmonics", "loss_factor", "modes")


class DiscStudy:
    """Per value i (study_<name>.csv's rows): values[i], peak_hz[i] and peak[i] (the curve's
    largest max |x(t)| of the response node's first DOF, mm; nan where the curve has no
    point), points[i], finished[i] (the whole band traced), is_reference[i] (the response's
    own curve), seconds[i]; curves[i], a ForcedResponse (its harmonics the value's for a
    harmonics study), and warnings[i]."""

    def __init__(self, parameter, raw):
        self.parameter = parameter
        self.curves = [ForcedResponse(c["curve"], c["harmonics"], c["num_dofs"], c["output_dofs"]) for c in raw]
        self.values = np.array([c["value"] for c in raw])
        self.is_reference = np.array([c["is_reference"] for c in raw])
        self.warnings = [list(c["warnings"]) for c in raw]
        self.seconds = np.array([c["seconds"] for c in raw])
        self.points = np.array([len(c) for c in self.curves])
        self.finished = np.array([c.finished for c in self.curves])
        self.peak = np.array([c.peak.value if c.peak else np.nan for c in self.curves])
        self.peak_hz = np.array([c.peak.omega / (2 * np.pi) if c.peak else np.nan for c in self.curves])

    def __len__(self):
        return len(self.curves)

    def __repr__(self):
        return f"<DiscStudy over {self.parameter}: {len(self)} curves>"


def study(response, parameter, values):
    """The curves of `response` (cyclone.disc.forced_response's) at each of `values` of
    `parameter`: "preload", "mu", "contact_stiffness" (kn = kt), "force" (times the
    excitation's amplitude), "clearance" (mm, the gap elements'), "harmonics" (H: 0..H, up
    to the response's harmonics_check_to), "loss_factor" or "modes" (the reduced models'
    structural damping, or their first modes: hybrid and truncation models). The speed is
    followed, not studied (follow_peak). Every value is checked before any curve is traced
    (an InputError naming values). The studies keys; returns a DiscStudy."""
    reference = getattr(response, "_reference", None)
    if reference is None:
        raise InputError("response", "must be a cyclone.disc.forced_response result")
    if parameter not in PARAMETERS:
        raise InputError("parameter", f"{parameter!r}: must be one of {', '.join(PARAMETERS)} (the speed: follow_peak)")
    values = [arrays.finite_number(v, "values") for v in np.atleast_1d(values)]
    if not values:
        raise InputError("values", "needs at least one value")
    return DiscStudy(parameter, _core.disc_study(reference, parameter, values, response._models._spec))
