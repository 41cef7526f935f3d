"""NumPy views of the world's particle arrays, without copies, guarded against going stale.

The world reorders its arrays for memory locality, and a step, run or restore may move or reuse
their memory. So every view is a ParticleArray: a real numpy.ndarray over the world's memory whose
indexing, ufuncs, NumPy functions and printing first ask its guard whether the memory is still
what the view was made for; if not they raise StaleViewError instead of reading moved memory.
Results of arithmetic are ordinary arrays (copies). np.asarray(view) strips the guard: use such
an array only before the next step.
"""

import numpy as np

from .errors import StaleViewError


def _plain(x):
    """x with any ParticleArray (one level into lists and tuples) as a plain ndarray, checked."""
    if isinstance(x, ParticleArray):
        x._check()
        return x.view(np.ndarray)
    if isinstance(x, (list, tuple)):
        return type(x)(_plain(e) for e in x)
    return x


class ParticleArray(np.ndarray):
    """A zero-copy view of a particle array, valid while its guard is."""

    _guard = None

    @classmethod
    def over(cls, array, guard):
        view = array.view(cls)
        view._guard = guard
        return view

    def __array_finalize__(self, obj):
        self._guard = getattr(obj, "_guard", None)

    def _check(self):
        guard = self._guard
        if guard is not None and not guard.valid():
            raise StaleViewError(guard.why())

    def __getitem__(self, key):
        self._check()
        result = super().__getitem__(key)
        # A fancy index copies: the copy is the user's, not the world's.
        if isinstance(result, ParticleArray) and not np.may_share_memory(result, self):
            return result.view(np.ndarray)
        return result

    def __setitem__(self, key, value):
        self._check()
        super().__setitem__(key, _plain(value))

    def __array_ufunc__(self, ufunc, method, *inputs, out=None, **kwargs):
        inputs = _plain(inputs)
        if out is not None:
            kwargs["out"] = _plain(out)
        result = getattr(ufunc, method)(*inputs, **kwargs)
        if out is not None:
            return out[0] if len(out) == 1 else out
        return result

    def __array_function__(self, func, types, args, kwargs):
        args = _plain(args)
        kwargs = {k: _plain(v) for k, v in kwargs.items()}
        return func(*args, **kwargs)

    def __array__(self, dtype=None):
        self._check()
        plain = self.view(np.ndarray)
        return plain if dtype is None else plain.astype(dtype, copy=False)

    def __iter__(self):
        self._check()
        return super().__iter__()

    def __repr__(self):
        self._check()
        return repr(self.view(np.ndarray))

    def __str__(self):
        self._check()
        return str(self.view(np.ndarray))

    def __reduce__(self):
        self._check()
        return self.view(np.ndarray).copy().__reduce__()

    def tolist(self):
        self._check()
        return self.view(np.ndarray).tolist()

    def copy(self, order="C"):
        self._check()
        return np.array(self.view(np.ndarray), order=order, copy=True)


class SimulationGuard:
    """Valid until the simulation steps, runs or restores, or the `with` block closes."""

    def __init__(self, core):
        self._core = core
        self._generation = core.generation
        self._closed = False

    def valid(self):
        return not self._closed and self._core.generation == self._generation

    def close(self):
        self._closed = True

    def why(self):
        if self._closed:
            return "this particle view was closed with its `with` block"
        return ("the simulation has stepped since this particle view was made (its arrays may "
                "have been reordered): take a new one with sim.particles()")


class Particles:
    """The particle arrays of a simulation as zero-copy views (sim.particles()).

    Usable as `with sim.particles() as p:`; its views are revoked when the block ends, and in any
    case when the simulation next steps. Built-ins: position, velocity, mass (writable); type,
    material, id, body, boundary_volume (read-only). Solver fields by name: p["pressure"].
    """

    def __init__(self, core):
        self._core = core
        core.prepare()  # the fields exist from here on: the views' generation is the prepared one
        self._guard = SimulationGuard(core)

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self._guard.close()
        return False

    def names(self):
        return list(self._core.array_names())

    def __getitem__(self, name):
        if not self._guard.valid():
            raise StaleViewError(self._guard.why())
        return ParticleArray.over(self._core.array(name), self._guard)

    def __len__(self):
        return self._core.size()

    position = property(lambda self: self["position"])
    velocity = property(lambda self: self["velocity"])
    mass = property(lambda self: self["mass"])
    type = property(lambda self: self["type"])
    material = property(lambda self: self["material"])
    id = property(lambda self: self["id"])
    body = property(lambda self: self["body"])
    boundary_volume = property(lambda self: self["boundary_volume"])
