"""The sector's finite-element calls from Python against the cyclone program on the same
sector (the built-in one at mesh size 12): the static solve at 10 000 rpm, bore held, as
the program's static.exo (every node's displacement and von Mises stress); the sector
written as a mesh file and read back, as the sector (the example 01's path); and the ND 3
reduced model's check against the full FE model, built from Python in a cache of its own,
as the program's rom_check.csv, its file read back from that cache and named as the
program's of the same model. Label scene (about 15 s)."""

import pathlib

import netCDF4
import numpy as np
import pytest

import cyclone
import program

STATIC = """cyclone:
  analysis: [static]
""" + program.SECTOR + """  loads: {speed_rpm: 10000.0}
"""

# A disc scene is what builds a checked model: its engine order's nodal diameter (3) is checked.
CHECKED = """cyclone:
  analysis: [disc_response]
""" + program.SECTOR + """  loads: {speed_rpm: 10000.0}
  reduced_model: {check_frequencies: 12}
  disc_response:
    engine_order: 3
    harmonics: [0, 1]
    contact: {preload: 20000.0}
    excitation: {amplitude: 20.0}
    stability: false
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


@pytest.mark.disc
@pytest.mark.parametrize("suffix", [".inp", ".exo"])
def test_a_mesh_written_and_read_back_is_the_sector(tmp_path, sector, suffix):
    cyclone.disc.write_mesh(sector, tmp_path / f"sector{suffix}")
    read = cyclone.disc.read_mesh(tmp_path / f"sector{suffix}", sectors=24)
    assert (read.num_nodes, read.num_elements) == (sector.num_nodes, sector.num_elements)
    np.testing.assert_allclose(read.coordinates, sector.coordinates, rtol=1e-15, atol=1e-13)
    assert read.node_sets.keys() == sector.node_sets.keys()
    for name, nodes in sector.node_sets.items():
        np.testing.assert_array_equal(np.sort(read.node_sets[name]), np.sort(nodes), err_msg=name)
    with pytest.raises(cyclone.InputError) as error:
        cyclone.disc.write_mesh(sector, tmp_path / "sector.vtk")
    assert error.value.key == "path"


@pytest.mark.disc
def test_the_reduced_model_check_equals_the_programs(cyclone_program, tmp_path, sector):
    expected = program.read_csv(program.run(cyclone_program, CHECKED, tmp_path / "out") / "rom_check.csv")
    models = cyclone.disc.reduced_models(sector, rpm=10000.0, nodal_diameters=[3], check_nodal_diameter=3,
                                         cache_directory=tmp_path / "models")
    assert models.built == 1  # checked here, not read back
    # The file written to the cache is read back (not built again), and its name, a digest of
    # every input, is the one the program gave the same model in its run.
    again = cyclone.disc.reduced_models(sector, rpm=10000.0, nodal_diameters=[3], cache_directory=tmp_path / "models")
    assert (again.built, again.reused) == (0, 1) and again.files[3] == models.files[3]
    np.testing.assert_array_equal(again.natural_hz[3], models.natural_hz[3])
    assert (tmp_path / "out" / "reduced_models" / pathlib.Path(models.files[3]).name).exists()
    check = models.check
    assert check.nodal_diameter == 3 and not check.reused
    assert len(check.hz) == len(expected["freq_hz"]) == 12
    # rom_check.csv's 12 significant digits.
    for values, column in [(check.hz, "freq_hz"), (check.reduced, "reduced_abs"), (check.full, "full_abs"),
                           (check.error, "relative_error")]:
        np.testing.assert_allclose(values, expected[column].astype(float), rtol=1e-11, err_msg=column)
