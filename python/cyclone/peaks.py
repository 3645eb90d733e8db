"""A resonance peak followed over a parameter, as numpy arrays: a matrix system's
(HarmonicBalance.follow_peak) and the disc's (cyclone.disc.follow_peak) alike.

A peak search per value (Newton at fixed frequencies, golden section to 1e-7 of the
frequency) from the peak before, instead of a frequency curve per value; where the
followed peak vanishes the band is swept and its largest peak taken, marked `jump`
(docs/scenes.md, peak_studies)."""

import enum

import numpy as np


class PeakFollowingEnd(enum.Enum):
    """How a peak's following ended (continuation::PeakFollowingEnd); `stop_reason` says it
    as a sentence, with where."""

    RUNNING = "running"  # not ended
    RANGE_END = "range_end"  # every value has its peak
    NO_PEAK_AT_START = "no_peak_at_start"  # no peak (or no response) at the first value
    PEAK_VANISHED = "peak_vanished"  # the followed peak vanished and the band's sweep found none
    VALUE_NOT_REACHED = "value_not_reached"  # none of several followed peaks reached a value
    CONTINUATION_STOPPED = "continuation_stopped"  # the LOCA continuation of the peak ended inside the range

    @property
    def finished(self):
        return self is PeakFollowingEnd.RANGE_END


class FollowedPeaks:
    """Per peak i: parameter[i], omega[i] (rad/s), peak[i] (max |x(t)| of the first output
    DOF), jump[i] (the followed peak vanished before it: the band's largest), x[i] (the
    coefficients; coefficients[i, dof, slot]). optimum: the index of the smallest peak (per
    unit force over the force scale; None where there is none), optimum_located (between its
    grid neighbours by golden section); end (a PeakFollowingEnd) and stop_reason."""

    def __init__(self, raw, num_dofs, num_coefficients):
        self.parameter = raw["parameter"]
        self.omega = raw["omega"]
        self.peak = raw["peak"]
        self.jump = raw["jump"]
        self.x = raw["x"]
        self.coefficients = self.x.reshape(len(self.parameter), num_dofs, num_coefficients)
        self.optimum = raw["optimum"] if raw["optimum"] >= 0 else None
        self.optimum_located = raw["optimum_located"]
        self.end = PeakFollowingEnd(raw["end"])
        self.stop_reason = raw["stop_reason"]
        self.sweeps, self.searches, self.solves = raw["sweeps"], raw["searches"], raw["solves"]
        self.seconds = raw["seconds"]

    def __len__(self):
        return len(self.parameter)

    @property
    def finished(self):
        return self.end.finished

    @property
    def hz(self):
        return self.omega / (2 * np.pi)

    def __repr__(self):
        return f"<FollowedPeaks: {len(self)} values, {self.end.value}>"
