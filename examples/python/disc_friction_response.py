"""The friction-damped forced response of the built-in disc under engine order 3 from
Python, its headline peak and a study of the shroud contacts' preload, as example 04.
Writes disc_response.png; exits 1 unless the whole range was traced, the headline lies
between the shroud's free and stuck resonances, and the study's peaks rise in frequency
with the preload, inside those limits.

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

# 1. Reduced models (hybrid, 20 modes, 10 000 rpm) for the nodal diameters engine order 3's
#    harmonics 0..2 live on (the harmonics check adds harmonic 2).
nds = cyclone.disc.nodal_diameters_for(sector.sectors, engine_order=3, harmonics=[0, 1, 2])
models = cyclone.disc.reduced_models(sector, rpm=10000.0, nodal_diameters=nds, cache_directory=out / "reduced_models")

# 2. The curve over the range the resonance estimate gives (3D friction at the shroud, 20 kN
#    over the interface, 20 N axial at mid-blade), its peak found again with harmonics 0..2.
response = cyclone.disc.forced_response(sector, models, engine_order=3, harmonics=[0, 1], preload=20000.0,
                                        amplitude=20.0, harmonics_check_to=2)
curve, headline, estimate = response.curve, response.headline, response.estimate
free, stuck = estimate["free_hz"], estimate["stuck_hz"]  # the shroud free, the contacts stuck
print(f"{len(curve)} points, ended: {curve.end.value}\nheadline: {headline.convergence.value}; {headline.text}")

# 3. The preload study: a curve per preload over the same band (20 kN is the response's own).
study = cyclone.disc.study(response, "preload", [5000.0, 20000.0, 40000.0])

fig, ax = plt.subplots(figsize=(7, 4.5))
for value, c in zip(study.values, study.curves):
    ax.plot(c.omega / (2 * np.pi), c.max_abs[:, 0], label=f"preload {value / 1000:g} kN")
ax.plot(headline.hz, headline.value, "kx", label="headline (harmonics 0..2)")
ax.set(xlabel="frequency (Hz)", ylabel="mid-blade max |x(t)| (mm)", xlim=(0.95 * study.peak_hz.min(), 1.02 * stuck),
       title="Engine order 3 with friction at the shroud: the preload study")
ax.legend()
fig.tight_layout()
fig.savefig(out / "disc_response.png", dpi=120)

# 4. What friction must give: the peaks between the linear limits (shroud free and contacts
#    stuck), rising in frequency as more preload holds the contacts.
for value, hz, peak in zip(study.values, study.peak_hz, study.peak):
    print(f"preload {value:7.0f} N: peak {peak:.5f} mm at {hz:.2f} Hz")
ok = curve.finished and headline.convergence is not cyclone.disc.Convergence.NOT_FOUND
ok = ok and free < headline.hz < 1.01 * stuck and study.finished.all()
ok = ok and (np.diff(study.peak_hz) > 0).all() and free < study.peak_hz.min() and study.peak_hz.max() < 1.01 * stuck
print(f"free {free:.2f} Hz, stuck {stuck:.2f} Hz:", "disc friction response: ok" if ok else "FAILED")
sys.exit(0 if ok else 1)
