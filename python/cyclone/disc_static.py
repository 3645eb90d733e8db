"""One linear static solve of a sector under its centrifugal load, as a static scene
(docs/scenes.md, `analysis: [static]`): the node sets held, the speed's load on the
undeformed geometry (no spin softening), the displacement and the nodes' von Mises
stress (mm, MPa).

    sector = cyclone.disc.shrouded_sector(mesh_size=10.0)
    solution = cyclone.disc.static_solve(sector, speed_rpm=10000.0)
    solution.displacement, solution.max_displacement, solution.relative_residual"""

from dataclasses import dataclass

import numpy as np

from . import _core, arrays
from .errors import InputError


@dataclass(frozen=True)
class StaticSolution:
    """displacement (nodes x 3, mm, the mesh's node order), von_mises (per node, the mean of
    its elements', MPa), equations (the free DOFs), max_displacement and its node's index,
    max_von_mises, relative_residual (||b - K u|| / ||b||, measured after the solve)."""

    displacement: np.ndarray
    von_mises: np.ndarray
    equations: int
    max_displacement: float
    max_displacement_node: int
    max_von_mises: float
    relative_residual: float


def static_solve(mesh, speed_rpm=0.0, fixed_node_sets=("bore",), material=None):
    """The static displacement of `mesh` spinning at `speed_rpm` about the z axis, the
    `fixed_node_sets` held (an InputError naming fixed_node_sets when none, the set for an
    unknown one; a SolverError when they leave a rigid-body motion); material: a cyclone.disc.Material (titanium by default)."""
    from .disc import Material  # cyclone.disc imports this module

    material = material or Material()
    speed = arrays.finite_number(speed_rpm, "speed_rpm")
    if speed < 0:
        raise InputError("speed_rpm", f"{speed}: must be >= 0")
    if not len(fixed_node_sets):  # as a static scene refuses it
        raise InputError("fixed_node_sets", "a static solve needs fixed node sets (the model would move as a rigid body)")
    raw = _core.static_solve(mesh._core, (material.name, material.E, material.nu, material.rho),
                             [str(s) for s in fixed_node_sets], speed)
    return StaticSolution(**raw)
