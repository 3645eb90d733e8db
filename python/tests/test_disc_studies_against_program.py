"""The disc's studies from Python against the cyclone program on the same disc (the
sector of test_disc_against_program.py, harmonics 0..1 checked with 2, 20 kN preload,
20 N at mid-blade): the value-list studies over the preload, the harmonics and the
models' modes (every curve's points as the program's study_<name>_<i>.csv, every peak as
study_<name>.csv), the peak followed over the friction coefficient and the loss factor
by peak searches and over the force by continuation (as peak_<name>.csv), and the
stresses at a chosen frequency (as disc_peak_stress.csv with at_hz); without stability
(test_disc_against_program.py compares it) to keep the test short. The value-list and
peak studies are over different parameters: the program adds a value-list study's values
to the peak following's grid of the same parameter. Label scene."""

import numpy as np
import pytest

import cyclone
import program

AT_HZ = 1550.0  # inside the curve's band (1380..1700 Hz), below the peak's 1563.75 Hz

SCENE = program.DISC_SCENE + """    studies:
      preload: [20000.0, 40000.0]
      harmonics: [2]
      modes: [10]
    stability: false
    peak_studies:
      mu: {range: [0.2, 0.8], values: 3}
      loss_factor: {range: [0.003, 0.012], values: 3}
      force: {range: [0.5, 2.0], method: continuation}
    peak_stress: {animation_steps: 8, at_hz: %s}
""" % AT_HZ


@pytest.fixture(scope="module")
def disc(cyclone_program, tmp_path_factory):
    """The program's products on SCENE, and Python's response on the same disc."""
    out = program.run(cyclone_program, SCENE, tmp_path_factory.mktemp("disc_studies") / "out")
    return out, program.disc_response(out, stability=False)


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


@pytest.mark.disc
@pytest.mark.parametrize("parameter, range, options", [("mu", (0.2, 0.8), dict(values=3)),
                                                       ("loss_factor", (0.003, 0.012), dict(values=3)),
                                                       ("force", (0.5, 2.0), dict(method="continuation"))])
def test_the_peak_followed_equals_the_programs(disc, parameter, range, options):
    program_out, response = disc
    peaks = cyclone.disc.follow_peak(response, parameter, range, **options)
    assert peaks.end is cyclone.PeakFollowingEnd.RANGE_END
    program.assert_peaks_equal(peaks, program_out / f"peak_{parameter}.csv", parameter)


@pytest.mark.disc
def test_the_stresses_at_a_frequency_equal_the_programs(disc):
    program_out, response = disc
    expected = program.read_csv(program_out / "disc_peak_stress.csv")
    stress = cyclone.disc.peak_stress(response, fatigue="Ti-6Al-4V", at_hz=AT_HZ)
    assert stress.hz == pytest.approx(AT_HZ, rel=1e-12)
    order = np.argsort(stress.safety_factor, kind="stable")  # the CSV's: worst first
    np.testing.assert_array_equal(stress.node_ids[order], expected["node"].astype(int))
    # Its 8 significant digits; a column's values near zero against the column's largest.
    for column, values in [("mean_vm_signed", stress.mean_von_mises), ("alternating_vm", stress.alternating_von_mises),
                           ("alternating_principal", stress.alternating_principal),
                           ("max_vm", stress.max_von_mises), ("safety_factor", stress.safety_factor)]:
        reference = number(expected, column)
        np.testing.assert_allclose(values[order], reference, rtol=1e-7, atol=1e-7 * abs(reference).max(),
                                   err_msg=column)
