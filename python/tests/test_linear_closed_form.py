"""Linear systems against their closed forms: without nonlinear elements the harmonic
balance is exact, so every traced point must be the linear response (Z(W)^-1 F)."""

import numpy as np
import scipy.sparse

import cyclone

m, c, k, F = 2.0, 0.1, 8.0, 0.3


def single_dof():
    oscillator = cyclone.HarmonicBalance(M=[[m]], K=[[k]], C=[[c]], harmonics=[1], samples=16)
    return oscillator.add_excitation(dof=0, harmonic=1, cos=F)


def test_each_point_is_the_closed_form_amplitude():
    curve = single_dof().forced_response(1.0, 3.0)
    w = curve.omega
    closed = F / np.sqrt((k - m * w**2) ** 2 + (c * w) ** 2)
    assert curve.end is cyclone.BranchEnd.RANGE_END and len(curve) > 10
    np.testing.assert_allclose(curve.amplitude_of(0, 1), closed, rtol=1e-9)
    np.testing.assert_allclose(curve.max_abs[:, 0], closed, rtol=1e-9)
    # The phase too: x = Re(X e^{iWt}), X = F / (k - m W^2 + i c W) = x_c - i x_s.
    X = F / (k - m * w**2 + 1j * c * w)
    np.testing.assert_allclose(curve.coefficients[:, 0, 0], X.real, rtol=0, atol=1e-9 * abs(X).max())
    np.testing.assert_allclose(curve.coefficients[:, 0, 1], -X.imag, rtol=0, atol=1e-9 * abs(X).max())


def test_the_peak_is_located_on_the_curve():
    curve = single_dof().forced_response(1.0, 3.0)
    # |X| is largest at W^2 = k / m - c^2 / (2 m^2), where it is F / (c sqrt(k / m - c^2 / (4 m^2))).
    w_peak = np.sqrt(k / m - c**2 / (2 * m**2))
    peak = F / (c * np.sqrt(k / m - c**2 / (4 * m**2)))
    assert abs(curve.peak.value / peak - 1) < 1e-8
    assert abs(curve.peak.omega / w_peak - 1) < 1e-4  # the top is flat: its place is known less well than its height


def test_a_two_dof_chain_given_by_scipy_sparse_matrices():
    M = scipy.sparse.diags([1.0, 0.5]).tocsr()
    K = scipy.sparse.csr_matrix(np.array([[3.0, -1.0], [-1.0, 1.0]]))
    C = 0.02 * K
    chain = cyclone.HarmonicBalance(M, K, C, harmonics=[0, 1], samples=16)
    chain.add_excitation(dof=1, harmonic=1, cos=0.1, sin=0.05)
    curve = chain.forced_response(0.3, 3.0, output_dofs=[0, 1])
    Md, Kd, Cd = M.toarray(), K.toarray(), C.toarray()
    for i, w in enumerate(curve.omega):
        X = np.linalg.solve(Kd - w**2 * Md + 1j * w * Cd, np.array([0.0, 0.1 - 0.05j]))
        np.testing.assert_allclose(curve.amplitude[i, :, 1], abs(X), rtol=1e-9)
        np.testing.assert_allclose(curve.max_abs[i], abs(X), rtol=1e-9)
    np.testing.assert_allclose(curve.mean(0), 0.0, atol=1e-14)


def test_a_force_scale_curve_grows_in_proportion():
    w = 1.7
    curve = single_dof().forced_response(0.5, 4.0, parameter="force_scale", omega=w, output_dofs=[0])
    assert curve.end is cyclone.BranchEnd.RANGE_END
    np.testing.assert_allclose(curve.omega, w, rtol=0)
    closed = curve.parameter * F / np.hypot(k - m * w**2, c * w)
    np.testing.assert_allclose(curve.amplitude_of(0, 1), closed, rtol=1e-9)
    assert curve.parameter[0] == 0.5 and abs(curve.parameter[-1] - 4.0) < 1e-12
