"""The Python API against the cyclone program on the same problem: the Duffing scene
(regression/scenes/duffing.yaml: x'' + 0.05 x' + x + 0.1 x^3 = 0.18 cos(W t), H = 7, 64
samples, W from 0.5 to 2) run by the program, and the same system built by hand in Python,
give the same curve point for point to 1e-10 (the program's frc.csv has 12 significant
digits)."""

import numpy as np

import cyclone
import program


def python_curve():
    duffing = cyclone.HarmonicBalance(M=[[1.0]], K=[[1.0]], C=[[0.05]], harmonics=7, samples=64)
    duffing.add_element(cyclone.CubicSpring(k3=0.1), dofs=[0])
    duffing.add_excitation(dof=0, harmonic=1, cos=0.18)
    return duffing.forced_response(0.5, 2.0, output_dofs=[0])


def test_the_duffing_curve_equals_the_programs(cyclone_program, scene_dir, tmp_path):
    expected = program.read_csv(program.run(cyclone_program, scene_dir / "duffing.yaml", tmp_path / "out") / "frc.csv")
    curve = python_curve()
    assert curve.end is cyclone.BranchEnd.RANGE_END
    assert len(curve) == len(expected["omega_rad_s"]) > 20
    number = lambda key: expected[key].astype(float)  # noqa: E731
    scale = number("dof0_max").max()
    np.testing.assert_allclose(curve.omega, number("omega_rad_s"), rtol=1e-10, atol=0)
    np.testing.assert_allclose(curve.mean(0), number("dof0_h0"), rtol=0, atol=1e-10 * scale)
    for h in range(1, 8):
        np.testing.assert_allclose(curve.amplitude_of(0, h), number(f"dof0_amp_h{h}"), rtol=0, atol=1e-10 * scale)
    np.testing.assert_allclose(curve.max_abs[:, 0], number("dof0_max"), rtol=1e-10, atol=0)
    np.testing.assert_array_equal(curve.stable, expected["stable"].astype(int))
    np.testing.assert_array_equal(curve.flags, expected["bifurcation"])
    # The peak is a point of the curve, the program's largest max|x|.
    assert curve.peak.value == curve.max_abs[curve.peak.index, 0]
    np.testing.assert_allclose(curve.peak.value, number("dof0_max").max(), rtol=1e-10)
