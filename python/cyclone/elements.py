"""The nonlinear elements, as tmdsimpy's and pyHarm's users attach them: an object with
its law's parameters, placed on the system by DOF lists or direction vectors
(HarmonicBalance.add_element). Each acts on coordinates w = W^T x and returns its force
through W; its coordinates are listed in its docstring."""

from dataclasses import dataclass

from . import _core
from .errors import InputError


class Element:
    """Base of the elements: `dimension` coordinates, the law made by `_law()`. The law is
    made once on construction, so a parameter out of range stops the script there, with
    the element's class as the key (the library names its own class, e.g. JenkinsElement)."""

    dimension = 1

    def __post_init__(self):
        try:
            self._law()
        except InputError as error:
            raise InputError(type(self).__name__, error.problem) from None

    def _law(self):
        raise NotImplementedError


@dataclass(frozen=True)
class CubicSpring(Element):
    """f = k3 w^3 (Duffing; k3 < 0 softens). One coordinate."""

    k3: float

    def _law(self):
        return _core.cubic_spring(self.k3)


@dataclass(frozen=True)
class UnilateralSpring(Element):
    """A contact that opens: f = k max(w - gap, 0); gap < 0 is an interference. One coordinate."""

    k: float
    gap: float = 0.0

    def _law(self):
        return _core.unilateral_spring(self.k, self.gap)


@dataclass(frozen=True)
class QuadraticDamper(Element):
    """f = c2 w' |w'|. One coordinate."""

    c2: float

    def _law(self):
        return _core.quadratic_damper(self.c2)


@dataclass(frozen=True)
class Jenkins(Element):
    """A spring kt in series with a Coulomb slider of slip force `slip_force` (mu N). One coordinate."""

    kt: float
    slip_force: float

    def _law(self):
        return _core.jenkins(self.kt, self.slip_force)


@dataclass(frozen=True)
class Friction2D(Element):
    """Friction with normal load variation and separation: coordinates [t, n] (tangential
    slip, normal approach, positive pressing). N = max(preload + kn n, 0), the slider's limit
    mu N; kn = 0 holds N at the preload."""

    kt: float
    kn: float
    mu: float
    preload: float = 0.0
    dimension = 2

    def _law(self):
        return _core.friction_contact(1, self.kt, self.kn, self.mu, self.preload)


@dataclass(frozen=True)
class Friction3D(Element):
    """As Friction2D with two tangential directions (a circular friction limit): coordinates [t1, t2, n]."""

    kt: float
    kn: float
    mu: float
    preload: float = 0.0
    dimension = 3

    def _law(self):
        return _core.friction_contact(2, self.kt, self.kn, self.mu, self.preload)
