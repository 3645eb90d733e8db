"""The exceptions of cyclone: the C++ library's errors as Python ones.

An ``InputError`` names where the input was wrong (``key``: an argument such as ``"M"``,
or what the library names, such as ``"excitation"`` or ``"friction contact"``) apart from
what was wrong (``problem``), so that a script can react to the key without parsing text.
"""


class InputError(ValueError):
    """Bad input: ``key`` says where, ``problem`` what; str() reads "<key>: <problem>"."""

    def __init__(self, key, problem):
        super().__init__(f"{key}: {problem}")
        self.key = key
        self.problem = problem

    def __reduce__(self):  # pickles (multiprocessing) with both parts
        return (type(self), (self.key, self.problem))


class SolverError(RuntimeError):
    """A numerical failure (no convergence, a singular matrix), with the reason."""
