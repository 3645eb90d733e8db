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
    """Runs `scene` (a path, or YAML text written to out.yaml) with its products in `out`."""
    out = pathlib.Path(out)
    if isinstance(scene, str):
        path = out.with_suffix(".yaml")
        path.write_text(scene)
        scene = path
    subprocess.run([str(program), "run", str(scene), "--output", str(out)], check=True, capture_output=True,
                   env={"OPENBLAS_NUM_THREADS": "1", "PATH": "/usr/bin:/bin"})
    return out


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


def disc_response(out, stability="auto"):
    """DISC_SCENE's response from Python, on the reduced models the program wrote in `out`
    (the same inputs, so their files: none built again); `stability` as the scene's."""
    import cyclone

    sector = cyclone.disc.shrouded_sector(mesh_size=12.0)
    nds = cyclone.disc.nodal_diameters_for(sector.sectors, engine_order=3, harmonics=[0, 1, 2])
    models = cyclone.disc.reduced_models(sector, rpm=10000.0, nodal_diameters=nds, cache_directory=out / "reduced_models")
    assert (models.reused, models.built) == (3, 0)
    return cyclone.disc.forced_response(sector, models, engine_order=3, harmonics=[0, 1], preload=20000.0,
                                        amplitude=20.0, harmonics_check_to=2, stability=stability)


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
