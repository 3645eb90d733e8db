"""The cyclone program run on a scene in a test, and its CSV files read back: the
reference the Python API must equal on the same problem."""

import csv
import pathlib
import re
import subprocess

import numpy as np

# The built-in sector as the disc tests' scenes give it (mesh size 12: seconds).
SECTOR = """  mesh:
    source: shrouded_sector
    shrouded_sector: {mesh_size: 12.0}
  material: {E: 1.16e5, nu: 0.34, rho: 4.507e-9}
  constraints: {fixed_node_sets: [bore]}
"""


def run(program, scene, out):
    """Runs `scene` (a path, or YAML text written to out.yaml) with its products in `out` and
    its log (standard output and error) in out.log."""
    out = pathlib.Path(out)
    if isinstance(scene, str):
        path = out.with_suffix(".yaml")
        path.write_text(scene)
        scene = path
    done = subprocess.run([str(program), "run", str(scene), "--output", str(out)], check=True, capture_output=True,
                          text=True, env={"OPENBLAS_NUM_THREADS": "1", "PATH": "/usr/bin:/bin"})
    out.with_suffix(".log").write_text(done.stdout + done.stderr)
    return out


ENGINES = {"LOCA": "loca", "the predictor-corrector": "predictor_corrector"}  # the log's names


def retraces(out, curve, engine=None):
    """The program's own account of how it traced its curve `curve` (frc, disc_frc) in `out`
    (run's products), not its retraces record: ((engine, other_engine_tried, samples_factor,
    samples_factors_tried), whole, stop_reason, points). The lines its log says as it starts
    each retrace ("the predictor-corrector left the curve incomplete (...); traced again with
    LOCA", "incomplete with 64 AFT samples; traced again with 128"); the scene's samples (its
    first forced-response line); the AFT samples of the curve it wrote (<curve>.h5's samples
    attribute) over those; whether that curve covers the range (its warning "<curve>: the
    curve is incomplete" where not); the engine: the other one where the log says it traced
    the curve again and the written curve is whole with the scene's samples, else the scene's
    `engine` (None: the predictor-corrector); the stop reason and points of report.md's line."""
    log = out.with_suffix(".log").read_text()
    samples = int(re.search(r"forced response: .*harmonics up to \d+, (\d+) samples", log)[1])
    raised = [int(n) for n in re.findall(rf"incomplete with {samples} AFT samples; traced again with (\d+)", log)]
    assert all(n % samples == 0 for n in raised)
    other = re.findall(r"left the curve incomplete \(.*\); traced again with (LOCA|the predictor-corrector)\n", log)
    written = h5_attribute(out / f"{curve}.h5", "samples")
    whole = f"{curve}: the curve is incomplete" not in log
    kept = ENGINES[other[-1]] if other and whole and written == samples else engine or "predictor_corrector"
    line = re.search(rf"^- {curve}: (\d+) points .*? in [0-9.e+-]+ s, (.*)$", (out / "report.md").read_text(), re.M)
    return (kept, bool(other), written // samples, tuple(n // samples for n in raised)), whole, line[2], int(line[1])


def h5_attribute(path, name):
    """An integer attribute of an HDF5 file's root group, read by h5dump (Debian hdf5-tools,
    scripts/debian-packages.txt; h5py is not among the project's packages)."""
    text = subprocess.run(["h5dump", "-a", name, str(path)], check=True, capture_output=True, text=True).stdout
    return int(re.search(r"\(0\): (-?\d+)", text)[1])


def read_csv(path):
    """{column: array of its texts}; .astype(float) where numbers."""
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {key: np.array([row[key] for row in rows]) for key in rows[0]}


# The disc the disc tests run by the program and from Python: the sector above at
# 10 000 rpm, engine order 3, harmonics 0..1 checked with 2, 20 kN preload over the
# shroud face, 20 N at mid-blade; Ti-6Al-4V for the margin.
DISC_SCENE = """cyclone:
  analysis: [disc_response]
""" + SECTOR.replace("rho: 4.507e-9}", "rho: 4.507e-9, fatigue: {data: Ti-6Al-4V}}") + """  loads: {speed_rpm: 10000.0}
  reduced_model: {check_frequencies: 0}
  disc_response:
    engine_order: 3
    harmonics: [0, 1]
    harmonics_check_to: 2
    contact: {preload: 20000.0}
    excitation: {amplitude: 20.0}
"""


def disc_response(out, stability="auto", **continuation):
    """DISC_SCENE's response from Python, on the reduced models the program wrote in `out`
    (the same inputs, so their files: none built again); `stability` and `continuation`
    (engine, tolerance, steps) as the scene's."""
    import cyclone

    sector = cyclone.disc.shrouded_sector(mesh_size=12.0)
    nds = cyclone.disc.nodal_diameters_for(sector.sectors, engine_order=3, harmonics=[0, 1, 2])
    models = cyclone.disc.reduced_models(sector, rpm=10000.0, nodal_diameters=nds, cache_directory=out / "reduced_models")
    assert (models.reused, models.built) == (3, 0)
    return cyclone.disc.forced_response(sector, models, engine_order=3, harmonics=[0, 1], preload=20000.0,
                                        amplitude=20.0, harmonics_check_to=2, stability=stability, **continuation)


def assert_peaks_equal(peaks, path, parameter):
    """A followed peak as the program's peak_<parameter>.csv: every value's parameter, peak
    frequency, peak and force_beyond_h to its 10 significant digits, the jumps and the optimum."""
    expected = read_csv(path)
    assert len(peaks) == len(expected[parameter])
    number = lambda key: expected[key].astype(float)  # noqa: E731
    np.testing.assert_allclose(peaks.parameter, number(parameter), rtol=1e-9)
    np.testing.assert_allclose(peaks.hz, number("peak_hz"), rtol=1e-9)
    np.testing.assert_allclose(peaks.peak, number("peak_max_abs"), rtol=1e-9)
    np.testing.assert_array_equal(peaks.jump.astype(int), expected["jump"].astype(int))
    optimum = np.flatnonzero(expected["optimum"].astype(int))
    assert peaks.optimum == (int(optimum[0]) if len(optimum) else None)
    beyond = np.array([float(v) if v else -1.0 for v in expected["force_beyond_h"]])
    np.testing.assert_allclose(peaks.force_beyond, beyond, rtol=1e-9)


def assert_retraces_equal(curve, out, name, engine=None):
    """A curve's retraces, end and stop reason from Python as the program's account of its
    curve `name` in `out` (retraces); returns that account."""
    reference, whole, stop_reason, points = retraces(out, name, engine)
    r = curve.retraces
    assert (r.engine.value, r.other_engine_tried, r.samples_factor, r.samples_factors_tried) == reference
    assert curve.finished == whole
    # report.md's line, word for word (the count of its flags after it)
    assert stop_reason == curve.stop_reason or stop_reason.startswith(curve.stop_reason + "; ")
    assert len(curve) == points
    return reference, whole


def assert_curve_equal(curve, expected, names):
    """Every point of a matrix system's `curve` as the program's frc.csv (`expected`, read_csv):
    the frequency, and per output DOF (names[k], the CSV's name of curve.output_dofs[k]) the
    mean, the amplitude of every harmonic above 0 and max |x(t)|, to 1e-10 (the CSV's 12
    significant digits; the mean and amplitudes against the DOF's largest max |x(t)|); Hill's
    verdicts and the flags equal."""
    assert len(curve) == len(expected["omega_rad_s"]) > 20
    number = lambda key: expected[key].astype(float)  # noqa: E731
    np.testing.assert_allclose(curve.omega, number("omega_rad_s"), rtol=1e-10, atol=0)
    for k, (dof, name) in enumerate(zip(curve.output_dofs, names)):
        scale = number(f"{name}_max").max()
        np.testing.assert_allclose(curve.mean(dof), number(f"{name}_h0"), rtol=0, atol=1e-10 * scale)
        for h in (h for h in curve.harmonics if h > 0):
            np.testing.assert_allclose(curve.amplitude_of(dof, h), number(f"{name}_amp_h{h}"), rtol=0,
                                       atol=1e-10 * scale, err_msg=f"{name}, harmonic {h}")
        np.testing.assert_allclose(curve.max_abs[:, k], number(f"{name}_max"), rtol=1e-10, atol=0)
    np.testing.assert_array_equal(curve.stable, expected["stable"].astype(int))
    np.testing.assert_array_equal(curve.flags, expected["bifurcation"])


def assert_whole_curve_is_the_programs(curve, cyclone_program, scene, out, names):
    """Runs `scene` into `out`; `curve`, the same system's from Python, traced whole once as
    the program says it traced its own (assert_retraces_equal) and equal to its frc.csv point
    for point (assert_curve_equal). Returns that CSV."""
    expected = read_csv(run(cyclone_program, scene, out) / "frc.csv")
    assert curve.end.value == "range_end"
    assert_curve_equal(curve, expected, names)
    assert assert_retraces_equal(curve, out, "frc") == (("predictor_corrector", False, 1, ()), True)
    return expected
