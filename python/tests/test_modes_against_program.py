"""The sector's modes over speeds from Python against the program on the same modal
scene: the built-in sector at mesh size 12, fixed shroud, linear prestress at 0 and
10 000 rpm, 3 modes at nodal diameters 0, 3 and 12: every frequency of the program's
frequencies.csv to 1e-10 (its 12 digits). And what the physics must give: centrifugal
stiffening raises every frequency, and a travelling-wave pair (0 < k < N/2) is listed
twice with one frequency. With the shapes kept, every mode's shape as the program's
modes_<rpm>rpm.exo holds it (1e-12 of its largest entry), and the Campbell branches and
engine-order resonances as its campbell.csv and resonances.csv (their 12 digits).
Label scene with the disc (about 5 s)."""

import netCDF4
import numpy as np
import pytest

import cyclone
import program

SCENE = """cyclone:
  analysis: [modal]
""" + program.SECTOR + """  modal:
    speeds_rpm: [0.0, 10000.0]
    modes_per_nd: 3
    nodal_diameters: [0, 3, 12]
    threads: 1
"""


@pytest.fixture(scope="module")
def program_out(cyclone_program, tmp_path_factory):
    return program.run(cyclone_program, SCENE, tmp_path_factory.mktemp("modes") / "out")


@pytest.fixture(scope="module")
def sweep():
    sector = cyclone.disc.shrouded_sector(mesh_size=12.0)
    return sector, cyclone.disc.modal_sweep(sector, speeds_rpm=[0.0, 10000.0], modes_per_nd=3,
                                            nodal_diameters=[0, 3, 12], threads=1, shapes=True)


@pytest.mark.disc
def test_the_modes_equal_the_programs(program_out, sweep):
    frequencies = program.read_csv(program_out / "frequencies.csv")
    rpms, nds = frequencies["rpm"].astype(float), frequencies["nd"].astype(int)
    _, modes = sweep
    np.testing.assert_array_equal(modes.rpm, [0.0, 10000.0])
    assert modes.nodal_diameters == [0, 3, 12]
    for s, rpm in enumerate(modes.rpm):
        for k in modes.nodal_diameters:
            expected = frequencies["freq_hz"][(rpms == rpm) & (nds == k)].astype(float)
            np.testing.assert_allclose(modes.frequencies_hz(k)[s], expected, rtol=1e-10)


def exodus_modes(path):
    """The program's modes_<rpm>rpm.exo: per step (a mode) its nodal diameter, mode number
    and the nodes' real and imaginary shape (nodes x 3 each)."""
    with netCDF4.Dataset(path) as f:
        names = [str(n) for n in netCDF4.chartostring(f["name_nod_var"][:])]
        fields = np.stack([np.asarray(f[f"vals_nod_var{i + 1}"][:]) for i in range(len(names))], axis=-1)
        global_values = np.asarray(f["vals_glo_var"][:])
    real = fields[:, :, [names.index(n) for n in ("ux", "uy", "uz")]]
    imag = fields[:, :, [names.index(n) for n in ("u_imag_x", "u_imag_y", "u_imag_z")]]
    return global_values[:, 0].astype(int), global_values[:, 1].astype(int), real + 1j * imag


@pytest.mark.disc
def test_the_shapes_and_the_campbell_data_equal_the_programs(program_out, sweep):
    out = program_out
    campbell, resonances = program.read_csv(out / "campbell.csv"), program.read_csv(out / "resonances.csv")
    sector, modes = sweep
    # Every mode's shape as the program's Exodus file holds it (double precision).
    for s, rpm in enumerate(modes.rpm):
        nds, numbers, shapes = exodus_modes(out / f"modes_{rpm:g}rpm.exo")
        for k in modes.nodal_diameters:
            ours = modes.shapes(k)[s]
            count = 6 if k == 3 else 3  # each member of a travelling-wave pair, as the frequencies
            assert ours.shape == (count, sector.num_nodes, 3)
            for mode in range(count):
                theirs = shapes[(nds == k) & (numbers == mode + 1)][0]
                np.testing.assert_allclose(ours[mode], theirs, rtol=0, atol=1e-12 * abs(theirs).max())
            if k in (0, 12):  # a standing wave (one copy): no imaginary part
                assert not ours.imag.any()
    # The Campbell branches (families tracked by MAC) and the engine-order resonances, to the CSVs' 12 digits.
    assert len(modes.branches) == len(set(zip(campbell["nd"], campbell["family"])))
    for branch in modes.branches:
        rows = (campbell["nd"].astype(int) == branch.nd) & (campbell["family"].astype(int) == branch.family)
        np.testing.assert_allclose(branch.hz, campbell["freq_hz"][rows].astype(float), rtol=1e-11)
        np.testing.assert_allclose(branch.worst_mac, campbell["worst_mac"][rows].astype(float), rtol=1e-11)
    assert len(modes.resonances["eo"]) == len(resonances["eo"]) > 0
    for key in ("eo", "nd", "family"):
        np.testing.assert_array_equal(modes.resonances[key], resonances[key].astype(int))
    np.testing.assert_allclose(modes.resonances["rpm"], resonances["rpm"].astype(float), rtol=1e-11)
    np.testing.assert_allclose(modes.resonances["hz"], resonances["freq_hz"].astype(float), rtol=1e-11)
    # A crossing lies on the engine order's line f = EO rpm / 60 (the Campbell diagram's).
    np.testing.assert_allclose(modes.resonances["hz"], modes.resonances["eo"] * modes.resonances["rpm"] / 60,
                               rtol=1e-12)
