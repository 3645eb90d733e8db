"""A harmonic balance system of matrices, as tmdsimpy's VibrationSystem(M, K, C): the
linear part, nonlinear elements, the excitation and static loads, the harmonics and the
time samples of the AFT. The unknowns are the real Fourier coefficients of every DOF,
x[dof * num_coefficients + slot], the slots following the harmonics: the mean for
harmonic 0, then cos and sin of each other harmonic (harmonics 0..2: [x0, x1c, x1s, x2c, x2s])."""

import numpy as np

from . import _core, arrays
from .elements import Element
from .errors import InputError
from .peaks import FollowedPeaks
from .response import ForcedResponse, trace_options


class HarmonicBalance:
    """M x'' + C x' + K x + sum_e W_e f_e(W_e^T x) = excitation(t) + static loads, x periodic.

    harmonics: H (0..H) or a list; samples: time samples per period of the AFT (None: the
    scenes' default, max(64, 4 H + 1), and for friction and gaps what their laws need).
    M, K, C: numpy arrays or scipy.sparse matrices (used dense); C None is no damping.
    """

    def __init__(self, M, K, C=None, harmonics=7, samples=None, sectors=1, engine_order=0, M_next=None, C_next=None,
                 K_next=None):
        self.M = arrays.square_matrix(M, "M")
        n = self.M.shape[0]
        self.K = arrays.square_matrix(K, "K", n)
        self.C = np.zeros((n, n)) if C is None else arrays.square_matrix(C, "C", n)
        self.harmonics = arrays.harmonic_list(harmonics)
        self._cyclic(sectors, engine_order, M_next, C_next, K_next)
        self._check_physics()
        for matrix in (self.M, self.K, self.C, self.M_next, self.C_next, self.K_next):
            matrix.flags.writeable = False  # the system is built from them: a change would not reach it
        # As a scene's `samples` (ForcedResponseScene.cpp): 2 H + 1 resolve harmonic H, 2^16 at most.
        H = max(self.harmonics)
        self._samples = None if samples is None else arrays.integer(
            samples, "samples", 2 * H + 1, arrays.MAX_SAMPLES, f" time samples per period (2 H + 1 resolve harmonic H = {H})")
        self._elements = []  # (element, W, W_next)
        self.element_names = []
        self._excitation = []  # (dof, harmonic, cos, sin)
        self._static = []  # (dof, value)
        self._built = None  # the compiled system, made again after any change

    def _cyclic(self, sectors, engine_order, M_next, C_next, K_next):
        """One sector of a ring of `sectors` under a travelling wave of `engine_order`: sector
        j's equation holds A x_j + A_next x_{j+1} + A_next^T x_{j-1} (A: M, C, K); only sector 0
        is solved, harmonic h on nodal diameter h EO mod N (HarmonicBalanceSystem.hpp)."""
        if not isinstance(sectors, (int, np.integer)) or sectors < 1:
            raise InputError("sectors", f"{sectors!r}: must be an int >= 1 (1: not cyclic)")
        self.sectors, self.engine_order = int(sectors), arrays.integer(engine_order, "engine_order")
        n, nxt = self.num_dofs, {}
        for name, value in (("M_next", M_next), ("C_next", C_next), ("K_next", K_next)):
            if value is not None and self.sectors == 1:
                raise InputError(name, "couples a sector to the next one: give sectors >= 2 for a cyclic system")
            nxt[name] = np.zeros((n, n)) if value is None else arrays.square_matrix(value, name, n)
        if self.sectors == 1 and engine_order:
            raise InputError("engine_order", "is for cyclic systems (sectors >= 2)")
        self.M_next, self.C_next, self.K_next = nxt["M_next"], nxt["C_next"], nxt["K_next"]

    def _check_physics(self):
        """What a scene refuses (ForcedResponseScene.cpp): M and K not symmetric, a mass matrix
        not positive definite, damping whose symmetric part generates energy; a cyclic sector's
        own M or C only without next-sector coupling of the kind."""
        for name, A in (("M", self.M), ("K", self.K)):
            if np.linalg.norm(A - A.T) > 1e-12 * np.linalg.norm(A):
                raise InputError(name, "must be symmetric")
        if not self.M_next.any() and np.linalg.eigvalsh(self.M).min() <= 0:
            raise InputError("M", "must be positive definite (a mass matrix: every DOF carries mass)")
        if not self.C_next.any():
            symmetric = 0.5 * (self.C + self.C.T)
            lowest = np.linalg.eigvalsh(symmetric).min()
            if lowest < -1e-12 * np.linalg.norm(symmetric):
                raise InputError("C", f"generates energy: its symmetric part has the eigenvalue {lowest} < 0")

    @property
    def num_dofs(self):
        return self.M.shape[0]

    @property
    def samples(self):
        return self._core().samples

    @property
    def num_coefficients(self):
        return sum(1 if h == 0 else 2 for h in self.harmonics)

    @property
    def num_unknowns(self):
        return self.num_dofs * self.num_coefficients

    def add_element(self, element, dofs=None, between=None, W=None, W_next=None, name=None):
        """Attaches `element` where it acts, by one of:
        dofs: one DOF per element coordinate, against ground (w_j = x[dofs[j]]);
        between: (dofs_a, dofs_b), w_j = x[dofs_a[j]] - x[dofs_b[j]] (a scalar element: (a, b));
        W: the n x dimension matrix of w = W^T x (a scalar element: a direction of n entries);
        and, for a cyclic system, W_next: w += W_next^T x_next, the next sector's motion (an
        element across the sector boundary). `name` (default "element<i>") is what a trace in one
        of its parameters names: forced_response(parameter="<name>/mu", ...); several elements
        may share one. Returns self (calls chain)."""
        if not isinstance(element, Element):
            raise InputError("element", f"must be one of cyclone's elements (cyclone.Jenkins, ...), got {element!r}")
        if sum(arg is not None for arg in (dofs, between, W)) != 1:
            raise InputError("add_element", "give exactly one of dofs, between or W")
        n, d = self.num_dofs, element.dimension
        if W is not None:
            W = arrays.matrix(W, "W", n, d)
        else:
            key = "dofs" if dofs is not None else "between"
            plus, minus = (dofs, []) if dofs is not None else self._pair(between)
            plus = self._dof_list(plus, key, d)
            minus = [] if dofs is not None else self._dof_list(minus, key, d)
            W = np.zeros((n, d))
            for j, dof in enumerate(plus):
                W[dof, j] += 1.0
            for j, dof in enumerate(minus):
                W[dof, j] -= 1.0
        if W_next is not None:
            if self.sectors == 1:
                raise InputError("W_next", "joins a sector to the next one: the system must be cyclic (sectors >= 2)")
            W_next = arrays.matrix(W_next, "W_next", n, d)
        else:
            W_next = np.zeros((n, 0))
        for j in range(d):
            if not W[:, j].any() and not (W_next.size and W_next[:, j].any()):
                raise InputError("W", f"coordinate {j} of the element is zero on every DOF: it would never act")
        self._elements.append((element, W, W_next))
        self.element_names.append(str(name) if name is not None else f"element{len(self._elements) - 1}")
        self._built = None
        return self

    def add_excitation(self, dof, harmonic=1, cos=0.0, sin=0.0):
        """f = cos * cos(h omega t) + sin * sin(h omega t) on `dof` (times the force scale)."""
        self._excitation.append((self._dof(dof, "dof"), arrays.integer(harmonic, "harmonic", 0),
                                 arrays.finite_number(cos, "cos"), arrays.finite_number(sin, "sin")))
        self._built = None
        return self

    def add_static_load(self, dof, value):
        """A constant force the force scale does not multiply (a preload); needs harmonic 0."""
        self._static.append((self._dof(dof, "dof"), arrays.finite_number(value, "value")))
        self._built = None
        return self

    def residual(self, x, omega, force_scale=1.0, jacobian=True, frequency_derivative=False):
        """R(x; omega) = Z(omega) x + F_nl(x) - force_scale F_ex - F_static, and dR/dx
        (num_unknowns square; None when jacobian is False), unscaled, as numpy arrays; with
        frequency_derivative also dR/domega (tmdsimpy's hbm_res: R, dR/dx, dR/dw)."""
        x = arrays.vector(x, "x", self.num_unknowns)
        omega = arrays.finite_number(omega, "omega")
        force_scale = arrays.finite_number(force_scale, "force_scale")
        R, J = self._core().residual(x, omega, force_scale, bool(jacobian))
        if not frequency_derivative:
            return R, J
        return R, J, self._frequency_derivative(x, omega, force_scale)

    def _frequency_derivative(self, x, omega, force_scale):
        """dR/domega, exact to rounding: the linear part K x + omega D C x + omega^2 D^2 M x is a
        quadratic in omega, whose central difference is its derivative whatever the step, and a
        rate-independent element's force (friction, gaps, springs) does not change with omega at
        given coefficients. So not for velocity-dependent elements (their force does)."""
        damper = next((element for element, _, _ in self._elements if element._law().uses_velocity), None)
        if damper is not None:
            raise InputError("frequency_derivative", f"{type(damper).__name__}'s force depends on the velocity, so "
                                                     "on the frequency: dR/domega is not available with it")
        step = 1e-2 * max(abs(omega), 1.0)
        plus, _ = self._core().residual(x, omega + step, force_scale, False)
        minus, _ = self._core().residual(x, omega - step, force_scale, False)
        return (plus - minus) / (2 * step)

    def linearized_solution(self, omega, force_scale=1.0):
        """The response linearised about rest (stuck contacts and closed gaps keep their
        stiffness): one Newton step from x = 0, a start for a solver of one's own."""
        return self._core().linearized_solution(arrays.finite_number(omega, "omega"),
                                                arrays.finite_number(force_scale, "force_scale"))

    def max_abs(self, x, dof):
        """max over the period of |x_dof(t)| (located between the samples)."""
        return self._core().max_abs(arrays.vector(x, "x", self.num_unknowns), self._dof(dof, "dof"))

    def forced_response(self, start, end, **options):
        """The forced response traced from `start` to `end` of the parameter (the frequency
        in rad/s; or the force scale, the damping scale, an element's parameter at the fixed
        frequency `omega`); the options are cyclone.response.trace_options'.
        Returns a ForcedResponse."""
        settings = trace_options(self, start, end, **options)
        return ForcedResponse(_core.forced_response(self._core(), settings), self.harmonics, self.num_dofs,
                              settings.output_dofs)

    def follow_peak(self, parameter, values, band, locate_optimum=True, **options):
        """The resonance peak followed over `values` of `parameter` ("force_scale",
        "damping_scale" or "<element name>/<parameter>", as forced_response's), a peak
        search per value instead of a frequency curve per value: at values[0] the largest
        peak of a sweep of `band` = (from, to) in rad/s, then each value's from the one
        before; where the followed peak vanishes, the band's largest (marked jump).
        values: strictly monotone, at least 2. locate_optimum: the smallest peak located
        between its grid neighbours (golden section; not over the force scale, whose peak
        grows with it). options: forced_response's force_scale, output_dofs (the first one's
        max |x(t)| is the peak), engine and tolerance (the band's sweep and the searches)
        and steps (the sweep's). Returns a FollowedPeaks; its end says how it ended."""
        if parameter == "omega":
            raise InputError("parameter", "the peak is followed over a parameter other than the frequency "
                                          "(force_scale, damping_scale or '<element name>/<parameter>')")
        values = np.atleast_1d(arrays.dense(values, "values"))
        steps = np.diff(values)
        if values.ndim != 1 or len(values) < 2 or not (np.all(steps > 0) or np.all(steps < 0)):
            raise InputError("values", "must be at least 2 values, strictly increasing or decreasing")
        try:
            low, high = (arrays.finite_number(b, "band") for b in band)
        except (TypeError, ValueError):
            raise InputError("band", f"must be (from, to) in rad/s, got {band!r}") from None
        if not 0 < low < high:
            raise InputError("band", f"({low}, {high}): must be (from, to) with 0 < from < to (rad/s)")
        for key in ("omega", "stability", "harmonics_check"):
            if key in options:
                raise InputError(key, "is not an option of the peak following (the frequency is the band's)")
        settings = trace_options(self, values[0], values[-1], parameter=parameter, omega=np.sqrt(low * high),
                                 stability="never", harmonics_check=False, **options)
        raw = _core.follow_peak(self._core(), settings, [float(v) for v in values], low, high,
                                bool(locate_optimum) and parameter != "force_scale")
        return FollowedPeaks(raw, self.num_dofs, self.num_coefficients)

    def _core(self):
        if self._built is None:
            system = _core.MatrixSystem(self.M, self.C, self.K, self.harmonics, self._default_samples())
            if self.sectors > 1:
                system.set_cyclic(self.sectors, self.engine_order, self.M_next, self.C_next, self.K_next)
            for element, W, W_next in self._elements:
                system.add_element(element._law(), W, W_next)
            for dof, h, c, s in self._excitation:
                system.add_excitation(dof, h, c, s)
            for dof, value in self._static:
                system.add_static_load(dof, value)
            self._built = system
        return self._built

    def _default_samples(self):
        """The scenes' default: max(64, 4 H + 1); for a nonsmooth law (friction, a gap) also
        what it recommends and samples that grow with the harmonics (ForcedResponseScene.cpp)."""
        if self._samples is not None:
            return self._samples
        H = max(self.harmonics)
        samples = max(64, 4 * H + 1)
        for element, _, _ in self._elements:
            recommended = element._law().recommended_samples
            if recommended > 0:
                samples = max(samples, recommended, _core.nonsmooth_samples(self.harmonics))
        return samples

    def _dof(self, dof, key):
        if not isinstance(dof, (int, np.integer)) or not 0 <= dof < self.num_dofs:
            raise InputError(key, f"{dof!r} is not a DOF of the system (0..{self.num_dofs - 1})")
        return int(dof)

    def _dof_list(self, dofs, key, dimension):
        dofs = [dofs] if isinstance(dofs, (int, np.integer)) else list(dofs)
        if len(dofs) != dimension:
            raise InputError(key, f"lists {len(dofs)} DOF(s) for an element of {dimension} coordinate(s)")
        return [self._dof(d, key) for d in dofs]

    @staticmethod
    def _pair(between):
        try:
            a, b = between
        except (TypeError, ValueError):
            raise InputError("between", f"must be a pair (dofs_a, dofs_b), got {between!r}") from None
        return a, b
