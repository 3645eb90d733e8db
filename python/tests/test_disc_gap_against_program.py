"""Gap elements on the disc from Python against the cyclone program: the disc of
test_disc_against_program.py with two shroud pairs as gap elements (normal direction only,
a clearance of 1 um) in place of friction contacts, its curve (every point's frequency and
max |x(t)| to 1e-10), and the study over the gap's clearance (every curve as the program's
study_clearance_<i>.csv, every peak as study_clearance.csv); without stability, to keep
the test short. Label scene."""

import numpy as np
import pytest

import cyclone
import program

GAP = {"pairs": [0, 1], "kn": 1.0e4, "clearance": 0.001}
CLEARANCES = [0.0, 0.003]
SCENE = program.DISC_SCENE + """    gap: {pairs: [0, 1], kn: 1.0e4, clearance: 0.001}
    stability: false
    studies:
      clearance: [0.0, 0.003]
"""


@pytest.fixture(scope="module")
def disc(cyclone_program, tmp_path_factory):
    """The program's products on SCENE, and Python's response on the same disc."""
    out = program.run(cyclone_program, SCENE, tmp_path_factory.mktemp("disc_gap") / "out")
    sector = cyclone.disc.shrouded_sector(mesh_size=12.0)
    nds = cyclone.disc.nodal_diameters_for(sector.sectors, engine_order=3, harmonics=[0, 1, 2])
    models = cyclone.disc.reduced_models(sector, rpm=10000.0, nodal_diameters=nds, cache_directory=out / "reduced_models")
    assert (models.reused, models.built) == (3, 0)
    response = cyclone.disc.forced_response(sector, models, engine_order=3, harmonics=[0, 1], preload=20000.0,
                                            amplitude=20.0, harmonics_check_to=2, stability=False, gap=GAP)
    return out, response


def number(table, key):
    return table[key].astype(float)


def assert_curve_equal(curve, expected):
    np.testing.assert_allclose(curve.omega, number(expected, "omega_rad_s"), rtol=1e-10)
    maxima = [key for key in expected if key.endswith("_max")]
    assert len(maxima) == curve.max_abs.shape[1] == 3
    for k, key in enumerate(maxima):
        np.testing.assert_allclose(curve.max_abs[:, k], number(expected, key), rtol=1e-10, err_msg=key)


@pytest.mark.disc
def test_the_gap_response_equals_the_programs(disc):
    out, response = disc
    assert response.curve.end is cyclone.BranchEnd.RANGE_END
    assert_curve_equal(response.curve, program.read_csv(out / "disc_frc.csv"))
    # Traced whole once, as the program's account of its disc_frc says (program.retraces).
    assert program.assert_retraces_equal(response.curve, out, "disc_frc") == (("predictor_corrector", False, 1, ()), True)


@pytest.mark.disc
def test_a_clearance_study_equals_the_programs(disc):
    out, response = disc
    study = cyclone.disc.study(response, "clearance", CLEARANCES)
    table = program.read_csv(out / "study_clearance.csv")
    np.testing.assert_array_equal(study.values, number(table, "clearance"))
    np.testing.assert_allclose(study.peak_hz, number(table, "peak_hz"), rtol=1e-9)
    np.testing.assert_allclose(study.peak, number(table, "peak_max_abs"), rtol=1e-9)
    for i, curve in enumerate(study.curves):
        assert_curve_equal(curve, program.read_csv(out / f"study_clearance_{i}.csv"))
    # The clearance changes the answer: the two values' peaks differ (the gap closes or not).
    assert abs(study.peak[1] / study.peak[0] - 1) > 1e-6


@pytest.mark.disc
def test_a_gap_without_pairs_is_refused(disc):
    _, response = disc
    sector = cyclone.disc.shrouded_sector(mesh_size=12.0)
    with pytest.raises(cyclone.InputError, match="gap/pairs"):
        cyclone.disc.forced_response(sector, response._models, engine_order=3, harmonics=[0, 1], gap={"pairs": []})
    with pytest.raises(cyclone.InputError, match="gap"):
        cyclone.disc.forced_response(sector, response._models, engine_order=3, harmonics=[0, 1],
                                     gap={"pairs": [0], "clearence": 0.1})
