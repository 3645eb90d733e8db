"""The residual for users who drive their own solver (tmdsimpy's hbm_res): it vanishes on
the traced curve, its Jacobian is the derivative of the residual (against central
differences of it), its frequency derivative the closed form's (a linear oscillator) and
the differences' (with friction), and a Newton iteration of one's own on it finds the
curve's points."""

import numpy as np
import pytest

import cyclone


def duffing_with_friction():
    system = cyclone.HarmonicBalance(M=np.diag([1.0, 1.0]), K=np.array([[2.0, -1.0], [-1.0, 2.0]]),
                                     C=np.diag([0.02, 0.02]), harmonics=[0, 1, 2, 3], samples=64)
    system.add_element(cyclone.CubicSpring(k3=0.3), dofs=[0])
    system.add_element(cyclone.QuadraticDamper(c2=0.01), between=(0, 1))
    system.add_excitation(dof=0, harmonic=1, cos=0.1)
    system.add_static_load(dof=1, value=0.05)
    return system


def test_the_residual_vanishes_on_the_curve():
    system = duffing_with_friction()
    curve = system.forced_response(0.5, 2.0, harmonics_check=False)
    assert curve.end is cyclone.BranchEnd.RANGE_END
    for x, w in zip(curve.x[::5], curve.omega[::5]):
        R, _ = system.residual(x, w)
        assert np.linalg.norm(R) < 1e-8 * 0.1  # the trace's tolerance is relative to the forces (0.1)


def test_the_jacobian_is_the_residuals_derivative():
    system = duffing_with_friction()
    rng = np.random.default_rng(1)
    x, w = 0.3 * rng.standard_normal(system.num_unknowns), 1.3
    _, J = system.residual(x, w)
    h = 1e-6
    for i in range(system.num_unknowns):
        e = np.zeros_like(x)
        e[i] = h
        column = (system.residual(x + e, w, jacobian=False)[0] - system.residual(x - e, w, jacobian=False)[0]) / (2 * h)
        np.testing.assert_allclose(J[:, i], column, rtol=0, atol=1e-7)


def test_newton_of_ones_own_finds_the_curves_point():
    system = duffing_with_friction()
    curve = system.forced_response(0.5, 2.0, harmonics_check=False)
    x = system.linearized_solution(curve.omega[0])  # the first point, below the resonance: one solution near
    for _ in range(50):
        R, J = system.residual(x, curve.omega[0])
        if np.linalg.norm(R) < 1e-14:
            break
        x = x - np.linalg.solve(J, R)
    assert np.linalg.norm(R) < 1e-14
    np.testing.assert_allclose(x, curve.x[0], rtol=0, atol=1e-9 * abs(curve.x[0]).max())


def test_the_frequency_derivative_is_the_closed_forms():
    # A linear oscillator: R = (k - m W^2 + i c W) X - F in complex form (x = Re(X e^{iWt}),
    # X = x_c - i x_s, likewise R), so dR/dW = (-2 m W + i c) X.
    m, c, k = 2.0, 0.3, 5.0
    oscillator = cyclone.HarmonicBalance(M=[[m]], K=[[k]], C=[[c]], harmonics=[1], samples=16)
    oscillator.add_excitation(dof=0, harmonic=1, cos=1.0)
    x, w = np.array([0.7, -0.4]), 1.9
    _, _, dRdw = oscillator.residual(x, w, frequency_derivative=True)
    closed = (-2 * m * w + 1j * c) * (x[0] - 1j * x[1])
    np.testing.assert_allclose(dRdw, [closed.real, -closed.imag], rtol=1e-12)


def test_the_frequency_derivative_with_friction_against_differences():
    system = cyclone.HarmonicBalance(M=np.diag([1.0, 0.5]), K=np.array([[2.0, -1.0], [-1.0, 1.0]]),
                                     C=np.diag([0.02, 0.02]), harmonics=[0, 1, 2, 3], samples=64)
    system.add_element(cyclone.CubicSpring(k3=0.3), dofs=[0])
    system.add_element(cyclone.Jenkins(kt=0.5, slip_force=0.05), between=(0, 1))
    system.add_excitation(dof=0, harmonic=1, cos=0.1)
    x = 0.3 * np.random.default_rng(2).standard_normal(system.num_unknowns)
    w, h = 1.3, 1e-6
    _, _, dRdw = system.residual(x, w, frequency_derivative=True)
    plus, minus = system.residual(x, w + h, jacobian=False)[0], system.residual(x, w - h, jacobian=False)[0]
    difference = (plus - minus) / (2 * h)
    np.testing.assert_allclose(dRdw, difference, rtol=0, atol=1e-8 * abs(dRdw).max())
    damped = duffing_with_friction()  # its quadratic damper's force changes with the frequency
    with pytest.raises(cyclone.InputError) as error:
        damped.residual(np.zeros(damped.num_unknowns), 1.0, frequency_derivative=True)
    assert error.value.key == "frequency_derivative"
