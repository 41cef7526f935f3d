"""upf from Python: loading, stepping on the frame clock, zero-copy views and their revocation,
Python forces, errors, and bitwise agreement with `upf run`."""

import filecmp
import json
import subprocess

import numpy as np
import pytest

import upf
from conftest import free, free_particle_scene

G = 9.81


def test_a_free_particle_falls_as_symplectic_euler_says():
    # v_n = -g n dt, y_n = y0 - g dt^2 n (n + 1) / 2 (the integrator every fluid solver uses).
    sim = upf.Simulation.from_dict(free_particle_scene(fixed_dt=0.001))
    y0 = float(free(sim, "position")[1])
    sim.advance_to(0.05)
    n, dt = sim.step_count, 0.001
    assert n == 50
    assert sim.time == 0.05
    y = float(free(sim, "position")[1])
    assert y == pytest.approx(y0 - G * dt * dt * n * (n + 1) / 2, rel=0, abs=2e-6)


def test_writing_through_a_view_changes_the_next_step():
    sim = upf.Simulation.from_dict(free_particle_scene(fixed_dt=0.001))
    with sim.particles() as p:
        i = np.flatnonzero(p.type == 0)[0]
        x0 = p.position[i].copy()
        p.velocity[i] = (2.0, 0.0, 0.0)
    sim.step()
    x1 = free(sim, "position")
    assert x1[0] - x0[0] == pytest.approx(2.0 * 0.001, rel=1e-5)


def test_a_view_goes_stale_when_the_world_steps():
    sim = upf.Simulation.from_dict(free_particle_scene())
    p = sim.particles()
    position = p.position
    i = np.flatnonzero(p.type == 0)[0]
    column = position[:, 1]  # a slice is a view: guarded too
    copied = position[[i]]  # a fancy index copies: the copy is the user's
    assert float(column[i]) == pytest.approx(1.01)
    sim.step()
    for stale in (lambda: position[0], lambda: column + 1, lambda: np.sum(position),
                  lambda: repr(position), lambda: p["velocity"]):
        with pytest.raises(upf.StaleViewError):
            stale()
    with pytest.raises(upf.StaleViewError):
        position[0] = (0, 0, 0)
    assert copied.shape == (1, 3)  # still readable
    with sim.particles() as q:
        velocity = q.velocity
        assert velocity[np.flatnonzero(q.type == 0)[0], 1] < 0
    with pytest.raises(upf.StaleViewError, match="closed"):
        velocity[0]


def test_the_routing_arrays_are_read_only():
    sim = upf.Simulation.from_dict(free_particle_scene())
    with sim.particles() as p:
        for name in ("id", "type", "material", "body", "boundary_volume"):
            with pytest.raises(ValueError):
                p[name][0] = 1
        with pytest.raises(KeyError, match="there are: position"):
            p["densty"]


def test_a_python_force_against_gravity_keeps_a_particle_at_rest():
    sim = upf.Simulation.from_dict(free_particle_scene())
    calls = []

    def lift(p):
        calls.append(len(p.mass))
        force = np.zeros((len(p.mass), 3))
        force[:, 1] = p.mass * G
        return force

    sim.add_force(lift, types=["liquid"])
    y0 = float(free(sim, "position")[1])
    sim.advance_to(0.1)
    assert calls and all(c == 1 for c in calls)
    assert abs(float(free(sim, "position")[1]) - y0) < 1e-5  # free fall: 0.049 m
    assert np.abs(free(sim, "velocity")).max() < 1e-4  # free fall: 0.98 m/s


def test_a_uniform_python_force_accelerates_as_newton_says():
    # F = m a along x: x_n - x_0 = a dt^2 n (n + 1) / 2 with symplectic Euler.
    sim = upf.Simulation.from_dict(free_particle_scene(fixed_dt=0.001))
    sim.add_force(lambda p: np.array([3.0 * p.mass[0], 0.0, 0.0]), name="push")
    x0 = float(free(sim, "position")[0])
    sim.advance_to(0.04)
    n = sim.step_count
    assert float(free(sim, "position")[0]) - x0 == pytest.approx(
        3.0 * 1e-6 * n * (n + 1) / 2, rel=1e-4)
    assert "push" in sim.stage_names()


def test_forces_come_before_the_first_step():
    sim = upf.Simulation.from_dict(free_particle_scene())
    sim.step()
    with pytest.raises(upf.SceneError, match="has started"):
        sim.add_force(lambda p: np.zeros(3))
    with pytest.raises(ValueError, match="unknown particle type 'water'"):
        upf.Simulation.from_dict(free_particle_scene()).add_force(lambda p: 0, types="water")
    with pytest.raises(upf.SceneError, match="granular"):
        upf.Simulation.from_dict(free_particle_scene()).add_force(lambda p: 0, types="granular")


def test_an_exception_in_a_force_reaches_the_caller_and_stops_the_simulation():
    sim = upf.Simulation.from_dict(free_particle_scene())

    def broken(p):
        return 1 / 0

    sim.add_force(broken)
    with pytest.raises(ZeroDivisionError):
        sim.step()
    with pytest.raises(RuntimeError, match="cannot go on"):
        sim.step()


def test_a_force_of_the_wrong_shape_is_named():
    sim = upf.Simulation.from_dict(free_particle_scene())
    sim.add_force(lambda p: np.zeros((2, 2)), name="wrong")
    with pytest.raises(ValueError, match=r"force 'wrong' must return an array of shape \(1, 3\)"):
        sim.step()


def test_bad_scenes_raise_scene_errors_with_json_paths(tmp_path):
    scene = free_particle_scene()
    scene["particle_spacing"] = -1
    scene["materials"]["water"]["density"] = "heavy"
    with pytest.raises(upf.SceneError) as error:
        upf.Simulation.from_dict(scene, source="my_scene")
    wheres = [where for where, _ in error.value.problems]
    assert any("particle_spacing" in w for w in wheres), wheres
    assert any("/materials/water/density" in w for w in wheres), wheres
    with pytest.raises(upf.SceneError, match="missing.json"):
        upf.Simulation.from_file(tmp_path / "missing.json")
    broken = tmp_path / "broken.json"
    broken.write_text('{"name": "x", ')
    with pytest.raises(upf.SceneError, match="broken.json"):
        upf.Simulation.from_file(broken)
    with pytest.raises(upf.SceneError, match="no_such_solver"):
        upf.Simulation.from_dict(free_particle_scene(), solver="no_such_solver")
    with pytest.raises(upf.SceneError):
        upf.Simulation.from_dict({"name": float("nan")})


def test_an_instability_raises_with_the_particle(tmp_path):
    scene = free_particle_scene()
    scene["stability"] = {"max_speed": 0.05}  # exceeded after a few steps of free fall
    sim = upf.Simulation.from_dict(scene)
    with pytest.raises(upf.InstabilityError) as error:
        sim.advance_to(0.1)
    assert error.value.quantity.startswith("speed")
    assert error.value.particle_id == int(free(sim, "id"))


def test_the_registry_lists_solvers_with_units():
    names = {s["name"]: s for s in upf.solvers()}
    assert {"pcisph", "wcsph", "sph", "dfsph", "iisph", "dem_linear"} <= set(names)
    eta = {p["name"]: p for p in names["pcisph"]["params"]}["eta"]
    assert eta["unit"] == "1" and 0 < eta["default"] < 1


def dam_break(source_dir):
    return source_dir / "samples" / "dam_break.json"


def test_python_steps_are_upf_runs_bit_for_bit(source_dir, upf_executable, tmp_path):
    end = 0.1
    # The command line, two threads.
    subprocess.run([upf_executable, "run", str(dam_break(source_dir)), "--out",
                    str(tmp_path / "cli"), "--end", str(end), "--threads", "2", "--quiet"],
                   check=True, capture_output=True)
    # Python's run: the same files.
    sim = upf.Simulation.from_file(dam_break(source_dir), threads=2)
    summary = sim.run(tmp_path / "py", end=end)
    assert summary["status"] == "completed"
    frames = sorted(p.name for p in (tmp_path / "cli" / "frames").iterdir())
    assert frames == sorted(p.name for p in (tmp_path / "py" / "frames").iterdir())
    for name in frames:
        assert filecmp.cmp(tmp_path / "cli" / "frames" / name, tmp_path / "py" / "frames" / name,
                           shallow=False), name
    for name in ("particles.pvd", "probes.csv", "upf_scene.json"):
        assert filecmp.cmp(tmp_path / "cli" / name, tmp_path / "py" / name, shallow=False), name
    # Python stepping, one thread: the final state of the run, bit for bit.
    stepped = upf.Simulation.from_file(dam_break(source_dir), threads=1)
    stepped.advance_to(end)
    assert stepped.step_count == sim.step_count
    for name in ("position", "velocity", "pressure"):
        assert np.array_equal(stepped.copy(name), sim.copy(name)), name
    cli_summary = json.loads((tmp_path / "cli" / "summary.json").read_text())
    assert cli_summary["steps"] == summary["steps"]


def crate_scene(source_dir):
    """A 0.1 m box of density 500 (0.5 kg) in the air above a shallow pool, falling freely for the
    first 0.1 s."""
    return {
        "name": "crate",
        "gravity": [0, -G, 0],
        "particle_spacing": 0.02,
        "materials": {
            "water": {"type": "liquid", "density": 1000, "viscosity": 0.001},
            "walls": {"type": "frozen"},
            "pine": {"type": "rigid", "density": 500},
        },
        "containers": [{"material": "walls", "min": [0, 0, 0], "max": [0.6, 1.2, 0.3]}],
        "fluid_blocks": [{"material": "water", "min": [0, 0, 0], "max": [0.6, 0.1, 0.3]}],
        "bodies": [{"name": "crate", "material": "pine",
                    "mesh": {"file": str(source_dir / "assets/meshes/unit_box.obj"),
                             "scale": 0.1, "position": [0.3, 0.9, 0.15]}}],
        "time": {"end": 0.2, "dt_max": 0.002},
        "output": {"fps": 50},
    }


def test_bodies_are_readable_and_their_velocity_settable(source_dir):
    sim = upf.Simulation.from_dict(crate_scene(source_dir))
    [crate] = sim.bodies()
    assert crate["name"] == "crate"
    assert crate["position"][1] == pytest.approx(0.9, abs=1e-9)
    sim.advance_to(0.05)
    [crate] = sim.bodies()
    assert crate["velocity"][1] == pytest.approx(-G * 0.05, rel=1e-3)  # free fall
    sim.set_body_velocity("crate", (1.0, 0.0, 0.0))
    x0 = sim.bodies()[0]["position"][0]
    sim.advance_to(0.1)
    [crate] = sim.bodies()
    assert crate["velocity"][0] == pytest.approx(1.0, rel=1e-6)
    assert crate["position"][0] - x0 == pytest.approx(0.05, rel=1e-3)
    with pytest.raises(KeyError, match="there are: crate"):
        sim.set_body_velocity("barrel", (0, 0, 0))


def test_a_python_force_on_a_bodys_particles_holds_it_up(source_dir):
    # The force on each boundary particle is summed into the body's force (Akinci et al. 2012):
    # M g spread over its particles cancels its weight, M = 500 kg/m^3 x (0.1 m)^3.
    sim = upf.Simulation.from_dict(crate_scene(source_dir))
    weight = 500 * 0.1 ** 3 * G
    sim.add_force(lambda p: np.array([0.0, weight / len(p.mass), 0.0]), types=["rigid"])
    sim.advance_to(0.1)
    [crate] = sim.bodies()
    assert abs(crate["velocity"][1]) < 1e-3  # free fall: 0.98 m/s
    assert crate["position"][1] == pytest.approx(0.9, abs=1e-4)


def test_ctrl_c_ends_a_long_advance_between_steps():
    import os
    import signal
    import threading

    scene = free_particle_scene(fixed_dt=1e-4)
    scene["gravity"] = [0, 0, 0]
    sim = upf.Simulation.from_dict(scene)
    threading.Timer(0.3, lambda: os.kill(os.getpid(), signal.SIGINT)).start()
    with pytest.raises(KeyboardInterrupt):
        sim.advance_to(1000.0)  # 10 million steps
    assert 0 < sim.time < 1000.0
    steps = sim.step_count
    sim.step()  # the world is whole: it goes on
    assert sim.step_count == steps + 1


def test_the_device_pipeline_steps_the_cpus_bits(source_dir):
    # --device omp (the GPU pipeline on the CPU's threads) is bitwise the CPU path
    # (docs/device.md): particles and the crate, here dropped into the pool within 0.1 s.
    scene = crate_scene(source_dir)
    scene["bodies"][0]["mesh"]["position"] = [0.3, 0.17, 0.15]
    try:
        omp = upf.Simulation.from_dict(scene, threads=2, device="omp")
    except upf.SceneError as e:
        pytest.skip(f"no device pipeline in this build: {e}")
    cpu = upf.Simulation.from_dict(scene, threads=2)
    assert (omp.device, cpu.device) == ("omp", "cpu")
    omp.advance_to(0.1)
    cpu.advance_to(0.1)
    assert omp.step_count == cpu.step_count
    for name in ("position", "velocity", "density", "pressure"):
        assert np.array_equal(omp.copy(name), cpu.copy(name)), name
    assert omp.bodies() == cpu.bodies()
    assert cpu.bodies()[0]["fluid_force"][1] > 0  # the crate reached the water


def test_grains_on_the_device_pipeline_are_the_cpus_bits(source_dir):
    # DEM on --device omp: contacts, springs and sub-steps give the CPU path's bits.
    path = str(source_dir / "samples" / "sand_pile.json")
    try:
        omp = upf.Simulation.from_file(path, threads=2, device="omp")
    except upf.SceneError as e:
        pytest.skip(f"no device pipeline in this build: {e}")
    cpu = upf.Simulation.from_file(path, threads=2)
    omp.advance_to(0.1)
    cpu.advance_to(0.1)
    assert omp.step_count == cpu.step_count
    for name in ("position", "velocity", "angular_velocity"):
        assert np.array_equal(omp.copy(name), cpu.copy(name)), name
    assert not np.array_equal(cpu.copy("velocity"), np.zeros_like(cpu.copy("velocity")))


def test_a_device_that_cannot_run_the_scene_is_a_scene_error(source_dir):
    with pytest.raises(upf.SceneError, match="device"):
        upf.Simulation.from_dict(crate_scene(source_dir), device="gpu0")
    scene = crate_scene(source_dir)
    scene["device"] = "gpu0"
    with pytest.raises(upf.SceneError, match="<dict>:/device"):
        upf.Simulation.from_dict(scene)
