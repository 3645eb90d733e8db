"""The Python package's overhead on the disc chain's long calls (issue 52: at most 5 %):
each call's wall time from Python against the time of the library's call inside it, timed
by the binding around the very C++ call a C++ program makes (DiscResponse.library_seconds,
ModalSweep.library_seconds). The rest is the Python layer: argument checks, the specs, the
results turned into numpy arrays. Three runs each, on one core:

    OPENBLAS_NUM_THREADS=1 PYTHONPATH=build/python python3 docs/studies/python_overhead.py
"""

import tempfile
import time

import cyclone


def timed(call):
    start = time.perf_counter()
    result = call()
    return time.perf_counter() - start, result


sector = cyclone.disc.shrouded_sector(mesh_size=12.0)
rows = []
for _ in range(3):
    wall, modes = timed(lambda: cyclone.disc.modal_sweep(sector, speeds_rpm=[0.0, 10000.0], modes_per_nd=3,
                                                         threads=1))
    rows.append(("modal sweep (13 ND, 2 speeds, 3 modes)", wall, modes.library_seconds))
with tempfile.TemporaryDirectory() as cache:
    nds = cyclone.disc.nodal_diameters_for(sector.sectors, engine_order=3, harmonics=[0, 1, 2])
    models = cyclone.disc.reduced_models(sector, rpm=10000.0, nodal_diameters=nds, cache_directory=cache)
    for _ in range(3):
        wall, response = timed(lambda: cyclone.disc.forced_response(
            sector, models, engine_order=3, harmonics=[0, 1], preload=20000.0, amplitude=20.0, harmonics_check_to=2))
        rows.append((f"disc forced response ({len(response.curve)} points, H 0..1, check H 2)", wall,
                     response.library_seconds))
print("| call | Python wall (s) | the library's call (s) | overhead |")
print("|---|---|---|---|")
for name, wall, library in rows:
    print(f"| {name} | {wall:.3f} | {library:.3f} | {100 * (wall / library - 1):.2f} % |")
