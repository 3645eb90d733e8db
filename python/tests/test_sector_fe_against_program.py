"""The sector's finite-element calls from Python against the cyclone program on the same
sector (the built-in one at mesh size 12): the static solve at 10 000 rpm, bore held, as
the program's static.exo (every node's displacement and von Mises stress). Label scene
(about 2 s)."""

import netCDF4
import numpy as np
import pytest

import cyclone
import program

STATIC = """cyclone:
  analysis: [static]
""" + program.SECTOR + """  loads: {speed_rpm: 10000.0}
"""


@pytest.fixture(scope="module")
def sector():
    return cyclone.disc.shrouded_sector(mesh_size=12.0)


def exodus_nodal(path):
    """{name: values per node} of the one step of an Exodus file."""
    with netCDF4.Dataset(path) as f:
        names = [str(n) for n in netCDF4.chartostring(f["name_nod_var"][:])]
        return {name: np.asarray(f[f"vals_nod_var{i + 1}"][0]) for i, name in enumerate(names)}


@pytest.mark.disc
def test_the_static_solve_equals_the_programs(cyclone_program, tmp_path, sector):
    expected = exodus_nodal(program.run(cyclone_program, STATIC, tmp_path / "out") / "static.exo")
    solution = cyclone.disc.static_solve(sector, speed_rpm=10000.0, fixed_node_sets=["bore"])
    u = np.column_stack([expected[name] for name in ("ux", "uy", "uz")])
    assert solution.displacement.shape == u.shape == (sector.num_nodes, 3)
    np.testing.assert_allclose(solution.displacement, u, rtol=0, atol=1e-12 * abs(u).max())
    np.testing.assert_allclose(solution.von_mises, expected["von_mises"], rtol=0,
                               atol=1e-12 * expected["von_mises"].max())
    assert solution.max_displacement == pytest.approx(np.linalg.norm(u, axis=1).max(), rel=1e-12)
    assert solution.equations == 3 * (sector.num_nodes - len(sector.node_sets["bore"]))
