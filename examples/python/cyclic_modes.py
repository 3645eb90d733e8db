"""The cyclic modes of a bladed-disc sector read from a mesh file, from Python, as
example 01. Without a mesh file the built-in sector is written as one first (.inp, as a
mesher would). Writes cyclic_modes.png (frequency against nodal diameter); exits 1 unless
every nodal diameter 0..12 has its three modes, ND 0 and 12 single, the others pairs of
equal frequency (1e-8), all positive with the bore held.

    PYTHONPATH=build/python python3 examples/python/cyclic_modes.py [output directory] [MESH]
    MESH: .inp, .exo or .msh with node sets bore, disc_left/right, shroud_left/right
"""

import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import cyclone  # noqa: E402

out = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".")
out.mkdir(parents=True, exist_ok=True)
path = pathlib.Path(sys.argv[2]) if len(sys.argv) > 2 else out / "sector.inp"
if len(sys.argv) <= 2:
    cyclone.disc.write_mesh(cyclone.disc.shrouded_sector(mesh_size=12.0), path)  # 24 sectors
sectors = 24
mesh = cyclone.disc.read_mesh(path, sectors=sectors)

# Three modes per nodal diameter 0..12 at rest, titanium, the bore held, the disc's and
# the shroud's side faces paired under the rotation.
modes = cyclone.disc.modal_sweep(mesh, speeds_rpm=[0.0], modes_per_nd=3, configuration="fixed_shroud")

ok = modes.nodal_diameters == list(range(sectors // 2 + 1))
fig, ax = plt.subplots(figsize=(6, 4.5))
for k in modes.nodal_diameters:
    f = modes.frequencies_hz(k)[0]
    copies = 1 if k in (0, sectors // 2) else 2
    ok = ok and len(f) == 3 * copies and (f > 0).all()
    if copies == 2:
        ok = ok and np.allclose(f[1::2], f[::2], rtol=1e-8, atol=0)
    print(f"ND {k:2d}:", " ".join(f"{hz:10.2f}" for hz in f[::copies]), "Hz")
    ax.plot([k] * 3, f[::copies], "o", color="C0", ms=4)
ax.set_xlabel("nodal diameter")
ax.set_ylabel("frequency (Hz)")
ax.set_title(f"Cyclic modes of {path.name}, {sectors} sectors, at rest")
fig.tight_layout()
fig.savefig(out / "cyclic_modes.png", dpi=120)
print("cyclic modes:", "ok" if ok else "FAILED")
sys.exit(0 if ok else 1)
