"""The cyclone program run on a scene in a test, and its CSV files read back: the
reference the Python API must equal on the same problem."""

import csv
import pathlib
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


def read_csv(path):
    """{column: array of its texts}; .astype(float) where numbers."""
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {key: np.array([row[key] for row in rows]) for key in rows[0]}
