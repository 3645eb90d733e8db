"""A curve's retraces (ForcedResponse.retraces, continuation::Branch::retraces) from Python
against the cyclone program on the same scene: a mass on a spring with a stiff stop (a
unilateral spring k = 1000 at a gap of 0.5, H = 5, the scenes' 128 samples) traced in the
force's scale at W = 1. With steps held at 0.2 (min_step = max_step) both of the
predictor-corrector's sweeps stop at the grazing force, one from each side: alone it is
traced again with twice and four times the AFT samples, incomplete each time; with LOCA
as its fallback (the default) LOCA traces it whole. With the default steps it is traced
whole once. The reference is the program's own account, not the retraces record: the
lines it logs as it starts each retrace ("the predictor-corrector left the curve
incomplete (...); traced again with LOCA", "incomplete with 128 AFT samples; traced
again with 256"), the AFT samples of the curve it wrote (frc.h5's samples attribute) and
whether that curve covers the range (frc.csv)."""

import re
import subprocess

import numpy as np
import pytest

import cyclone
import program

h5py = pytest.importorskip("h5py")

SAMPLES = 128  # the scenes' default for H = 5 with a unilateral spring, and Python's
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
  harmonics: [5]
  continuation:
    parameter: force_scale
    omega: 1.0
    from: 0.01
    to: 1.0
{engine}{steps}"""

STEPS = "    initial_step: 0.2\n    min_step: 0.2\n    max_step: 0.2\n"


def python_curve(engine, steps):
    system = cyclone.HarmonicBalance(M=[[1.0]], K=[[1.0]], C=[[0.02]], harmonics=5)
    system.add_element(cyclone.UnilateralSpring(k=1000.0, gap=0.5), dofs=[0], name="stop")
    system.add_excitation(dof=0, harmonic=1, cos=0.1)
    step_options = dict(initial_step=0.2, min_step=0.2, max_step=0.2) if steps else {}
    return system.forced_response(0.01, 1.0, parameter="force_scale", omega=1.0, engine=engine, **step_options)


def program_retraces(cyclone_program, out, engine, steps):
    """The program's account of the same trace, as (engine, other_engine_tried, samples_factor,
    samples_factors_tried): the engine that traced the curve again where its log says so and
    the written curve covers the range, else the scene's; the factors its log says the samples
    were raised by; the written curve's samples over the scene's."""
    scene = SCENE.format(engine=f"    engine: {engine}\n" if engine else "", steps=STEPS if steps else "")
    path = out.with_suffix(".yaml")
    path.write_text(scene)
    log = subprocess.run([str(cyclone_program), "run", str(path), "--output", str(out)], check=True,
                         capture_output=True, text=True,
                         env={"OPENBLAS_NUM_THREADS": "1", "PATH": "/usr/bin:/bin"}).stdout
    raised = [int(m[1]) for m in re.findall(r"incomplete with (\d+) AFT samples; traced again with (\d+)", log)]
    assert all(n % SAMPLES == 0 for n in raised)
    other = re.findall(r"left the curve incomplete \(.*\); traced again with (LOCA|the predictor-corrector)\n", log)
    with h5py.File(out / "frc.h5", "r") as f:
        written = int(f.attrs["samples"])
    scale = program.read_csv(out / "frc.csv")["force_scale"].astype(float)
    whole = np.isclose(scale.min(), 0.01, rtol=1e-9) and np.isclose(scale.max(), 1.0, rtol=1e-9)
    kept = ENGINES[other[-1]] if other and whole and written == SAMPLES else engine or "predictor_corrector"
    return kept, bool(other), written // SAMPLES, tuple(n // SAMPLES for n in raised)


# (engine, steps held at 0.2, the retraces expected of the program's account: the scene
# does what the case is about)
CASES = [
    ("predictor_corrector", True, ("predictor_corrector", False, 1, (2, 4))),
    (None, True, ("loca", True, 1, ())),
    ("predictor_corrector", False, ("predictor_corrector", False, 1, ())),
]


@pytest.mark.parametrize("engine, steps, expected", CASES, ids=["more_samples", "other_engine", "traced_once"])
def test_a_curves_retraces_are_the_programs(cyclone_program, tmp_path, engine, steps, expected):
    reference = program_retraces(cyclone_program, tmp_path / "out", engine, steps)
    assert reference == expected
    curve = python_curve(engine, steps)
    r = curve.retraces
    assert isinstance(r, cyclone.Retraces) and isinstance(r.engine, cyclone.ContinuationEngine)
    assert (r.engine.value, r.other_engine_tried, r.samples_factor, r.samples_factors_tried) == reference
    assert curve.finished == (reference[3] == ())  # retraced with more samples: incomplete each time
    if reference == ("predictor_corrector", False, 1, ()):  # traced once: the record's defaults
        assert r == cyclone.Retraces(cyclone.ContinuationEngine.PREDICTOR_CORRECTOR, False, 1, ())
    with pytest.raises(AttributeError):  # frozen
        r.samples_factor = 2


def test_every_engine_has_its_name():
    assert {engine.value for engine in cyclone.ContinuationEngine} == set(cyclone._core.engine_names)
