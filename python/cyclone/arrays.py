"""numpy (and scipy.sparse) arguments checked and converted, each refusal naming the
argument: the library takes dense float64 arrays, and a wrong shape or a NaN must stop a
script where it was given, not as a residual of NaNs many calls later."""

import numpy as np

from .errors import InputError


def dense(value, name):
    """A float64 ndarray of value: scipy.sparse matrices made dense, any order or stride."""
    if hasattr(value, "toarray") and hasattr(value, "nnz"):  # scipy.sparse, without importing scipy
        value = value.toarray()
    if np.iscomplexobj(value):
        raise InputError(name, "is complex: the library takes real matrices (a complex one's imaginary part would be dropped)")
    try:
        array = np.array(value, dtype=np.float64)  # a copy: later changes to the caller's array do not leak in
    except (TypeError, ValueError) as error:
        raise InputError(name, f"is not an array of numbers ({error})") from None
    if not np.all(np.isfinite(array)):
        bad = tuple(int(i) for i in np.argwhere(~np.isfinite(array))[0])
        raise InputError(name, f"entry {bad if len(bad) > 1 else bad[0]} is {array[bad]}: entries must be finite")
    return array


def square_matrix(value, name, n=None):
    """An n x n matrix (n: the first matrix's size when None)."""
    array = dense(value, name)
    if array.ndim != 2 or array.shape[0] != array.shape[1]:
        raise InputError(name, f"must be a square matrix, got shape {array.shape}")
    if n is not None and array.shape[0] != n:
        raise InputError(name, f"is {array.shape[0]} x {array.shape[1]}; the system has {n} DOFs (M is {n} x {n})")
    return array


def vector(value, name, size):
    """A vector of `size` entries (a column or row matrix of that size is accepted)."""
    array = dense(value, name)
    if array.size != size or (array.ndim == 2 and 1 not in array.shape) or array.ndim > 2:
        raise InputError(name, f"must have {size} entries, got shape {array.shape}")
    return array.reshape(size)


def matrix(value, name, rows, cols):
    """A rows x cols matrix; a vector of `rows` entries when cols is 1."""
    array = dense(value, name)
    if cols == 1 and array.ndim == 1:
        array = array.reshape(rows if array.size == rows else -1, 1)
    if array.shape != (rows, cols):
        raise InputError(name, f"must be {rows} x {cols}, got shape {array.shape}")
    return array


def finite_number(value, name):
    try:
        number = float(value)
    except (TypeError, ValueError):
        raise InputError(name, f"must be a number, got {value!r}") from None
    if not np.isfinite(number):
        raise InputError(name, f"must be finite, got {number}")
    return number


MAX_SAMPLES = 1 << 16  # the scenes' largest sample count per period (kMaxSamples)


def integer(value, name, low=None, high=None, why=""):
    """value as an int (an integral number; not a bool), within low..high where given:
    an InputError naming `name` otherwise."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, np.integer, float, np.floating)) or \
            not float(value).is_integer():
        raise InputError(name, f"must be an integer, got {value!r}")
    number = int(value)
    if (low is not None and number < low) or (high is not None and number > high):
        bounds = f">= {low}" if high is None else f"in {low}..{high}"
        raise InputError(name, f"{number}: must be {bounds}{why}")
    return number


def harmonic_list(harmonics):
    """H (an int) means 0..H, as the scenes' `harmonics: [H]`; otherwise the list itself, of
    distinct integers >= 0 (1.5 is refused, not read as 1)."""
    if isinstance(harmonics, (int, np.integer)) and not isinstance(harmonics, (bool, np.bool_)):
        if harmonics < 1:
            raise InputError("harmonics", f"{harmonics}: needs at least harmonic 1 (an int H means 0..H)")
        return list(range(int(harmonics) + 1))
    try:
        listed = [integer(h, "harmonics") for h in harmonics]
    except TypeError:
        raise InputError("harmonics", f"must be an int H (0..H) or a list of harmonics, got {harmonics!r}") from None
    if not listed or min(listed) < 0 or len(set(listed)) != len(listed):
        raise InputError("harmonics", f"{listed}: a list of distinct harmonics >= 0, not empty")
    return listed
