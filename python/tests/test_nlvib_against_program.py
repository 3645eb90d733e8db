"""A Jenkins curve from Python against the cyclone program on the same problem: NLvib's
example 07 (regression/scenes/nlvib_07.yaml: a chain of three unit masses, two elastic dry
friction (Jenkins) elements kt 20, slip force 1, along [1 0 0] and [-1 1 0], cubic springs
along [0 1 0] and [0 -1 1], a unilateral spring at a gap of 0.25 along [0 0 1], H = 7,
1024 samples, W from 0.5 to 2, forced on DOF 1) run by the program, and the same system
built by hand in Python with the elements attached by their direction vectors: the same
curve point for point, every column of frc.csv for the three output DOFs to 1e-10 (its 12
significant digits), Hill's verdicts and flags equal."""

import numpy as np

import cyclone
import program


def python_curve():
    K = np.array([[2.0, -1.0, 0.0], [-1.0, 2.0, -1.0], [0.0, -1.0, 2.0]])
    chain = cyclone.HarmonicBalance(M=np.eye(3), K=K, C=0.02 * K, harmonics=7, samples=1024)
    chain.add_element(cyclone.Jenkins(kt=20.0, slip_force=1.0), W=[1.0, 0.0, 0.0], name="friction_1")
    chain.add_element(cyclone.Jenkins(kt=20.0, slip_force=1.0), W=[-1.0, 1.0, 0.0], name="friction_21")
    chain.add_element(cyclone.CubicSpring(k3=1.0), W=[0.0, 1.0, 0.0], name="cubic_2")
    chain.add_element(cyclone.CubicSpring(k3=1.0), W=[0.0, -1.0, 1.0], name="cubic_32")
    chain.add_element(cyclone.UnilateralSpring(k=1.0, gap=0.25), W=[0.0, 0.0, 1.0], name="gap_3")
    chain.add_excitation(dof=1, harmonic=1, cos=1.0)
    return chain.forced_response(0.5, 2.0, output_dofs=[1, 0, 2])


def test_the_nlvib_07_curve_equals_the_programs(cyclone_program, scene_dir, tmp_path):
    out = program.run(cyclone_program, scene_dir / "nlvib_07.yaml", tmp_path / "out")
    expected = program.read_csv(out / "frc.csv")
    curve = python_curve()
    assert curve.end is cyclone.BranchEnd.RANGE_END
    assert len(curve) == len(expected["omega_rad_s"]) > 20
    number = lambda key: expected[key].astype(float)  # noqa: E731
    np.testing.assert_allclose(curve.omega, number("omega_rad_s"), rtol=1e-10, atol=0)
    for k, dof in enumerate([1, 0, 2]):
        scale = number(f"dof{dof}_max").max()
        np.testing.assert_allclose(curve.mean(dof), number(f"dof{dof}_h0"), rtol=0, atol=1e-10 * scale)
        for h in range(1, 8):
            np.testing.assert_allclose(curve.amplitude_of(dof, h), number(f"dof{dof}_amp_h{h}"), rtol=0,
                                       atol=1e-10 * scale, err_msg=f"DOF {dof}, harmonic {h}")
        np.testing.assert_allclose(curve.max_abs[:, k], number(f"dof{dof}_max"), rtol=1e-10, atol=0)
    np.testing.assert_array_equal(curve.stable, expected["stable"].astype(int))
    np.testing.assert_array_equal(curve.flags, expected["bifurcation"])
    np.testing.assert_array_equal(curve.segment, expected["segment"].astype(int))
    assert program.assert_retraces_equal(curve, out, "frc") == (("predictor_corrector", False, 1, ()), True)
