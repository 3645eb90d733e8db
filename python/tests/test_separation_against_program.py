"""2D friction with its normal load varying down to separation, from Python against the
cyclone program on the same problem: tmdsimpy's 2-DOF friction of
regression/scenes/tmdsimpy_friction2d.yaml (Friction2D kt 5, kn 21, mu 0.85, pressed by a
static 100, s = 100) with the normal force raised from 0.1 to 0.5 s cos(W t) and the range
to 7.5 rad/s, past the normal DOF's resonance, so that the contact opens over part of the
period (n(t) < 0) on a stretch of the curve: run by the program and built by hand, the same
curve point for point (every column of frc.csv to 1e-10), traced whole once as the program
says."""

import numpy as np

import cyclone
import program


def test_a_contact_that_separates_equals_the_programs(cyclone_program, scene_dir, tmp_path):
    scene = (scene_dir / "tmdsimpy_friction2d.yaml").read_text()
    for old, new in [("fn: {dof: 1, harmonic: 1, cos: 0.1}", "fn: {dof: 1, harmonic: 1, cos: 0.5}"),
                     ("    to: 5.5\n", "    to: 7.5\n"), ("  output_directory: tmdsimpy_friction2d_out\n", "")]:
        assert old in scene
        scene = scene.replace(old, new)
    system = cyclone.HarmonicBalance(M=np.eye(2), K=np.diag([12.0, 21.0]), C=np.diag([0.346410161513775, 2.0]),
                                     harmonics=8, samples=128)
    system.add_element(cyclone.Friction2D(kt=5.0, kn=21.0, mu=0.85), dofs=[0, 1], name="contact")
    system.add_static_load(dof=1, value=100.0)
    system.add_excitation(dof=0, harmonic=1, cos=1.0)
    system.add_excitation(dof=1, harmonic=1, cos=0.5)
    curve = system.forced_response(2.5, 7.5, force_scale=100.0, output_dofs=[0, 1])
    program.assert_whole_curve_is_the_programs(curve, cyclone_program, scene, tmp_path / "out", ["dof0", "dof1"])
    # The case is about separation: n(t) = mean + sum (cos, sin) of harmonics 1..8 below 0
    # (the contact open; pressed, n = 100 / 42) over part of the period at a stretch of points.
    phase = np.linspace(0, 2 * np.pi, 256, endpoint=False)
    n = curve.coefficients[:, 1, :1] + sum(curve.coefficients[:, 1, [2 * h - 1]] * np.cos(h * phase) +
                                           curve.coefficients[:, 1, [2 * h]] * np.sin(h * phase) for h in range(1, 9))
    opened = n.min(axis=1) < 0
    assert 10 <= opened.sum() < len(curve)
    np.testing.assert_allclose(n[0].mean(), 100.0 / 42.0, rtol=1e-2)
