"""The engine-order cyclic constraint from Python against the program, and against the
travelling wave's closed form.

- The lumped bladed ring of regression/scenes/cyclic_friction_ring.yaml (12 sectors, a
  2D friction contact across the sector boundary by W_next, engine order 3, modal damping
  0.5 %, cyclone.modal_damping the scene's computation) run by the program and built by
  hand in Python: the same curve to 1e-10 (the CSV's 12 digits).
- A linear ring of N spring-masses, each on a ground spring k and coupled to its
  neighbours by kc, under f_j = F cos(W t - 2 pi EO j / N): every sector's amplitude is
  F / |k + 2 kc (1 - cos(2 pi EO / N)) - m W^2 + i c W|."""

import numpy as np

import cyclone
import program


def test_the_cyclic_friction_ring_equals_the_programs(cyclone_program, scene_dir, tmp_path):
    out = program.run(cyclone_program, scene_dir / "cyclic_friction_ring.yaml", tmp_path / "out")
    expected = program.read_csv(out / "frc.csv")

    M = np.diag([1.0, 0.3, 0.3])
    K = np.array([[14.0, -4.0, -2.0], [-4.0, 4.0, 0.0], [-2.0, 0.0, 2.0]])
    K_next = np.zeros((3, 3))
    K_next[0, 0] = -3.0
    ring = cyclone.HarmonicBalance(M, K, cyclone.modal_damping(M, K, 0.005), harmonics=5, samples=384, sectors=12,
                                   engine_order=3, K_next=K_next)
    ring.add_element(cyclone.Friction2D(kt=3.0, kn=6.0, mu=0.3, preload=0.4),
                     W=[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]], W_next=[[0.0, 0.0], [-1.0, 0.0], [0.0, -1.0]])
    ring.add_excitation(dof=1, harmonic=1, cos=0.05)
    curve = ring.forced_response(2.0, 5.0, output_dofs=[1, 0, 2])

    assert curve.end is cyclone.BranchEnd.RANGE_END
    assert len(curve) == len(expected["omega_rad_s"]) > 20
    number = lambda key: expected[key].astype(float)  # noqa: E731
    np.testing.assert_allclose(curve.omega, number("omega_rad_s"), rtol=1e-10)
    for k, dof in enumerate([1, 0, 2]):
        scale = number(f"dof{dof}_max").max()
        np.testing.assert_allclose(curve.max_abs[:, k], number(f"dof{dof}_max"), rtol=0, atol=1e-10 * scale)
        for h in range(1, 6):
            np.testing.assert_allclose(curve.amplitude_of(dof, h), number(f"dof{dof}_amp_h{h}"), rtol=0,
                                       atol=1e-10 * scale)
    np.testing.assert_array_equal(curve.stable, expected["stable"].astype(int))
    np.testing.assert_array_equal(curve.flags, expected["bifurcation"])
    assert [ring._core().nodal_diameter(h) for h in range(1, 6)] == [3, 6, 3, 0, 3]  # 3 h mod 12, folded


def test_a_linear_ring_is_the_travelling_waves_closed_form():
    N, EO, m, c, k, kc, F = 8, 3, 1.0, 0.02, 2.0, 0.5, 0.1
    ring = cyclone.HarmonicBalance(M=[[m]], K=[[k + 2 * kc]], C=[[c]], harmonics=[1], samples=16, sectors=N,
                                   engine_order=EO, K_next=[[-kc]])
    ring.add_excitation(dof=0, harmonic=1, cos=F)
    curve = ring.forced_response(0.5, 3.0)
    w = curve.omega
    stiffness = k + 2 * kc * (1 - np.cos(2 * np.pi * EO / N))
    np.testing.assert_allclose(curve.amplitude_of(0, 1), F / np.abs(stiffness - m * w**2 + 1j * c * w), rtol=1e-9)
    assert abs(curve.peak.omega / np.sqrt(stiffness / m - c**2 / (2 * m**2)) - 1) < 1e-4
