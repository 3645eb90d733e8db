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
(frc.csv) and its stop reason (report.md)."""

import re
import subprocess

import numpy as np
import pytest

import cyclone
import program

SCENE_SAMPLES = {5: 128, 3: 64}  # the scenes' default with a unilateral spring, and Python's
ENGINES = {"LOCA": "loca", "the predictor-corrector": "predictor_corrector"}  # the log's names

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
      k: 1000.0
      gap: 0.5
  excitation:
    force: {{dof: 0, harmonic: 1, cos: 0.1}}
  harmonics: [{harmonics}]
  continuation:
    parameter: force_scale
    omega: 1.0
    from: 0.01
    to: 1.0
{engine}{steps}"""

STEPS = "    initial_step: 0.2\n    min_step: 0.2\n    max_step: 0.2\n"


def python_curve(engine, steps, harmonics):
    system = cyclone.HarmonicBalance(M=[[1.0]], K=[[1.0]], C=[[0.02]], harmonics=harmonics)
    system.add_element(cyclone.UnilateralSpring(k=1000.0, gap=0.5), dofs=[0], name="stop")
    system.add_excitation(dof=0, harmonic=1, cos=0.1)
    assert system.samples == SCENE_SAMPLES[harmonics]
    step_options = dict(initial_step=0.2, min_step=0.2, max_step=0.2) if steps else {}
    return system.forced_response(0.01, 1.0, parameter="force_scale", omega=1.0, engine=engine, **step_options)


def program_retraces(cyclone_program, out, engine, steps, harmonics):
    """The program's account of the same trace: ((engine, other_engine_tried, samples_factor,
    samples_factors_tried), whole, frc.csv, report.md's text): the engine that traced the
    curve again where its log says so and the written curve covers the range, else the
    scene's; the factors its log says the samples were raised by; the written curve's
    samples over the scene's (its log's first line); whether the written curve covers the
    range (the log's warning where not)."""
    scene = SCENE.format(harmonics=harmonics, engine=f"    engine: {engine}\n" if engine else "",
                         steps=STEPS if steps else "")
    path = out.with_suffix(".yaml")
    path.write_text(scene)
    run = subprocess.run([str(cyclone_program), "run", str(path), "--output", str(out)], check=True,
                         capture_output=True, text=True, env={"OPENBLAS_NUM_THREADS": "1", "PATH": "/usr/bin:/bin"})
    log = run.stdout + run.stderr
    samples = int(re.search(rf"harmonics up to {harmonics}, (\d+) samples", log)[1])
    assert samples == SCENE_SAMPLES[harmonics]
    raised = [int(n) for n in re.findall(rf"incomplete with {samples} AFT samples; traced again with (\d+)", log)]
    assert all(n % samples == 0 for n in raised)
    other = re.findall(r"left the curve incomplete \(.*\); traced again with (LOCA|the predictor-corrector)\n", log)
    written = program.h5_attribute(out / "frc.h5", "samples")
    csv = program.read_csv(out / "frc.csv")
    # Its warning where the curve it wrote does not cover the range (two sweeps may each
    # reach an end of it and not meet).
    whole = "frc: the curve is incomplete" not in log
    kept = ENGINES[other[-1]] if other and whole and written == samples else engine or "predictor_corrector"
    retraces = (kept, bool(other), written // samples, tuple(n // samples for n in raised))
    return retraces, whole, csv, (out / "report.md").read_text()


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
    reference, whole, csv, report = program_retraces(cyclone_program, tmp_path / "out", engine, steps, harmonics)
    assert (reference, whole) == (expected, expected_whole)
    curve = python_curve(engine, steps, harmonics)
    r = curve.retraces
    assert isinstance(r, cyclone.Retraces) and isinstance(r.engine, cyclone.ContinuationEngine)
    assert (r.engine.value, r.other_engine_tried, r.samples_factor, r.samples_factors_tried) == reference
    assert curve.finished == whole
    assert curve.stop_reason in report  # the program's summary of its curve, word for word
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
