"""Damping matrices as the scenes make them from their keys: the same computation
(hbm::modalDamping), so that a script's C is a scene's to the bit."""

from . import _core, arrays


def modal_damping(M, K, ratio):
    """C = M Phi diag(2 ratio w_j) Phi^T M, Phi the M-normalised modes of (K, M): every mode
    damped by `ratio` of critical (a scene's system: modal_damping_ratio; of a cyclic sector,
    its own K and M, without the coupling)."""
    M = arrays.square_matrix(M, "M")
    return _core.modal_damping(M, arrays.square_matrix(K, "K", M.shape[0]), arrays.finite_number(ratio, "ratio"))
