"""A 3D friction contact from Python against the cyclone program on the same problem:
regression/scenes/friction3d_rotating.yaml (a mass on a 3D friction contact, kt 5, kn 20,
mu 0.3, pressed by a static force 100, under a rotating force 20 (cos W t, sin W t), H = 3,
2048 samples, W from 1.5 to 6) run by the program, and the same system built by hand in
Python (Friction3D on W = I, add_static_load): the same curve point for point, every
column of frc.csv for x, y and n to 1e-10 (its 12 significant digits), Hill's verdicts and
flags equal, traced whole once as the program says."""

import numpy as np

import cyclone
import program


def python_curve():
    system = cyclone.HarmonicBalance(M=np.eye(3), K=np.diag([10.0, 10.0, 20.0]), C=np.diag([0.2, 0.2, 1.0]),
                                     harmonics=3, samples=2048)
    system.add_element(cyclone.Friction3D(kt=5.0, kn=20.0, mu=0.3), W=np.eye(3), name="contact")
    system.add_static_load(dof=2, value=100.0)
    system.add_excitation(dof=0, harmonic=1, cos=20.0)
    system.add_excitation(dof=1, harmonic=1, sin=20.0)
    return system.forced_response(1.5, 6.0, output_dofs=[0, 1, 2])


def test_the_friction3d_curve_equals_the_programs(cyclone_program, scene_dir, tmp_path):
    curve = python_curve()
    program.assert_whole_curve_is_the_programs(curve, cyclone_program, scene_dir / "friction3d_rotating.yaml",
                                               tmp_path / "out", ["x", "y", "n"])
    # The contact pressed by 100 on kn 20 beside the spring 20: its mean normal displacement 100 / 40.
    np.testing.assert_allclose(curve.mean(2), 2.5, rtol=1e-9)
