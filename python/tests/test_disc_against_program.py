"""The disc chain from Python against the cyclone program on the same disc: the built-in
sector at mesh size 12, 10 000 rpm, engine order 3, harmonics 0..1 checked with 2, a
20 kN preload over the shroud face, 20 N at mid-blade, the peak followed over the preload
from 10 to 40 kN. The program runs the scene once and writes its reduced models; Python
builds the same models' spec, so it reuses the program's three files (their names are
digests of every input), and traces the same curve: every point's frequency and
max |x(t)| to 1e-10, and the headline peak of harmonics 0..2 as the program's (its CSV's
10 digits); then follows the same peak: every value's peak and frequency as the program's
peak_preload.csv (10 digits); and the stresses and fatigue margin at the peak, every node as
the program's disc_peak_stress.csv (8 digits); the curve's retraces, end and stop reason as
the program's account of it (program.retraces). Label scene: about 20 s."""

import shutil

import numpy as np
import pytest

import cyclone
import program

SCENE = program.DISC_SCENE + """    peak_studies:
      preload: {range: [10000.0, 40000.0], values: 4}
    peak_stress: {animation_steps: 8}
"""


@pytest.fixture(scope="module")
def program_out(cyclone_program, tmp_path_factory):
    return program.run(cyclone_program, SCENE, tmp_path_factory.mktemp("disc") / "out")


@pytest.fixture(scope="module")
def python_response(program_out):
    return program.disc_response(program_out)


@pytest.mark.disc
def test_the_disc_response_equals_the_programs(program_out, python_response):
    expected = program.read_csv(program_out / "disc_frc.csv")
    levels = program.read_csv(program_out / "disc_frc_harmonics.csv")
    response = python_response
    curve = response.curve
    assert curve.end is cyclone.BranchEnd.RANGE_END
    assert len(curve) == len(expected["omega_rad_s"]) > 20
    np.testing.assert_allclose(curve.omega, expected["omega_rad_s"].astype(float), rtol=1e-10)
    maxima = [key for key in expected if key.endswith("_max")]
    assert len(maxima) == curve.max_abs.shape[1] == 3  # mid-blade x, y, z
    for k, key in enumerate(maxima):
        np.testing.assert_allclose(curve.max_abs[:, k], expected[key].astype(float), rtol=1e-10)
    np.testing.assert_array_equal(curve.stable, expected["stable"].astype(int))
    top = levels["max_harmonic"].astype(int).argmax()
    assert response.headline.max_harmonic == 2
    assert response.headline.convergence is cyclone.disc.Convergence.ESTIMATE  # 3 % from H 1 to 2: above 1 %
    assert abs(response.headline.value / float(levels["peak_max_abs_dof0"][top]) - 1) < 1e-9
    assert abs(response.headline.hz / float(levels["freq_hz"][top]) - 1) < 1e-9
    # The peak lies between the shroud's free and stuck resonances (the estimate's).
    assert response.estimate["free_hz"] < response.headline.hz < response.estimate["stuck_hz"] * 1.01


@pytest.mark.disc
def test_the_disc_curves_retraces_and_stop_are_the_programs(program_out, python_response):
    # The program's account of its disc_frc (its log's retrace lines, disc_frc.h5's samples,
    # its incomplete-curve warning, report.md's stop reason): traced whole once by the
    # predictor-corrector with the scene's 256 samples, and so from Python.
    reference = program.assert_retraces_equal(python_response.curve, program_out, "disc_frc")
    assert reference == (("predictor_corrector", False, 1, ()), True)
    assert "forced response: 66 DOFs, harmonics up to 1, 256 samples" in program_out.with_suffix(".log").read_text()
    assert python_response.curve.end is cyclone.BranchEnd.RANGE_END


# The scene's disc_response/continuation and the same keys from Python: (its keys, Python's
# arguments, the program's account expected of it: the scene does what the case is about).
CONTINUATIONS = [
    ("{engine: loca}", dict(engine="loca"), (("loca", False, 1, ()), True)),  # LOCA alone, whole
    # Out of points after 10: incomplete, and not traced again (the budget is the caller's).
    ("{max_points: 10}", dict(max_points=10), (("predictor_corrector", False, 1, ()), False)),
]


@pytest.mark.disc
@pytest.mark.parametrize("keys, options, expected", CONTINUATIONS, ids=["loca", "point_budget"])
def test_the_disc_curve_with_the_scenes_continuation_is_the_programs(cyclone_program, program_out, tmp_path, keys,
                                                                      options, expected):
    out = tmp_path / "out"
    shutil.copytree(program_out / "reduced_models", out / "reduced_models")  # reused, not built again
    program.run(cyclone_program, program.DISC_SCENE + f"    stability: false\n    continuation: {keys}\n", out)
    response = program.disc_response(out, stability=False, **options)
    assert program.assert_retraces_equal(response.curve, out, "disc_frc", options.get("engine")) == expected
    expected_curve = program.read_csv(out / "disc_frc.csv")
    np.testing.assert_allclose(response.curve.omega, expected_curve["omega_rad_s"].astype(float), rtol=1e-10)
    maxima = [key for key in expected_curve if key.endswith("_max")]  # mid-blade x, y, z
    for k, key in enumerate(maxima):
        np.testing.assert_allclose(response.curve.max_abs[:, k], expected_curve[key].astype(float), rtol=1e-10)
    assert response.curve.end is (cyclone.BranchEnd.RANGE_END if expected[1] else cyclone.BranchEnd.POINT_BUDGET)


@pytest.mark.disc
def test_the_peak_over_the_preload_equals_the_programs(program_out, python_response):
    peaks = cyclone.disc.follow_peak(python_response, "preload", (10000.0, 40000.0), values=4)
    assert peaks.end is cyclone.PeakFollowingEnd.RANGE_END
    assert peaks.reference_value == 20000.0
    assert len(peaks) >= 5  # 4 values in log and the response's 20 kN
    program.assert_peaks_equal(peaks, program_out / "peak_preload.csv", "preload")
    # At the response's own preload the followed peak is the traced curve's (located on its path).
    at_reference = int(np.flatnonzero(peaks.parameter == 20000.0)[0])
    assert abs(peaks.peak[at_reference] / python_response.curve.peak.value - 1) < 1e-3


@pytest.mark.disc
def test_the_stresses_and_margin_at_the_peak_equal_the_programs(program_out, python_response):
    expected = program.read_csv(program_out / "disc_peak_stress.csv")
    stress = cyclone.disc.peak_stress(python_response, fatigue="Ti-6Al-4V")
    # The CSV lists every node worst first (a stable sort by the safety factor).
    order = np.argsort(stress.safety_factor, kind="stable")
    np.testing.assert_array_equal(stress.node_ids[order], expected["node"].astype(int))
    assert stress.critical == order[0] and stress.critical_node == int(expected["node"][0])
    # Its 8 significant digits; a column's values near zero against the column's largest.
    for column, values in [("x", stress.coordinates[:, 0]), ("y", stress.coordinates[:, 1]),
                           ("z", stress.coordinates[:, 2]), ("mean_vm_signed", stress.mean_von_mises),
                           ("alternating_vm", stress.alternating_von_mises),
                           ("alternating_principal", stress.alternating_principal),
                           ("max_vm", stress.max_von_mises), ("safety_factor", stress.safety_factor)]:
        reference = expected[column].astype(float)
        np.testing.assert_allclose(values[order], reference, rtol=1e-7, atol=1e-7 * abs(reference).max(),
                                   err_msg=column)
    # The margin is the modified Goodman-Haigh diagram's with Ti-6Al-4V's data sheet values
    # (S_u 950, S_y 880, S_e 510 MPa), the mean held: at every node the allowable alternating
    # stress S_e (1 - max(s_m, 0) / S_u), at most S_y - |s_m|, over the alternating stress.
    assert (stress.material["ultimate_strength"], stress.material["yield_strength"],
            stress.material["endurance_limit"]) == (950.0, 880.0, 510.0)
    sm, sa = stress.mean_von_mises, stress.alternating_von_mises
    allowed = np.maximum(np.minimum(510.0 * (1 - np.maximum(sm, 0) / 950.0), 880.0 - abs(sm)), 0)
    moving = sa > 0  # a node without alternating stress has an infinite factor
    assert moving.mean() > 0.9
    np.testing.assert_allclose(stress.safety_factor[moving], allowed[moving] / sa[moving], rtol=1e-12)
    # Strengths the Goodman line cannot have are refused naming the key, before any solve.
    with pytest.raises(cyclone.InputError) as error:
        cyclone.disc.peak_stress(python_response, fatigue={"ultimate_strength": 500.0, "endurance_limit": 600.0})
    assert error.value.key == "fatigue/endurance_limit"
    with pytest.raises(cyclone.InputError) as error:
        cyclone.disc.peak_stress(python_response, fatigue={"ultimate": 500.0})
    assert error.value.key == "fatigue"
