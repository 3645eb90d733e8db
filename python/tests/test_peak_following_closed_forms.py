"""A matrix system's peak followed over a parameter against closed forms (the program
follows peaks of the disc only: tests/test_disc_studies_against_program.py).

- A linear oscillator m x'' + s c x' + k x = F cos(W t) over the damping's scale s: the
  peak F / (s c sqrt(k / m - (s c)^2 / (4 m^2))) at W^2 = k / m - (s c)^2 / (2 m^2); over
  the force scale the same peak times the scale. The smallest peak is the most damped.
- A Jenkins element on a 1-DOF oscillator over its slip force: each peak is the largest
  amplitude of the describing function's amplitude equation (test_friction_closed_forms)
  over the frequency, to the 1e-4 that 1024 samples place the stick-slip corners to.
- A band above the resonance holds no peak: the typed end says so."""

import numpy as np
import pytest
from scipy.optimize import brentq, minimize_scalar

import cyclone
from test_friction_closed_forms import describing_function_of

m, c, k, F = 2.0, 0.1, 8.0, 0.3


def oscillator():
    return cyclone.HarmonicBalance(M=[[m]], K=[[k]], C=[[c]], harmonics=[1], samples=16).add_excitation(
        dof=0, harmonic=1, cos=F)


def linear_peak(s):
    return F / (s * c * np.sqrt(k / m - (s * c) ** 2 / (4 * m * m))), np.sqrt(k / m - (s * c) ** 2 / (2 * m * m))


@pytest.mark.parametrize("values", [[1.0, 1.5, 2.0, 3.0], [3.0, 2.0, 1.5, 1.0]])
def test_the_linear_peak_over_the_damping_scale(values):
    peaks = oscillator().follow_peak("damping_scale", values, band=(1.0, 3.0))
    assert peaks.end is cyclone.PeakFollowingEnd.RANGE_END and peaks.finished
    np.testing.assert_array_equal(peaks.parameter, values)
    value, omega = linear_peak(np.array(values))
    np.testing.assert_allclose(peaks.peak, value, rtol=1e-8)
    np.testing.assert_allclose(peaks.omega, omega, rtol=1e-6)  # the search's bracket: 1e-7 of the frequency
    assert not peaks.jump.any()
    assert peaks.parameter[peaks.optimum] == 3.0 and not peaks.optimum_located  # the range's end: nothing to locate
    # Each peak's coefficients: the linear response there, x = Re(X e^{iWt}), X = x_c - i x_s.
    X = F / (k - m * peaks.omega**2 + 1j * peaks.parameter * c * peaks.omega)
    np.testing.assert_allclose(peaks.coefficients[:, 0, 0] - 1j * peaks.coefficients[:, 0, 1], X, rtol=1e-7)


def test_the_linear_peak_over_the_force_scale_grows_in_proportion():
    scales = [0.5, 1.0, 2.0, 4.0]
    peaks = oscillator().follow_peak("force_scale", scales, band=(1.0, 3.0))
    assert peaks.end is cyclone.PeakFollowingEnd.RANGE_END
    value, omega = linear_peak(1.0)
    np.testing.assert_allclose(peaks.peak, value * np.array(scales), rtol=1e-8)
    np.testing.assert_allclose(peaks.omega, omega, rtol=1e-6)


def describing_function_peak(fs, m=1.0, k=1.0, c=0.01, kt=1.0, P=0.01):
    """The largest a over W of a^2 [(k + K(a) - m W^2)^2 + (c W + D(a))^2] = P^2: the
    amplitude a is reached at some W while the smallest left side over W is at most P^2."""
    def excess(a):
        K, D = describing_function_of(a, kt, fs)
        lowest = minimize_scalar(lambda w: (k + K - m * w * w) ** 2 + (c * w + D) ** 2, bounds=(0.5, 2.0),
                                 method="bounded", options=dict(xatol=1e-12)).fun
        return a * a * lowest - P * P
    grid = np.geomspace(1e-4, 2 * P / c, 400)  # the largest root: where the amplitude stops being reached
    signs = np.array([excess(a) > 0 for a in grid])
    last = np.flatnonzero(~signs)[-1]
    return brentq(excess, grid[last], grid[last + 1], xtol=1e-14)


def test_the_jenkins_peak_over_the_slip_force_is_the_describing_functions():
    oscillator = cyclone.HarmonicBalance(M=[[1.0]], K=[[1.0]], C=[[0.01]], harmonics=[1], samples=1024)
    oscillator.add_element(cyclone.Jenkins(kt=1.0, slip_force=0.02), dofs=[0], name="contact")
    oscillator.add_excitation(dof=0, harmonic=1, cos=0.01)
    slip_forces = [0.01, 0.014, 0.02, 0.028, 0.04]  # the optimum near 0.015 (the describing function)
    peaks = oscillator.follow_peak("contact/slip_force", slip_forces, band=(0.8, 1.8))
    assert peaks.end is cyclone.PeakFollowingEnd.RANGE_END
    assert set(slip_forces) <= set(peaks.parameter)  # the optimum located between its neighbours is added
    for fs, value in zip(peaks.parameter, peaks.peak):
        assert abs(value / describing_function_peak(fs) - 1) < 1e-4, fs
    # Friction damps most between the extremes: little slip force dissipates little, much sticks.
    assert 0 < peaks.optimum < len(peaks) - 1 and peaks.optimum_located


def test_a_band_without_a_peak_ends_typed():
    peaks = oscillator().follow_peak("damping_scale", [1.0, 2.0], band=(4.0, 6.0))  # the resonance is at 2 rad/s
    assert peaks.end is cyclone.PeakFollowingEnd.NO_PEAK_AT_START and not peaks.finished
    assert len(peaks) == 0 and "no peak" in peaks.stop_reason
    assert {end.value for end in cyclone.PeakFollowingEnd} == set(cyclone._core.peak_following_end_names)


@pytest.mark.parametrize("key, kwargs", [
    ("parameter", dict(parameter="omega", values=[1.0, 2.0], band=(1.0, 3.0))),
    ("values", dict(parameter="damping_scale", values=[1.0, 1.0, 2.0], band=(1.0, 3.0))),
    ("values", dict(parameter="damping_scale", values=[1.0], band=(1.0, 3.0))),
    ("band", dict(parameter="damping_scale", values=[1.0, 2.0], band=(3.0, 1.0))),
    ("band", dict(parameter="damping_scale", values=[1.0, 2.0], band=3.0)),
    ("parameter", dict(parameter="contact/mu", values=[1.0, 2.0], band=(1.0, 3.0))),  # no element of that name
])
def test_wrong_arguments_are_named(key, kwargs):
    with pytest.raises(cyclone.InputError) as error:
        oscillator().follow_peak(**kwargs)
    assert error.value.key == key
