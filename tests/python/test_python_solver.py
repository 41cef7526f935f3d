"""A solver written in Python (samples/python/toy_wcsph.py), registered by name, passes the
hydrostatic tank as upf's C++ WCSPH does, and runs in upf.compare beside the built-ins.

Reference: Pascal's law, p = rho0 g d below the free surface, read as in
tests/physics/hydrostatic_tank.h: slabs one spacing thick from two support radii below the
surface, away from the side walls, pressures averaged over time.
"""

import json

import numpy as np
import pytest

import toy_wcsph
import upf

WIDTH, COLUMN, SPACING = 0.15, 0.3, 0.025
RHO0, G = 1000.0, 9.81


def tank(solver):
    return {
        "name": "small_tank",
        "gravity": [0, -G, 0],
        "particle_spacing": SPACING,
        "materials": {
            "water": {"type": "liquid", "density": RHO0, "viscosity": 0.001, "solver": solver},
            "walls": {"type": "frozen"},
        },
        "containers": [{"material": "walls", "min": [0, 0, 0], "max": [WIDTH, 0.4, WIDTH]}],
        "fluid_blocks": [{"material": "water", "min": [0, 0, 0], "max": [WIDTH, COLUMN, WIDTH]}],
        "time": {"end": 0.8, "dt_max": 0.002},
        "output": {"fps": 20},
    }


def slab_pressures(sim, settle, average):
    """(depth, measured / rho0 g d) per slab, and the largest compression at the end."""
    sim.advance_to(settle)
    total, samples = 0.0, 0
    while sim.time < settle + average - 1e-9:
        sim.advance_to(min(sim.time + 0.01, settle + average))
        total = total + sim.copy("pressure")
        samples += 1
    pressure = total / samples
    x = sim.copy("position")
    liquid = sim.copy("type") == upf.PARTICLE_TYPES["liquid"]
    support = 2 * SPACING
    # The free surface: the mean height of the top layer of particles + half a spacing.
    layer = int(round(WIDTH / SPACING)) ** 2
    surface = np.sort(x[liquid, 1])[::-1][:layer].mean() + 0.5 * SPACING
    inner = (liquid & (x[:, 0] > support) & (x[:, 0] < WIDTH - support) & (x[:, 2] > support)
             & (x[:, 2] < WIDTH - support))
    slabs = []
    depth = 2 * support
    while depth <= COLUMN - 2 * support + 1e-9:
        chosen = inner & (np.abs(x[:, 1] - (surface - depth)) <= 0.5 * SPACING)
        assert chosen.sum() > 0, f"no particles at depth {depth}"
        expected = RHO0 * G * (surface - x[chosen, 1]).mean()
        slabs.append((depth, pressure[chosen].mean() / expected))
        depth += support
    return slabs, sim.last_step()["max_density_error"]


@pytest.fixture
def registry():
    r = upf.Registry()
    toy_wcsph.register(r)
    return r


def test_the_python_solver_is_listed_with_its_parameters(registry):
    toy = [s for s in upf.solvers(registry) if s["name"] == "toy_wcsph"]
    assert len(toy) == 1
    params = {p["name"]: p for p in toy[0]["params"]}
    assert params["speed_of_sound"]["unit"] == "m/s"
    assert params["speed_of_sound"]["default"] == 20.0
    assert "toy_wcsph" not in [s["name"] for s in upf.solvers()]  # registries are separate


def test_a_parameter_out_of_range_is_a_scene_error(registry):
    with pytest.raises(upf.SceneError) as error:
        upf.Simulation.from_dict(tank({"name": "toy_wcsph", "speed_of_sound": -3}),
                                 registry=registry)
    assert any("speed_of_sound" in where for where, _ in error.value.problems)


def test_a_periodic_scene_is_refused_for_a_python_solver(registry):
    # Its step is one stage: the periodic images would keep stale values between its passes.
    scene = tank({"name": "toy_wcsph"})
    scene["periodic"] = {"x": [0, WIDTH]}
    sim = upf.Simulation.from_dict(scene, registry=registry)
    with pytest.raises(upf.SceneError) as error:
        sim.advance_to(0.01)  # the world is prepared at its first use
    assert any(where.endswith("/periodic") and "Python solver" in what
               for where, what in error.value.problems)


def test_the_python_wcsph_holds_pascals_law_in_the_tank(registry):
    # c = 10 sqrt(2 g H) keeps WCSPH's compression near 1 % (Becker & Teschner 2007).
    c = 10 * np.sqrt(2 * G * COLUMN)
    sim = upf.Simulation.from_dict(tank({"name": "toy_wcsph", "speed_of_sound": c}),
                                   threads=2, registry=registry)
    slabs, max_error = slab_pressures(sim, settle=0.5, average=0.3)
    print("toy_wcsph", slabs, max_error)
    for depth, ratio in slabs:
        assert abs(ratio - 1) < 0.05, f"depth {depth:.3f} m: p / rho0 g d = {ratio:.4f}"
    assert max_error < 0.03


def test_the_python_wcsph_runs_in_a_comparison(registry, tmp_path):
    scene = tmp_path / "tank.json"
    scene.write_text(json.dumps(tank({"name": "wcsph"})))
    report = upf.compare(scene, solvers=["wcsph", "toy_wcsph"], out=tmp_path / "compare",
                         end=0.05, threads=2, frames=False, registry=registry)
    rows = {row["solver"]: row for row in report["rows"]}
    assert set(rows) == {"wcsph", "toy_wcsph"}
    assert rows["toy_wcsph"]["status"] == "completed"
    assert (tmp_path / "compare" / "toy_wcsph" / "summary.json").exists()
