"""Friction elements against the closed forms the C++ verification uses.

- A Jenkins element on a 1-DOF oscillator by single-harmonic balance: every point of the
  curve solves the describing function's amplitude equation
  (regression/verification/jenkins_peak_tracking.cpp):
    K(a) = kt / pi (beta - sin(2 beta) / 2), cos beta = 1 - 2 fs / (kt a),
    D(a) = 4 fs (a - fs / kt) / (pi a^2)   (a > fs / kt; stuck: K = kt, D = 0),
    a^2 [(k + K - m W^2)^2 + (c W + D)^2] = P^2.
- The 2-DOF Jenkins chain of regression/verification/peak_tracking_vs_sweeps.cpp (masses 1
  and 0.5, K = [[2, -1], [-1, 1]], C = 0.02 K, a Jenkins element kt 0.5, slip force 0.02
  from the second mass to ground, at its force level 0.2: 0.02 cos(W t) on the first), built by hand as a tmdsimpy
  user would, one harmonic: each point solves the describing function's fixed point
  X = (K - W^2 M + i W C + e2 e2^T (K(a) + i D(a)))^-1 F with a = |X_2|, the peak too.
- tmdsimpy's 2-DOF elastic dry friction example, built by hand as a tmdsimpy user would
  (regression/scenes/tmdsimpy_friction2d.yaml, regression/verification/friction_tmdsimpy.cpp):
  at a force scale of 10 the contact stays stuck, so every point is the stuck linear
  system's response, and the peak is the decoupled x oscillator's closed form (tmdsimpy:
  0.70071 s at W = 4.118)."""

import numpy as np

import cyclone

m, k, c, kt, P = 1.0, 1.0, 0.01, 1.0, 0.01


def describing_function_of(a, kt, fs):
    """The Jenkins element's first-harmonic stiffness and quadrature (damping) part at amplitude a."""
    if a <= fs / kt:
        return kt, 0.0
    beta = np.arccos(1 - 2 * fs / (kt * a))
    return kt / np.pi * (beta - np.sin(2 * beta) / 2), 4 * fs * (a - fs / kt) / (np.pi * a * a)


def describing_function(a, fs):
    return describing_function_of(a, kt, fs)


def test_jenkins_points_solve_the_describing_function():
    fs = 0.02  # slips over the resonance, stuck on its flanks
    oscillator = cyclone.HarmonicBalance(M=[[m]], K=[[k]], C=[[c]], harmonics=[1], samples=1024)
    oscillator.add_element(cyclone.Jenkins(kt=kt, slip_force=fs), dofs=[0])
    oscillator.add_excitation(dof=0, harmonic=1, cos=P)
    curve = oscillator.forced_response(0.8, 1.8, harmonics_check=False)
    assert curve.end is cyclone.BranchEnd.RANGE_END
    a = curve.amplitude_of(0, 1)
    slipping = a > fs / kt
    assert slipping.sum() > 10 and (~slipping).sum() > 10  # both laws are exercised
    worst = 0.0
    for ai, w in zip(a, curve.omega):
        K, D = describing_function(ai, fs)
        worst = max(worst, abs(ai * np.hypot(k + K - m * w**2, c * w + D) / P - 1))
    # 1024 samples place the stick-slip corners to within a sample: the C++ test's 1e-4.
    assert worst < 1e-4


def test_the_two_dof_jenkins_chain_solves_the_describing_function():
    M, K = np.diag([1.0, 0.5]), np.array([[2.0, -1.0], [-1.0, 1.0]])
    chain = cyclone.HarmonicBalance(M, K, 0.02 * K, harmonics=[1], samples=1024)
    chain.add_element(cyclone.Jenkins(kt=0.5, slip_force=0.02), dofs=[1])
    chain.add_excitation(dof=0, harmonic=1, cos=0.02)
    curve = chain.forced_response(0.3, 2.2, output_dofs=[1, 0], harmonics_check=False)
    assert curve.end is cyclone.BranchEnd.RANGE_END
    X = curve.coefficients[:, :, 0] - 1j * curve.coefficients[:, :, 1]  # x = Re(X e^{iWt})
    assert (abs(X[:, 1]) > 0.02 / 0.5).sum() > 10 and (abs(X[:, 1]) < 0.02 / 0.5).sum() > 10  # slips and sticks
    worst = 0.0
    for Xi, w in zip(X, curve.omega):
        K_eq, D_eq = describing_function_of(abs(Xi[1]), kt=0.5, fs=0.02)
        Z = K - w**2 * M + 1j * w * 0.02 * K + np.diag([0.0, K_eq + 1j * D_eq])
        closed = np.linalg.solve(Z, [0.02, 0.0])
        worst = max(worst, np.abs(closed - Xi).max() / np.abs(Xi).max())
    assert worst < 1e-4  # the stick-slip corners placed to within one of 1024 samples, as the 1-DOF case
    assert curve.peak.index in range(len(curve)) and curve.peak.value == curve.max_abs[curve.peak.index, 0]


def tmdsimpy_friction_2dof(scale, cx=2 * 0.05 * np.sqrt(12.0)):
    kx, kn, cn = 12.0, 21.0, 2.0
    system = cyclone.HarmonicBalance(M=np.eye(2), K=np.diag([kx, kn]), C=np.diag([cx, cn]), harmonics=8,
                                     samples=128)
    system.add_element(cyclone.Friction2D(kt=5.0, kn=21.0, mu=0.85), dofs=[0, 1], name="contact")  # [t, n]
    system.add_static_load(dof=1, value=100.0)
    system.add_excitation(dof=0, harmonic=1, cos=1.0)
    system.add_excitation(dof=1, harmonic=1, cos=0.1)
    return system, dict(force_scale=scale, output_dofs=[0, 1], max_step=0.02)


def test_tmdsimpy_friction_stuck_level_is_the_stuck_linear_system():
    s = 10.0
    system, options = tmdsimpy_friction_2dof(s)
    curve = system.forced_response(3.6, 4.6, **options)
    assert curve.end is cyclone.BranchEnd.RANGE_END
    Ks = system.K + np.diag([5.0, 21.0])  # stuck: the contact's kt and kn added
    for i, w in enumerate(curve.omega):
        X = np.linalg.solve(Ks - w**2 * system.M + 1j * w * system.C, s * np.array([1.0, 0.1]))
        assert abs(curve.max_abs[i, 0] / abs(X[0]) - 1) < 1e-8
    cx = system.C[0, 0]
    w_peak, x_peak = np.sqrt(17 - cx**2 / 2), s / (cx * np.sqrt(17 - cx**2 / 4))
    assert abs(curve.peak.value / x_peak - 1) < 1e-8
    assert abs(curve.peak.omega / w_peak - 1) < 1e-4
    assert abs(curve.peak.value / (0.70071 * s) - 1) < 2e-4  # tmdsimpy's published value
