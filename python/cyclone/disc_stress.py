"""The sector's stresses and fatigue margin at the disc's friction-damped peak, as a disc
scene's disc_response/peak_stress (docs/scenes.md): the whole sector's vibration at the
response's peak (the harmonics check's highest level found, else the traced point nearest
the peak; or the curve at `at_hz`) by a full FE solve per harmonic under the loads the
harmonic balance solution puts on the retained DOFs, and per node the stress cycle's
signed mean von Mises, alternating von Mises and principal, largest von Mises and the
Goodman-Haigh safety factor (MPa: the library's mm-N-s-t).

    stress = cyclone.disc.peak_stress(response, fatigue="Ti-6Al-4V")
    stress.safety_factor.min(), stress.critical_node, stress.alternating_von_mises[stress.critical]"""

import numpy as np

from . import _core, arrays
from .errors import InputError

_STRENGTHS = ("ultimate_strength", "endurance_limit", "yield_strength", "design_cycles")


class PeakStress:
    """Per node i of the mesh (node_ids[i], coordinates[i], mm): mean_von_mises[i] (signed:
    the sign of the mean's largest principal), alternating_von_mises[i],
    alternating_principal[i], max_von_mises[i] (the period's largest), safety_factor[i]
    (Goodman-Haigh; the arrays are None without fatigue data). critical: the index of the
    smallest safety factor, critical_node its id. hz, what (the point), caveat (why it is an
    estimate, empty when converged to 1 % in the harmonics), model_error (the field at the
    retained DOFs against the harmonic balance solution), harmonics and nodal_diameters of
    the FE solves. disc_peak_stress.csv lists the same nodes worst first."""

    def __init__(self, raw):
        self.node_ids = raw["node_ids"]
        self.coordinates = raw["coordinates"]
        self.hz, self.what, self.caveat = raw["hz"], raw["what"], raw["caveat"]
        self.model_error = raw["model_error"]
        self.harmonics, self.nodal_diameters = list(raw["harmonics"]), list(raw["nodal_diameters"])
        self.mean_von_mises = raw.get("mean_von_mises")
        self.alternating_von_mises = raw.get("alternating_von_mises")
        self.alternating_principal = raw.get("alternating_principal")
        self.max_von_mises = raw.get("max_von_mises")
        self.safety_factor = raw.get("safety_factor")
        self.critical = raw.get("critical")
        self.critical_node = None if self.critical is None else int(self.node_ids[self.critical])
        self.material = raw.get("material")

    def __repr__(self):
        if self.critical is None:
            return f"<PeakStress at {self.hz:.6g} Hz, no fatigue data>"
        return (f"<PeakStress at {self.hz:.6g} Hz: safety factor {self.safety_factor[self.critical]:.4g} at node "
                f"{self.critical_node}>")


def peak_stress(response, fatigue="Ti-6Al-4V", at_hz=None):
    """The sector's vibration, stresses and fatigue margin at the peak of `response`
    (cyclone.disc.forced_response's). fatigue: "Ti-6Al-4V" (the annealed alloy's data sheet
    values), a dict of ultimate_strength, endurance_limit and optionally yield_strength,
    design_cycles (MPa; or with data="Ti-6Al-4V", each overriding it), or None (the
    stresses' field only, no margin). at_hz: a frequency of the curve instead of the peak."""
    reference = getattr(response, "_reference", None)
    if reference is None:
        raise InputError("response", "must be a cyclone.disc.forced_response result")
    if isinstance(fatigue, str):
        fatigue = {"data": fatigue}
    elif fatigue is not None:
        if not isinstance(fatigue, dict):
            raise InputError("fatigue", f"must be 'Ti-6Al-4V', a dict of strengths or None, got {fatigue!r}")
        unknown = set(fatigue) - set(_STRENGTHS) - {"data", "name"}
        if unknown:
            raise InputError("fatigue", f"{sorted(unknown)}: not known (" + ", ".join(_STRENGTHS) + ", data, name)")
        fatigue = {key: (value if key in ("data", "name") else arrays.finite_number(value, key))
                   for key, value in fatigue.items()}
    hz = 0.0
    if at_hz is not None:
        hz = arrays.finite_number(at_hz, "at_hz")
        if not hz > 0:
            raise InputError("at_hz", f"{hz}: must be a positive frequency in Hz (None for the peak)")
    return PeakStress(_core.disc_peak_stress(reference, response._models._spec, fatigue, hz))
