"""tmdsimpy's 2-DOF elastic dry friction example (Porter & Brake; its
examples/2dof_eldry_fric.py), built by hand and traced at five force levels: as the
contact slips the resonance moves from the stuck system's to the free one's, most damped
between. Writes friction_2dof.png; exits 1 unless the stuck level's peak is the stuck
linear system's (tmdsimpy's 0.70071 s at W = 4.118) and the peaks' frequencies fall with
the force between the stuck and the free limits.

    PYTHONPATH=build/python python3 examples/python/friction_2dof.py [output directory]
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
kx, kn, cx, cn = 12.0, 21.0, 2 * 0.05 * np.sqrt(12.0), 2.0
system = cyclone.HarmonicBalance(M=np.eye(2), K=np.diag([kx, kn]), C=np.diag([cx, cn]), harmonics=8, samples=128)
system.add_element(cyclone.Friction2D(kt=5.0, kn=21.0, mu=0.85), dofs=[0, 1])  # coordinates [t, n]
system.add_static_load(dof=1, value=100.0)  # presses the contact shut
system.add_excitation(dof=0, harmonic=1, cos=1.0)
system.add_excitation(dof=1, harmonic=1, cos=0.1)

fig, ax = plt.subplots(figsize=(7, 4.5))
peaks = {}
for scale in (1.0, 10.0, 50.0, 100.0, 300.0):
    curve = system.forced_response(2.5, 5.5, force_scale=scale, output_dofs=[0, 1], max_step=0.05)
    if not curve.finished:
        sys.exit(f"s = {scale}: the trace ended early: {curve.stop_reason}")
    x = curve.max_abs[:, 0] / scale
    ax.plot(curve.omega, x, label=f"s = {scale:g}")
    unstable = curve.stable == 0
    ax.plot(curve.omega[unstable], x[unstable], "k.", ms=3)
    peaks[scale] = curve.peak
    print(f"s = {scale:5g}: {len(curve)} points, peak max|x|/s {curve.peak.value / scale:.5f} at W {curve.peak.omega:.4f}")
ax.set_xlabel("W (rad/s)")
ax.set_ylabel("max |x(t)| / s")
ax.set_title("tmdsimpy 2-DOF elastic dry friction (black dots: unstable)")
ax.legend()
fig.tight_layout()
fig.savefig(out / "friction_2dof.png", dpi=120)

# Stuck at s = 10: the decoupled x oscillator with the contact's kt, m = 1, k = 17.
stuck = peaks[10.0]
closed = 10.0 / (cx * np.sqrt(17 - cx**2 / 4))
ok = abs(stuck.value / closed - 1) < 1e-8 and abs(stuck.value / 7.0071 - 1) < 2e-4
# The free limit: the x oscillator without the contact, k = 12.
frequencies = [peaks[s].omega for s in sorted(peaks)]
ok = ok and all(b <= a + 1e-9 for a, b in zip(frequencies, frequencies[1:]))
ok = ok and np.sqrt(kx - cx**2 / 2) <= frequencies[-1] and frequencies[0] <= np.sqrt(17 - cx**2 / 2) + 1e-9
print("friction_2dof:", "ok" if ok else "FAILED")
sys.exit(0 if ok else 1)
