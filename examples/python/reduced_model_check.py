"""Reduced models of the built-in sector at its shroud contact and mid-blade nodes, one
per nodal diameter, the one of ND 3 checked against the full FE compliance, from Python,
as example 03. Writes reduced_model_check.png (|A| at mid-blade, reduced and full, and
the error); exits 1 unless the hybrid model's error is below 1e-3 at every frequency.

    PYTHONPATH=build/python python3 examples/python/reduced_model_check.py [output directory]
"""

import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import cyclone  # noqa: E402

out = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".")
out.mkdir(parents=True, exist_ok=True)
sector = cyclone.disc.shrouded_sector(mesh_size=12.0)

# Petrov's hybrid models (20 modes and the exact static correction) on the nonlinear
# prestress at 10 000 rpm, cantilevered (the shroud free: its contacts are the harmonic
# balance's), ND 3's compared with the complex FE solve at 12 frequencies. A model read
# back from the cache brings the check made when it was built.
models = cyclone.disc.reduced_models(sector, rpm=10000.0, nodal_diameters=[1, 2, 3], kind="hybrid", modes=20,
                                     cache_directory=out / "reduced_models", check_nodal_diameter=3)
c = models.check
for hz, reduced, full, error in zip(c.hz, c.reduced, c.full, c.error):
    print(f"{hz:9.2f} Hz  reduced {reduced:.6e}  full {full:.6e}  error {error:.2e}")
print(f"models for ND {models.nodal_diameters} ({models.built} built, {models.reused} reused) in {models.seconds:.1f} s")

fig, (top, bottom) = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
top.semilogy(c.hz, c.full, "o", label="full FE")
top.semilogy(c.hz, c.reduced, "x", label="reduced (hybrid, 20 modes)")
top.set(ylabel="|A| at mid-blade (mm/N)", title=f"ND {c.nodal_diameter}: the reduced model against the full FE model")
top.legend()
bottom.semilogy(c.hz, c.error, "s-", ms=3)
bottom.set(xlabel="frequency (Hz)", ylabel="relative error of A")
fig.tight_layout()
fig.savefig(out / "reduced_model_check.png", dpi=120)

ok = c.nodal_diameter == 3 and len(c.hz) > 0 and c.max_error < 1e-3
print(f"largest error {c.max_error:.2e}:", "reduced model check: ok" if ok else "reduced model check: FAILED")
sys.exit(0 if ok else 1)
