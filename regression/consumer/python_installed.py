"""The package `cyclone` as `cmake --install` puts it (the examples' scratch prefix, test
examples_build): imported from there alone, not from the build tree, and a Duffing curve
traced with it whose peak is the harmonic balance's (the backbone's fold near
W = 1.27 for x'' + 0.05 x' + x + 0.1 x^3 = 0.18 cos(W t), as regression/scenes/duffing.yaml).

    PYTHONPATH=<prefix>/lib/python3.X/dist-packages python3 python_installed.py <prefix>
"""

import pathlib
import sys

import cyclone

prefix = pathlib.Path(sys.argv[1]).resolve()
where, core = (pathlib.Path(m.__file__).resolve() for m in (cyclone, cyclone._core))
if prefix not in where.parents or prefix not in core.parents:
    sys.exit(f"cyclone imported from {where} ({core}), not from the install prefix {prefix}")
duffing = cyclone.HarmonicBalance(M=[[1.0]], K=[[1.0]], C=[[0.05]], harmonics=7, samples=64)
duffing.add_element(cyclone.CubicSpring(k3=0.1), dofs=[0])
duffing.add_excitation(dof=0, harmonic=1, cos=0.18)
curve = duffing.forced_response(0.5, 2.0)
ok = curve.end is cyclone.BranchEnd.RANGE_END and abs(curve.peak.value / 2.87711 - 1) < 1e-5
ok = ok and abs(curve.peak.omega / 1.26869 - 1) < 1e-4
print(f"cyclone from {where.parent}: {curve}", "ok" if ok else "FAILED")
sys.exit(0 if ok else 1)
