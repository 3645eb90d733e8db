"""The Campbell and SAFE diagrams of the built-in sector over 0..10 000 rpm and the
engine-order resonances in that range, from Python, as example 02. Writes campbell.png
and safe.png; exits 1 unless each resonance lies on its engine order's line
f = EO rpm / 60 (1e-9) and the blade-dominated first family at ND 12 stiffens with speed.

    PYTHONPATH=build/python python3 examples/python/campbell_safe.py [output directory]
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
sector = cyclone.disc.shrouded_sector(mesh_size=12.0)  # 24 sectors, coarse: seconds
N = sector.sectors

# Two modes per nodal diameter at three speeds on the linear prestress; the families
# tracked across the speeds by MAC, and where engine orders 1..24 cross them.
modes = cyclone.disc.modal_sweep(sector, speeds_rpm=[0.0, 5000.0, 10000.0], modes_per_nd=2, prestress="linear",
                                 engine_orders=range(1, N + 1))
r = modes.resonances

fig, ax = plt.subplots(figsize=(7, 4.5))
for b in modes.branches:
    ax.plot(b.rpm, b.hz, "-", color=plt.cm.viridis(b.nd / (N // 2)), lw=1)
rpm = np.array([0.0, modes.rpm[-1]])
for eo in range(1, N + 1):
    ax.plot(rpm, eo * rpm / 60, "k--", lw=0.4)
ax.plot(r["rpm"], r["hz"], "ro", ms=4, label="resonances")
ax.set(xlabel="speed (rpm)", ylabel="frequency (Hz)", ylim=(0, 2500),
       title="Campbell diagram (colour: nodal diameter; dashed: engine orders)")
ax.legend()
fig.tight_layout()
fig.savefig(out / "campbell.png", dpi=120)

# SAFE: the families against the nodal diameter at the top speed, and the engine orders'
# zig-zag (EO excites ND |EO mod N| folded into 0..N/2) at the frequency they reach there.
fig, ax = plt.subplots(figsize=(7, 4.5))
for family in (1, 2):
    top = sorted((b.nd, b.hz[-1]) for b in modes.branches if b.family == family)
    ax.plot(*zip(*top), "o-", ms=3, label=f"family {family} at {modes.rpm[-1]:g} rpm")
eo = np.arange(1, N + 1)
nd = np.minimum(eo % N, N - eo % N)
ax.plot(nd, eo * modes.rpm[-1] / 60, "k--", lw=0.6, label="engine orders 1..24")
ax.plot(r["nd"], r["hz"], "ro", ms=4, label="resonances (at their speed)")
ax.set(xlabel="nodal diameter", ylabel="frequency (Hz)", ylim=(0, 4500), title="SAFE diagram")
ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(out / "safe.png", dpi=120)

ok = len(r["eo"]) > 0 and np.allclose(r["hz"], r["eo"] * r["rpm"] / 60, rtol=1e-9, atol=0)
for i in range(len(r["eo"])):
    print(f"EO {r['eo'][i]:2d}  ND {r['nd'][i]:2d}  family {r['family'][i]}  {r['rpm'][i]:7.0f} rpm  "
          f"{r['hz'][i]:8.2f} Hz")
nd12 = next(b for b in modes.branches if b.nd == 12 and b.family == 1)
print(f"ND 12 family 1: {nd12.hz[0]:.2f} Hz at 0 rpm, {nd12.hz[-1]:.2f} Hz at 10000 rpm")
ok = ok and nd12.hz[-1] > nd12.hz[0]
print("campbell and safe:", "ok" if ok else "FAILED")
sys.exit(0 if ok else 1)
