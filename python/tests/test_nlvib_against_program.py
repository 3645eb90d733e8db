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
    curve = python_curve()
    expected = program.assert_whole_curve_is_the_programs(curve, cyclone_program, scene_dir / "nlvib_07.yaml",
                                                          tmp_path / "out", ["dof1", "dof0", "dof2"])
    np.testing.assert_array_equal(curve.segment, expected["segment"].astype(int))
