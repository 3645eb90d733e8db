"""The built-in sector spinning at 10 000 rpm, its bore held, from Python, as example 00:
one static solve of the centrifugal load. Writes static_solve.png (the displacement over
the sector); exits 1 unless the solve's residual is below 1e-8 and the largest
displacement grows with the speed squared (the load is linear in it: 5 000 rpm gives a
quarter).

    PYTHONPATH=build/python python3 examples/python/static_solve.py [output directory]
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
sector = cyclone.disc.shrouded_sector(mesh_size=10.0)
full = cyclone.disc.static_solve(sector, speed_rpm=10000.0, fixed_node_sets=["bore"])
half = cyclone.disc.static_solve(sector, speed_rpm=5000.0, fixed_node_sets=["bore"])
print(f"static solve: {full.equations} equations, max |u| = {full.max_displacement:.6g} mm, "
      f"residual {full.relative_residual:.2g}, max von Mises {full.max_von_mises:.4g} MPa")

x, y = sector.coordinates[:, 0], sector.coordinates[:, 1]
u = np.linalg.norm(full.displacement, axis=1)
fig, ax = plt.subplots(figsize=(6, 5))
dots = ax.scatter(x, y, c=u, s=6, cmap="viridis")
fig.colorbar(dots, label="|u| (mm)")
ax.set_aspect("equal")
ax.set_xlabel("x (mm)")
ax.set_ylabel("y (mm)")
ax.set_title("The sector at 10 000 rpm, bore held (nodes seen along the axis)")
fig.tight_layout()
fig.savefig(out / "static_solve.png", dpi=120)

ratio = half.max_displacement / full.max_displacement
ok = full.relative_residual < 1e-8 and abs(ratio - 0.25) < 1e-9 and np.isclose(u.max(), full.max_displacement)
print(f"5000 rpm over 10000 rpm: {ratio:.12f} (0.25):", "static solve: ok" if ok else "static solve: FAILED")
sys.exit(0 if ok else 1)
