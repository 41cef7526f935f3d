"""upf: a unified multi-material particle simulation framework, from Python.

    import upf
    sim = upf.Simulation.from_file("samples/dam_break.json", threads=2)
    sim.advance_to(0.5)
    with sim.particles() as p:
        print(p.position[:, 1].max())
    sim.run(out="out/dam_break")          # frames, metrics.csv, probes.csv, summary.json

Stepping follows the scene's frame clock exactly as `upf run` does, so the same scene gives the
same bits from Python and from the command line. See docs/python.md.
"""

import json
import math
import os

import numpy as np

from . import _upf
from .errors import InstabilityError, SceneError, StaleViewError
from .kernels import cubic_spline, cubic_spline_gradient
from .solver import Solver, World
from .views import ParticleArray, Particles

__all__ = [
    "Simulation", "Registry", "Solver", "World", "Particles", "ParticleArray", "SceneError",
    "InstabilityError", "StaleViewError", "solvers", "compare", "cubic_spline",
    "cubic_spline_gradient", "PARTICLE_TYPES",
]

# The particle-type codes in the "type" array.
PARTICLE_TYPES = {"liquid": 0, "rigid": 1, "granular": 2, "frozen": 3}

Registry = _upf.Registry


def _types(types):
    if isinstance(types, str):
        return [types]
    return list(types)


class Simulation:
    """A scene's world, stepped on the scene's frame clock (the steps `upf run` takes)."""

    def __init__(self, core, registry):
        self._core = core
        self._registry = registry

    @classmethod
    def from_file(cls, path, threads=0, solver=None, registry=None, device=None):
        """Loads a scene file; a bad scene raises SceneError naming the file and JSON paths.

        threads: OpenMP threads (0: OpenMP's default). solver: every liquid material's solver
        replaced by this one (as `upf run --solver`). registry: a Registry with Python solvers.
        device: where the steps run, "cpu", "omp" or "cuda" (as `upf run --device`; default:
        the scene's "device" key, else "cpu"); one that cannot run the scene raises SceneError.
        """
        registry = registry or Registry()
        return cls(_upf.Simulation.from_file(os.fspath(path), threads, solver or "", registry,
                                             device or ""),
                   registry)

    @classmethod
    def from_dict(cls, scene, threads=0, solver=None, registry=None, source="<dict>",
                  device=None):
        """Loads a scene given as a dict (the JSON of a scene file); errors name `source`."""
        registry = registry or Registry()
        try:
            text = json.dumps(scene, allow_nan=False)
        except (TypeError, ValueError) as e:
            raise SceneError(f"{source}: {e}", [(source, str(e))]) from None
        return cls(_upf.Simulation.from_text(text, source, threads, solver or "", registry,
                                             device or ""),
                   registry)

    @property
    def name(self):
        return self._core.name

    @property
    def device(self):
        """Where the steps run: "cpu", "omp" or "cuda"."""
        return self._core.device

    @property
    def time(self):
        """Simulated seconds."""
        return self._core.time

    @property
    def step_count(self):
        return self._core.step_count

    @property
    def fps(self):
        return self._core.fps

    @property
    def end_time(self):
        """The scene's time.end."""
        return self._core.end_time

    @property
    def spacing(self):
        return self._core.spacing

    def step(self, n=1):
        """n steps, each towards the next frame time (the steps `upf run` takes)."""
        for _ in range(int(n)):
            self._core.step()

    def advance_to(self, time):
        """Steps until self.time == time, stopping on every frame time on the way."""
        self._core.advance_to(float(time))

    def run(self, out, end=None, frames=True, overwrite=False):
        """Runs from now to `end` (default: the scene's end) into the folder `out`, writing what
        `upf run` writes (frames, metrics.csv, probes.csv, summary.json, upf_scene.json,
        upf_manifest.txt; no checkpoint). Returns summary.json's figures as a dict. A new run
        into `out` removes only what the earlier run there recorded; a non-empty folder no run
        recorded is refused (upf.SceneError) unless `overwrite`, which replaces only the names
        the run writes (docs/robustness.md, "What a run may delete")."""
        return self._core.run(os.fspath(out), end, frames, overwrite)

    def particles(self):
        """The particle arrays as zero-copy NumPy views (upf.Particles), valid until the next
        step, or the end of a `with sim.particles() as p:` block."""
        return Particles(self._core)

    def copy(self, name, order="id"):
        """A copy of a particle array; order="id" sorts it by stable particle id (the same order
        in every step), order="memory" keeps the world's current order."""
        values = np.array(self._core.array(name), copy=True)
        if order == "memory":
            return values
        if order != "id":
            raise ValueError(f"order must be 'id' or 'memory', not {order!r}")
        ids = np.asarray(self._core.array("id"))
        return values[np.argsort(ids, kind="stable")]

    def bodies(self):
        """Every rigid or mesh body now: name, position, orientation (w, x, y, z), velocity,
        angular_velocity, fluid_force (N) and fluid_torque (N m) of the last step."""
        return list(self._core.bodies())

    def set_body_velocity(self, name, velocity, angular_velocity=(0.0, 0.0, 0.0)):
        """Sets a dynamic body's velocity (m/s) and angular velocity (rad/s, world axes, about
        its centre of mass) from now on; KeyError for an unknown name, ValueError for a static
        or kinematic body."""
        self._core.set_body_velocity(name, tuple(map(float, velocity)),
                                     tuple(map(float, angular_velocity)))

    def add_force(self, function, types=("liquid",), name=None):
        """Adds a force computed in Python every step on the particles of `types` (liquid,
        rigid). function(p) receives p.position, p.velocity, p.mass, p.id, p.type, p.material
        (arrays of the chosen particles), p.time and p.dt, and returns their forces in N: an
        array of shape (n, 3), or (3,) for the same force on each. Call before the first step."""
        name = name or getattr(function, "__name__", "python_force")
        self._core.add_force(name, function, _types(types))

    def last_step(self):
        """The last step's dt, solver iterations and density errors, and wall ms per stage."""
        return self._core.last_step()

    def stage_names(self):
        return list(self._core.stage_names())

    def __len__(self):
        return self._core.size()

    def __repr__(self):
        return f"<upf.Simulation {self.name!r} t={self.time:.6g} s, step {self.step_count}>"


def solvers(registry=None):
    """Every solver scenes may name: name, type, summary, reference, params (name, unit,
    default, min, max, description)."""
    return list((registry or Registry()).solvers())


def compare(scene, solvers=None, out="out/compare", end=None, threads=0, frames=True,
            registry=None):
    """Runs `scene` once per solver (default: every solver of its liquid's type) into out/<solver>/
    and writes the report (report.md, report.html, report.json, plots) as `upf compare` does.
    Returns report.json as plain Python data."""
    return _upf.compare(os.fspath(scene), list(solvers or []), os.fspath(out), end, threads,
                        frames, registry or Registry())
