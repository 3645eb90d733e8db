"""The sector's modes over speeds from Python against the program on the same modal
scene: the built-in sector at mesh size 12, fixed shroud, linear prestress at 0 and
10 000 rpm, 3 modes at nodal diameters 0, 3 and 12: every frequency of the program's
frequencies.csv to 1e-10 (its 12 digits). And what the physics must give: centrifugal
stiffening raises every frequency, and a travelling-wave pair (0 < k < N/2) is listed
twice with one frequency. Label scene with the disc (about 5 s)."""

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


@pytest.mark.disc
def test_the_modes_equal_the_programs(cyclone_program, tmp_path):
    frequencies = program.read_csv(program.run(cyclone_program, SCENE, tmp_path / "out") / "frequencies.csv")
    rpms, nds = frequencies["rpm"].astype(float), frequencies["nd"].astype(int)

    sector = cyclone.disc.shrouded_sector(mesh_size=12.0)
    modes = cyclone.disc.modal_sweep(sector, speeds_rpm=[0.0, 10000.0], modes_per_nd=3, nodal_diameters=[0, 3, 12],
                                     threads=1)
    np.testing.assert_array_equal(modes.rpm, [0.0, 10000.0])
    assert modes.nodal_diameters == [0, 3, 12]
    for s, rpm in enumerate(modes.rpm):
        for k in modes.nodal_diameters:
            expected = frequencies["freq_hz"][(rpms == rpm) & (nds == k)].astype(float)
            np.testing.assert_allclose(modes.frequencies_hz(k)[s], expected, rtol=1e-10)
    assert np.all(modes.frequencies_hz(3)[1] > modes.frequencies_hz(3)[0])  # stiffened by the speed
    pair = modes.frequencies_hz(3)[0]
    np.testing.assert_allclose(pair[0::2], pair[1::2], rtol=1e-8)  # each frequency of ND 3 twice
    assert len(modes.frequencies_hz(0)[0]) == 3 and len(pair) == 6
