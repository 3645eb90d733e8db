"""The built-in disc from Python, as examples 02 and 04: its Campbell diagram (the
frequencies of every nodal diameter over the speed, engine-order lines) and the
friction-damped response under engine order 3 at two preloads, with the headline peak.
Writes campbell.png and disc_response.png; exits 1 unless each peak lies between the
shroud's free and stuck resonances and the larger preload's is the higher in frequency.

    PYTHONPATH=build/python python3 examples/python/disc_friction_response.py [output directory]
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
sector = cyclone.disc.shrouded_sector(mesh_size=12.0)  # coarse: seconds

# 1. Campbell: two families per nodal diameter at three speeds.
speeds = [0.0, 5000.0, 10000.0]
modes = cyclone.disc.modal_sweep(sector, speeds_rpm=speeds, modes_per_nd=2)
fig, ax = plt.subplots(figsize=(7, 4.5))
for k in modes.nodal_diameters:
    f = modes.frequencies_hz(k)
    for j in range(0, f.shape[1], 1 if k in (0, sector.sectors // 2) else 2):  # a pair once
        ax.plot(modes.rpm, f[:, j], "o-", color=plt.cm.viridis(k / (sector.sectors // 2)), ms=3, lw=1)
rpm = np.linspace(0, speeds[-1], 2)
for eo in range(1, 13):
    ax.plot(rpm, eo * rpm / 60, "k--", lw=0.5)
ax.set_xlabel("speed (rpm)")
ax.set_ylabel("frequency (Hz)")
ax.set_ylim(0, 2500)  # engine orders 1..12 cross the lowest families here
ax.set_title("Campbell diagram (colour: nodal diameter; dashed: engine orders 1..12)")
fig.tight_layout()
fig.savefig(out / "campbell.png", dpi=120)

# 2. The friction-damped response under engine order 3 at 10 000 rpm, two preloads.
nds = cyclone.disc.nodal_diameters_for(sector.sectors, engine_order=3, harmonics=[0, 1, 2])
models = cyclone.disc.reduced_models(sector, rpm=10000.0, nodal_diameters=nds, cache_directory=out / "reduced_models")
fig, ax = plt.subplots(figsize=(7, 4.5))
ok, last_hz = True, 0.0
for preload in (5000.0, 20000.0):
    response = cyclone.disc.forced_response(sector, models, engine_order=3, harmonics=[0, 1], preload=preload,
                                            amplitude=20.0, harmonics_check_to=2)
    curve, headline, estimate = response.curve, response.headline, response.estimate
    hz = curve.omega / (2 * np.pi)
    ax.plot(hz, curve.max_abs[:, 0], label=f"preload {preload / 1000:g} kN")
    ax.plot(headline.hz, headline.value, "kx")
    print(f"preload {preload:g} N: {len(curve)} points, {curve.end.value}; {headline.text}")
    ok = ok and curve.finished and headline.convergence is not cyclone.disc.Convergence.NOT_FOUND
    ok = ok and estimate["free_hz"] < headline.hz < 1.01 * estimate["stuck_hz"] and headline.hz > last_hz
    last_hz = headline.hz
ax.set_xlabel("frequency (Hz)")
ax.set_ylabel("mid-blade max |x(t)| (mm)")
ax.set_title("Engine order 3 with friction at the shroud (x: the headline, harmonics 0..2)")
ax.legend()
fig.tight_layout()
fig.savefig(out / "disc_response.png", dpi=120)
print("disc friction response:", "ok" if ok else "FAILED")
sys.exit(0 if ok else 1)
