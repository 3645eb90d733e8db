"""harmonics="auto" and the time-domain check from Python against the cyclone program on
the same disc (program.DISC_SCENE's: the built-in sector at mesh size 12, 10 000 rpm, engine
order 3, a 20 kN preload, 20 N at mid-blade) with `harmonics: auto, harmonics_max: 3` and
`time_domain_check: {periods: 100}`, stability not computed (Hill's method on the H = 3
curve alone would double the time). The program runs the scene once and builds the five
models (ND 0, 3, 6, 9 of harmonics 0..3, and 12: the time domain's ring of 8 sectors
reaches every multiple of 3); Python reuses them and makes the same call. The curve starts
with H = 1, the check raises H to 3 (3.1 % from H 1 to 2, 1.4 % from 2 to 3: the 1 % target
not met), and the curve is traced again with H = 3: the headline and the retraced curve equal the program's
(disc_frc_harmonics.csv, disc_frc.csv: every harmonic of every output DOF to 1e-10 of its
largest max |x(t)|), the time domain's amplitude per period equals disc_peak_in_time.csv
(its 10 digits), and the summary's lines are the program's. About 19 s for the program,
13 s for Python (measured: the curve to 5e-12, the headline 2e-10, the time domain 2e-10)."""

import re

import numpy as np
import pytest

import cyclone
import program

SCENE = program.DISC_SCENE.replace("    harmonics: [0, 1]\n    harmonics_check_to: 2\n",
                                   "    harmonics: auto\n    harmonics_max: 3\n    stability: false\n"
                                   "    time_domain_check: {periods: 100}\n")


def disc_inputs(out):
    sector = cyclone.disc.shrouded_sector(mesh_size=12.0)
    nds = cyclone.disc.nodal_diameters_for(sector.sectors, engine_order=3, harmonics=range(5))
    models = cyclone.disc.reduced_models(sector, rpm=10000.0, nodal_diameters=nds,
                                         cache_directory=out / "reduced_models")
    assert (models.reused, models.built) == (5, 0)  # the program's files
    return sector, models


@pytest.fixture(scope="module")
def program_out(cyclone_program, tmp_path_factory):
    assert "harmonics: auto" in SCENE
    return program.run(cyclone_program, SCENE, tmp_path_factory.mktemp("disc_auto") / "out")


@pytest.fixture(scope="module")
def python_response(program_out):
    sector, models = disc_inputs(program_out)
    return cyclone.disc.forced_response(sector, models, engine_order=3, harmonics="auto", harmonics_max=3,
                                        preload=20000.0, amplitude=20.0, stability=False,
                                        time_domain_check={"periods": 100})


def summary_lines(out):
    """The program's summary (its log's lines after "summary (...)", two spaces in)."""
    log = out.with_suffix(".log").read_text()
    summary = log[log.index("\nsummary ("):log.index("\nwritten:")]
    return [line[2:] for line in summary.splitlines()[2:]]


def without_seconds(text):
    """A summary line with its timings ("9 s", "3.62 s") taken out: the runs' own."""
    return re.sub(r"\b[0-9.]+ s\b", "<t> s", text)


@pytest.mark.disc
def test_harmonics_auto_retraces_the_programs_curve(program_out, python_response):
    response = python_response
    levels = program.read_csv(program_out / "disc_frc_harmonics.csv")
    top = levels["max_harmonic"].astype(int).argmax()
    # The headline: the check's highest level, H = 3, an estimate (the target not met).
    assert response.headline.max_harmonic == int(levels["max_harmonic"][top]) == 3
    assert response.headline.convergence is cyclone.disc.Convergence.ESTIMATE
    assert abs(response.headline.value / float(levels["peak_max_abs_dof0"][top]) - 1) < 1e-9
    assert abs(response.headline.hz / float(levels["freq_hz"][top]) - 1) < 1e-9
    lines = summary_lines(program_out)
    assert lines[0] == response.headline.text
    assert "harmonics: auto" in response.headline.text
    # What the target came to: traced with H = 1, not met by H = 3, traced again with H = 3.
    target = response.harmonics_target
    assert (target.tolerance, target.traced_harmonic, target.reached, target.change, target.retraced) == (
        0.01, 1, -1, -1.0, True)
    assert target.retrace_seconds > 0
    assert without_seconds(target.text) in [without_seconds(line) for line in lines]
    # The curve returned is the retraced one, point for point the program's disc_frc.csv.
    curve = response.curve
    assert list(curve.harmonics) == [0, 1, 2, 3]
    expected = program.read_csv(program_out / "disc_frc.csv")
    assert len(curve) == len(expected["omega_rad_s"]) > 50
    np.testing.assert_allclose(curve.omega, expected["omega_rad_s"].astype(float), rtol=1e-10, atol=0)
    names = [key[:-len("_max")] for key in expected if key.endswith("_max")]
    assert len(names) == len(curve.output_dofs) == 3  # mid-blade z, x, y
    for k, (dof, name) in enumerate(zip(curve.output_dofs, names)):
        scale = expected[f"{name}_max"].astype(float).max()
        np.testing.assert_allclose(curve.mean(dof), expected[f"{name}_h0"].astype(float), rtol=0, atol=1e-10 * scale)
        for h in range(1, 4):
            np.testing.assert_allclose(curve.amplitude_of(dof, h), expected[f"{name}_amp_h{h}"].astype(float), rtol=0,
                                       atol=1e-10 * scale, err_msg=f"{name}, harmonic {h}")
        np.testing.assert_allclose(curve.max_abs[:, k], expected[f"{name}_max"].astype(float), rtol=1e-10, atol=0)
    assert (expected["stable"] == "").all() and (curve.stable == -1).all()  # stability: false
    # Traced whole once by the predictor-corrector with the scene's 256 samples, and so from Python.
    assert program.assert_retraces_equal(curve, program_out, "disc_frc") == (
        ("predictor_corrector", False, 1, ()), True)


@pytest.mark.disc
def test_the_time_domain_check_is_the_programs(program_out, python_response):
    check = python_response.time_domain_check
    expected = program.read_csv(program_out / "disc_peak_in_time.csv")
    np.testing.assert_array_equal(expected["period"].astype(int), np.arange(1, check.periods + 1))
    assert isinstance(check.amplitude_history, np.ndarray) and len(check.amplitude_history) == check.periods
    np.testing.assert_allclose(check.amplitude_history, expected["amplitude_mm"].astype(float), rtol=1e-9, atol=0)
    # The summary's second line, word for word but its time.
    assert without_seconds(summary_lines(program_out)[1]) == without_seconds(check.text)
    # At the retraced curve's largest point, from its state; 100 periods of 1024 steps on the
    # ring of 8 sectors (EO 3 on 24), not steady there: the range over the last 50.
    assert abs(check.hz / python_response.headline.hz - 1) < 1e-3
    assert abs(check.harmonic_balance / python_response.curve.peak.value - 1) < 1e-6
    assert (check.periods, check.steps_per_period, check.sectors) == (100, 1024, 8)
    assert check.ending is cyclone.disc.TimeDomainEnding.NOT_STEADY and check.ending == "not_steady"
    assert not check.steady
    last_half = check.amplitude_history[50:]
    assert (check.largest, check.smallest) == (last_half.max(), last_half.min())
    assert check.last_amplitude == check.amplitude_history[-1]
    assert check.seconds > 0
    with pytest.raises(AttributeError):  # frozen
        check.largest = 0.0


# Python's arguments as the scene's keys (SceneReaders.cpp: readHarmonicsTarget,
# readHarmonicsCheckTo; DiscSweepReaders.cpp: time_domain_check): each refused before any
# solve, naming the argument as the scene names its key under disc_response.
REFUSALS = [
    (dict(harmonics="auto", harmonics_tolerance=0.0), "harmonics_tolerance"),
    (dict(harmonics="auto", harmonics_tolerance=0.5), "harmonics_tolerance"),
    (dict(harmonics="auto", harmonics_tolerance=float("nan")), "harmonics_tolerance"),
    (dict(harmonics="auto", harmonics_max=2), "harmonics_max"),
    (dict(harmonics="auto", harmonics_max=65), "harmonics_max"),
    (dict(harmonics="auto", harmonics_max=3.5), "harmonics_max"),
    (dict(harmonics="auto", harmonics_check_to=4), "harmonics_check_to"),
    (dict(harmonics="automatic"), "harmonics"),
    (dict(harmonics=[0, 1], harmonics_max=4), "harmonics_max"),
    (dict(harmonics=3, harmonics_tolerance=0.01), "harmonics_tolerance"),
    (dict(time_domain_check={"periods": 99}), "time_domain_check/periods"),
    (dict(time_domain_check={"periods": 150.5}), "time_domain_check/periods"),
    (dict(time_domain_check={"steps_per_period": 15}), "time_domain_check/steps_per_period"),
    # the library's upper limits, before the trace (they were met only after it)
    (dict(time_domain_check={"steps_per_period": 70000}), "time_domain_check/steps_per_period"),
    (dict(time_domain_check={"periods": 100000}), "time_domain_check/periods"),
    (dict(time_domain_check={"period": 100}), "time_domain_check"),
    (dict(time_domain_check=100), "time_domain_check"),
]


@pytest.mark.disc
def test_refusals_name_the_argument(program_out):
    sector, models = disc_inputs(program_out)
    for arguments, key in REFUSALS:
        with pytest.raises(cyclone.InputError) as error:
            cyclone.disc.forced_response(sector, models, engine_order=3, preload=20000.0, amplitude=20.0,
                                         **{"harmonics": [0, 1, 2, 3], **arguments})
        assert error.value.key == key, (arguments, str(error.value))
    # Models without the nodal diameters the keys reach (the scene builds them): refused before
    # the trace, naming them (not a target stopped at H = 1, nor a time domain failed after it).
    fewer = cyclone.disc.reduced_models(sector, rpm=10000.0, nodal_diameters=[0, 3, 6, 9],
                                        cache_directory=program_out / "reduced_models")
    for arguments, missing in [(dict(harmonics="auto", harmonics_max=4), "[12]"),
                               (dict(harmonics=[0, 1], time_domain_check={}), "[12]")]:
        with pytest.raises(cyclone.InputError) as error:
            cyclone.disc.forced_response(sector, fewer, engine_order=3, preload=20000.0, amplitude=20.0, **arguments)
        assert error.value.key == "models" and f"nodal diameter(s) {missing}" in error.value.problem, str(error.value)
