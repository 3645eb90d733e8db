"""A curve's retraces (ForcedResponse.retraces, continuation::Branch::retraces) from Python
against the cyclone program on the same scene: a mass on a spring with a stiff stop (a
unilateral spring k = 1000 at a gap of 0.5, the scenes' samples: 128 at H = 5, 64 at
H = 3) traced in the force's scale at W = 1. With steps held at 0.2 (min_step = max_step)
both of the predictor-corrector's sweeps stop at the grazing force, one from each side:
alone at H = 5 it is traced again with twice and four times the AFT samples, incomplete
each time; at H = 3 it is traced again with twice the samples (128) and that trace
completes it (the sweep from the end passes the grazing force), so the curve kept is the
retrace's; with LOCA as its fallback (the default) LOCA traces it whole. With the default
steps it is traced whole once. The reference is the program's own account, not the
retraces record: the lines it logs as it starts each retrace ("the predictor-corrector
left the curve incomplete (...); traced again with LOCA", "incomplete with 64 AFT
samples; traced again with 128"), the scene's samples in its first line, the AFT samples
of the curve it wrote (frc.h5's samples attribute, read by h5dump), whether that curve
covers the range (its warning "frc: the curve is incomplete" where not), its points
(frc.csv) and its stop reason (report.md). A curve with no start, which the program refuses
to write, from Python a curve of no points with the program's stop reason."""

import re
import subprocess

import numpy as np
import pytest

import cyclone
import program

SCENE_SAMPLES = {5: 128, 3: 64}  # the scenes' default with a unilateral spring, and Python's

SCENE = """cyclone:
  analysis: forced_response
  system:
    dofs: 1
    M: [1.0]
    C: [0.02]
    K: [1.0]
  nonlinear_elements:
    stop:
      type: unilateral
      direction: [1.0]
      k: {k}
      gap: {gap}
  excitation:
    force: {{dof: 0, harmonic: 1, cos: {cos}}}
  harmonics: [{harmonics}]
  continuation:
{continuation}"""

FORCE_SCALE = "    parameter: force_scale\n    omega: 1.0\n    from: 0.01\n    to: 1.0\n"

STEPS = "    initial_step: 0.2\n    min_step: 0.2\n    max_step: 0.2\n"


def python_curve(engine, steps, harmonics):
    system = cyclone.HarmonicBalance(M=[[1.0]], K=[[1.0]], C=[[0.02]], harmonics=harmonics)
    system.add_element(cyclone.UnilateralSpring(k=1000.0, gap=0.5), dofs=[0], name="stop")
    system.add_excitation(dof=0, harmonic=1, cos=0.1)
    assert system.samples == SCENE_SAMPLES[harmonics]
    step_options = dict(initial_step=0.2, min_step=0.2, max_step=0.2) if steps else {}
    return system.forced_response(0.01, 1.0, parameter="force_scale", omega=1.0, engine=engine, **step_options)


def program_retraces(cyclone_program, out, engine, steps, harmonics):
    """The program's account of the same trace (program.retraces), its CSV and its samples."""
    scene = SCENE.format(k=1000.0, gap=0.5, cos=0.1, harmonics=harmonics,
                         continuation=FORCE_SCALE + (f"    engine: {engine}\n" if engine else "") + (STEPS if steps else ""))
    program.run(cyclone_program, scene, out)
    retraces, whole, _, _ = program.retraces(out, "frc", engine)
    log = out.with_suffix(".log").read_text()
    assert f"harmonics up to {harmonics}, {SCENE_SAMPLES[harmonics]} samples" in log
    return retraces, whole, program.read_csv(out / "frc.csv")


# (engine, steps held at 0.2, H, the retraces expected of the program's account and whether
# its curve covers the range: the scene does what the case is about)
CASES = [
    ("predictor_corrector", True, 5, ("predictor_corrector", False, 1, (2, 4)), False),
    ("predictor_corrector", True, 3, ("predictor_corrector", False, 2, (2,)), True),
    (None, True, 5, ("loca", True, 1, ()), True),
    ("predictor_corrector", False, 5, ("predictor_corrector", False, 1, ()), True),
]


@pytest.mark.parametrize("engine, steps, harmonics, expected, expected_whole", CASES,
                         ids=["more_samples", "more_samples_complete", "other_engine", "traced_once"])
def test_a_curves_retraces_are_the_programs(cyclone_program, tmp_path, engine, steps, harmonics, expected,
                                            expected_whole):
    out = tmp_path / "out"
    reference, whole, csv = program_retraces(cyclone_program, out, engine, steps, harmonics)
    assert (reference, whole) == (expected, expected_whole)
    curve = python_curve(engine, steps, harmonics)
    r = curve.retraces
    assert isinstance(r, cyclone.Retraces) and isinstance(r.engine, cyclone.ContinuationEngine)
    assert program.assert_retraces_equal(curve, out, "frc", engine) == (reference, whole)
    if reference[2] > 1:
        # The curve kept is the retrace's: every point the program wrote (its CSV's 12 digits),
        # traced with the samples it wrote.
        assert curve.end is cyclone.BranchEnd.MET_FROM_THE_END
        assert f"(with {reference[2] * SCENE_SAMPLES[harmonics]} AFT samples" in curve.stop_reason
        np.testing.assert_allclose(curve.parameter, csv["force_scale"].astype(float), rtol=1e-10)
        np.testing.assert_allclose(curve.max_abs[:, 0], csv["dof0_max"].astype(float), rtol=1e-10, atol=1e-14)
        np.testing.assert_array_equal(curve.segment, csv["segment"].astype(int))
    if reference == ("predictor_corrector", False, 1, ()):  # traced once: the record's defaults
        assert r == cyclone.Retraces(cyclone.ContinuationEngine.PREDICTOR_CORRECTOR, False, 1, ())
    with pytest.raises(AttributeError):  # frozen
        r.samples_factor = 2


def test_every_engine_has_its_name():
    assert {engine.value for engine in cyclone.ContinuationEngine} == set(cyclone._core.engine_names)


# A curve with no start: a stop of k = 1e9 shut at rest (gap 0), forced hard, solved to
# 1e-14: neither engine converges a first point at either end of the range.
NO_START = SCENE.format(k=1.0e9, gap=0.0, cos=1.0, harmonics=5,
                        continuation="    from: 0.5\n    to: 1.5\n    tolerance: 1.0e-14\n    max_points: 20\n")


def test_a_curve_without_a_start_is_the_programs(cyclone_program, tmp_path):
    """The program writes nothing for a curve of no points and says why (exit 1); from
    Python the same trace is a ForcedResponse of no points, its arrays empty in their
    shapes, its stop reason the program's word for word, its retraces the program's log's
    (LOCA tried after the predictor-corrector; no more samples: nothing was traced)."""
    out = tmp_path / "out"
    path = out.with_suffix(".yaml")
    path.write_text(NO_START)
    run = subprocess.run([str(cyclone_program), "run", str(path), "--output", str(out)], capture_output=True, text=True,
                         env={"OPENBLAS_NUM_THREADS": "1", "PATH": "/usr/bin:/bin"})
    log = run.stdout + run.stderr
    assert run.returncode == 1, log
    stop_reason = re.search(r"frc: no point of the curve was computed, so nothing was written: (.*)$", log, re.M)[1]
    other = re.findall(r"left the curve incomplete \(.*\); traced again with (LOCA|the predictor-corrector)\n", log)
    assert other == ["LOCA"] and "AFT samples; traced again" not in log

    system = cyclone.HarmonicBalance(M=[[1.0]], K=[[1.0]], C=[[0.02]], harmonics=5)
    system.add_element(cyclone.UnilateralSpring(k=1e9, gap=0.0), dofs=[0], name="stop")
    system.add_excitation(dof=0, harmonic=1, cos=1.0)
    curve = system.forced_response(0.5, 1.5, tolerance=1e-14, max_points=20)
    assert len(curve) == 0 and curve.end is cyclone.BranchEnd.NO_START and not curve.finished
    assert curve.stop_reason == stop_reason
    assert curve.retraces == cyclone.Retraces(cyclone.ContinuationEngine.PREDICTOR_CORRECTOR, True, 1, ())
    assert curve.peak is None
    assert (curve.x.shape, curve.coefficients.shape, curve.amplitude.shape, curve.max_abs.shape) == (
        (0, 11), (0, 1, 11), (0, 1, 6), (0, 1))
    assert curve.amplitude_of(0, 1).shape == (0,)
