"""Solvers written in Python: derive from upf.Solver, register it by name on a upf.Registry, and
scenes name it like any built-in ("solver": {"name": "my_solver"}); upf.compare runs it beside
the others. See docs/python.md and samples/python/toy_wcsph.py.
"""

import math

from .views import ParticleArray


class World:
    """The world during one call of a Python solver (prepare, max_time_step, step).

    Its arrays are NumPy views of the world's memory without copies, valid during that call only:
    keep handles and names between calls, never arrays.
    """

    def __init__(self, handle):
        self._handle = handle

    # The guard of the views made from this world.
    def valid(self):
        return self._handle.valid

    def why(self):
        return ("this array came from a world handle that was valid only during one solver call: "
                "take arrays again in each call")

    def array(self, name):
        """A particle array or field by name (position, velocity, mass, type, ..., pressure)."""
        return ParticleArray.over(self._handle.array(name), self)

    def __getitem__(self, name):
        return self.array(name)

    @property
    def array_names(self):
        return list(self._handle.array_names)

    @property
    def size(self):
        return self._handle.size

    @property
    def time(self):
        return self._handle.time

    @property
    def spacing(self):
        return self._handle.spacing

    @property
    def support_radius(self):
        return self._handle.support_radius

    @property
    def gravity(self):
        return self._handle.gravity

    @property
    def materials(self):
        """Every material: name, kind, type, solver, params and solver_params (dicts)."""
        return self._handle.materials

    def declare_scalar(self, name, init=0.0, exported=False):
        """A per-particle scalar field (call in prepare); exported fields go into frames."""
        self._handle.declare_scalar(name, init, exported)

    def declare_vector(self, name, exported=False):
        """A per-particle 3-vector field (call in prepare), zero to start with."""
        self._handle.declare_vector(name, exported)

    def request_neighbours(self, query, target, radius=0.0):
        """Neighbour lists from `query` types to `target` types (call in prepare): a handle."""
        return self._handle.request_neighbours(list(query), list(target), radius)

    def neighbours(self, handle):
        """(offsets, indices): particle i's neighbours are indices[offsets[i]:offsets[i + 1]]."""
        offsets, indices = self._handle.neighbours(handle)
        return ParticleArray.over(offsets, self), ParticleArray.over(indices, self)

    def coupling(self, name):
        """A coupling array ("boundary_force", "liquid_force") in N per particle, or None when
        nothing in this scene reads it (framework/world/coupling.h)."""
        array = self._handle.coupling(name)
        return None if array is None else ParticleArray.over(array, self)


class Solver:
    """Base class of solvers written in Python.

    The factory registered with Registry.add_solver(name, factory, ...) is called as
    factory(params, materials): the solver's parameters (a dict, defaults filled in and ranges
    checked) and the material ids it moves. Override:
      prepare(world)         declare fields, request neighbour lists (once, before stepping)
      max_time_step(world)   the largest stable step now (default: no limit)
      step(world, dt)        advance the solver's particles by dt
      stats()                {"iterations", "avg_density_error", "max_density_error"} (optional)
    """

    def __init__(self, params=None, materials=()):
        self.params = dict(params or {})
        self.materials = list(materials)

    def prepare(self, world):
        pass

    def max_time_step(self, world):
        return math.inf

    def step(self, world, dt):
        raise NotImplementedError("a upf.Solver must define step(world, dt)")

    def stats(self):
        return {}
