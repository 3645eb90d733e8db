"""Cyclone from Python: harmonic balance of matrix systems with friction, gaps and other
nonlinear elements, traced over the frequency or the force, results as numpy arrays.

    import numpy as np, cyclone
    duffing = cyclone.HarmonicBalance(M=[[1.0]], K=[[1.0]], C=[[0.05]], harmonics=7)
    duffing.add_element(cyclone.CubicSpring(k3=0.1), dofs=[0])
    duffing.add_excitation(dof=0, harmonic=1, cos=0.18)
    curve = duffing.forced_response(0.5, 2.0)
    curve.omega, curve.max_abs[:, 0], curve.peak, curve.end

The bladed disc's chain (the built-in sector, reduced models, the friction forced
response and its headline): cyclone.disc. The compiled part is cyclone._core (not meant for direct use). The library's progress
lines go to the logger "cyclone"; its errors arrive as cyclone.InputError (a ValueError
with the key it names) and cyclone.SolverError (a RuntimeError).
"""

from . import disc
from .damping import modal_damping
from .elements import CubicSpring, Element, Friction2D, Friction3D, Jenkins, QuadraticDamper, UnilateralSpring
from .errors import InputError, SolverError
from .peaks import FollowedPeaks, PeakFollowingEnd
from .response import BranchEnd, ContinuationEngine, ForcedResponse, Peak, Retraces
from .system import HarmonicBalance

__all__ = [
    "BranchEnd", "ContinuationEngine", "CubicSpring", "disc", "Element", "FollowedPeaks", "ForcedResponse", "Friction2D",
    "Friction3D", "HarmonicBalance", "InputError", "Jenkins", "modal_damping", "Peak", "PeakFollowingEnd", "QuadraticDamper",
    "Retraces", "SolverError", "UnilateralSpring",
]
