"""The disc's studies from Python against the cyclone program on the same disc (the
sector of test_disc_against_program.py, harmonics 0..1 checked with 2, 20 kN preload,
20 N at mid-blade): the value-list studies over the preload, the harmonics and the
models' modes (every curve's points as the program's study_<name>_<i>.csv, every peak as
study_<name>.csv). Label scene."""

import numpy as np
import pytest

import cyclone
import program

SCENE = program.DISC_SCENE + """    studies:
      preload: [20000.0, 40000.0]
      harmonics: [2]
      modes: [10]
"""


@pytest.fixture(scope="module")
def disc(cyclone_program, tmp_path_factory):
    """The program's products on SCENE, and Python's response on the same disc."""
    out = program.run(cyclone_program, SCENE, tmp_path_factory.mktemp("disc_studies") / "out")
    return out, program.disc_response(out)


def number(table, key):
    return table[key].astype(float)


@pytest.mark.disc
@pytest.mark.parametrize("parameter, values", [("preload", [20000.0, 40000.0]), ("harmonics", [2]),
                                               ("modes", [10])])
def test_a_value_list_study_equals_the_programs(disc, parameter, values):
    program_out, response = disc
    study = cyclone.disc.study(response, parameter, values)
    table = program.read_csv(program_out / f"study_{parameter}.csv")
    np.testing.assert_array_equal(study.values, number(table, parameter))
    # study_<name>.csv's 10 significant digits.
    np.testing.assert_allclose(study.peak_hz, number(table, "peak_hz"), rtol=1e-9)
    np.testing.assert_allclose(study.peak, number(table, "peak_max_abs"), rtol=1e-9)
    np.testing.assert_array_equal(study.points, table["points"].astype(int))
    np.testing.assert_array_equal(study.finished, table["finished"].astype(int).astype(bool))
    for i, curve in enumerate(study.curves):
        expected = program.read_csv(program_out / f"study_{parameter}_{i}.csv")
        np.testing.assert_allclose(curve.omega, number(expected, "omega_rad_s"), rtol=1e-10)
        maxima = [key for key in expected if key.endswith("_max")]
        assert len(maxima) == curve.max_abs.shape[1] == 3
        for k, key in enumerate(maxima):
            np.testing.assert_allclose(curve.max_abs[:, k], number(expected, key), rtol=1e-10, err_msg=key)
    # The response's own value is its curve, not traced again.
    np.testing.assert_array_equal(study.is_reference, study.values == 20000.0 if parameter == "preload" else False)
    if parameter == "harmonics":
        assert study.curves[0].harmonics == [0, 1, 2]


@pytest.mark.disc
def test_a_study_refuses_a_value_before_any_curve(disc):
    _, response = disc
    with pytest.raises(cyclone.InputError) as error:
        cyclone.disc.study(response, "mu", [0.3, -0.1])
    assert error.value.key == "values" and "-0.1" in error.value.problem
    with pytest.raises(cyclone.InputError) as error:
        cyclone.disc.study(response, "speed", [5000.0])
    assert error.value.key == "parameter"
