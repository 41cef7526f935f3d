"""upf from Python when things go wrong: a thread count out of range, Ctrl-C inside a Python
force, a run that cannot write, a Python solver returning the wrong type, and a callback that
steps its own simulation. Each leaves a clear error and, where the docs promise it, a simulation
that goes on."""

import json
import os
import re
import signal
import time

import numpy as np
import pytest

import upf
from conftest import free_particle_scene


def small_block_scene():
    """A block of 125 liquid particles falling in a tank: neighbours, pressure and a reorder in
    the first step, so that undoing a step has something to undo."""
    scene = free_particle_scene(fixed_dt=0.001)
    scene["fluid_blocks"] = [{"material": "water", "min": [0.1, 0.1, 0.1], "max": [0.2, 0.2, 0.2]}]
    scene["containers"][0]["max"] = [0.3, 0.4, 0.3]
    return scene


def by_id(sim, name):
    return sim.copy(name, order="id")


@pytest.mark.parametrize("threads", [-1, 1025, 100000])
def test_threads_outside_0_to_1024_are_a_scene_error(threads, tmp_path):
    # 100000 threads crashed the first step; the program caps --threads at 1024.
    with pytest.raises(upf.SceneError, match="threads"):
        upf.Simulation.from_dict(free_particle_scene(), threads=threads)
    scene = tmp_path / "scene.json"
    scene.write_text(json.dumps(free_particle_scene()))
    with pytest.raises(upf.SceneError, match="threads"):
        upf.compare(scene, solvers=["pcisph"], out=tmp_path / "cmp", end=0.01, threads=threads)
    assert not (tmp_path / "cmp").exists()


def interrupted_once(how):
    """A slow force that Ctrl-C interrupts on its first call (raised, or a real SIGINT that
    Python turns into KeyboardInterrupt while the force sleeps); then no force."""
    calls = []

    def slow(p):
        calls.append(p.time)
        if len(calls) == 1:
            if how == "raise":
                raise KeyboardInterrupt
            os.kill(os.getpid(), signal.SIGINT)
            time.sleep(5)  # the signal's handler raises KeyboardInterrupt here
            raise AssertionError("SIGINT did not interrupt the force")
        return np.zeros(3)

    return slow


@pytest.mark.parametrize("how", ["raise", "sigint"])
def test_ctrl_c_in_a_python_force_undoes_the_step_and_the_simulation_goes_on(how):
    sim = upf.Simulation.from_dict(small_block_scene())
    sim.add_force(interrupted_once(how), name="slow")
    position, velocity = by_id(sim, "position"), by_id(sim, "velocity")
    with pytest.raises(KeyboardInterrupt):
        sim.step()
    assert (sim.time, sim.step_count) == (0.0, 0)
    np.testing.assert_array_equal(by_id(sim, "position"), position)
    np.testing.assert_array_equal(by_id(sim, "velocity"), velocity)

    sim.step()
    sim.step()
    fresh = upf.Simulation.from_dict(small_block_scene())
    fresh.add_force(lambda p: np.zeros(3), name="slow")
    fresh.step(2)
    assert (sim.time, sim.step_count) == (fresh.time, fresh.step_count)
    for name in ("position", "velocity", "pressure"):
        np.testing.assert_array_equal(by_id(sim, name), by_id(fresh, name), err_msg=name)


class Falling(upf.Solver):
    """Free fall of its liquid particles (symplectic Euler); Ctrl-C on its first step, once it
    has moved them, when `interrupt` is set."""

    interrupt = False

    def step(self, world, dt):
        liquid = world["type"] == upf.PARTICLE_TYPES["liquid"]
        world["velocity"][liquid] += np.array(world.gravity) * dt
        world["position"][liquid] += world["velocity"][liquid] * dt
        if self.interrupt:
            self.interrupt = False
            raise KeyboardInterrupt


def test_ctrl_c_after_a_python_solver_moved_particles_puts_them_back():
    def falling(interrupt):
        registry = upf.Registry()

        def make(params, materials):
            solver = Falling(params, materials)
            solver.interrupt = interrupt
            return solver

        registry.add_solver("falling", make)
        scene = small_block_scene()
        scene["materials"]["water"]["solver"] = "falling"
        return upf.Simulation.from_dict(scene, registry=registry)

    sim, fresh = falling(True), falling(False)
    position = by_id(sim, "position")
    with pytest.raises(KeyboardInterrupt):
        sim.step()
    np.testing.assert_array_equal(by_id(sim, "position"), position)
    sim.step(3)
    fresh.step(3)
    assert (sim.time, sim.step_count) == (fresh.time, fresh.step_count)
    np.testing.assert_array_equal(by_id(sim, "position"), by_id(fresh, "position"))
    np.testing.assert_array_equal(by_id(sim, "velocity"), by_id(fresh, "velocity"))


def test_ctrl_c_in_a_python_force_during_a_run_keeps_the_steps_before_it(tmp_path):
    calls = []

    def force(p):
        calls.append(p.time)
        if len(calls) == 3:
            raise KeyboardInterrupt
        return np.zeros(3)

    sim = upf.Simulation.from_dict(small_block_scene())
    sim.add_force(force)
    with pytest.raises(KeyboardInterrupt):
        sim.run(tmp_path / "out", end=0.01, frames=False)
    assert sim.step_count == 2
    sim.advance_to(0.01)
    assert sim.step_count == 10


def test_a_run_that_cannot_create_its_folder_leaves_the_simulation_usable(tmp_path):
    # Tests run as root, which may write anywhere: a folder under a regular file cannot exist.
    blocker = tmp_path / "a_file"
    blocker.write_text("not a folder")
    sim = upf.Simulation.from_dict(free_particle_scene())
    with pytest.raises(OSError, match="a_file"):
        sim.run(blocker / "out", end=0.02)
    sim.step()
    assert sim.step_count == 1
    summary = sim.run(tmp_path / "out", end=0.02, frames=False)
    assert summary["status"] == "completed"
    assert sim.time == pytest.approx(0.02)


def test_a_run_never_deletes_what_it_did_not_write(tmp_path):
    # docs/robustness.md, "What a run may delete": a folder of the user's files is refused (the
    # simulation stays usable); overwrite=True writes beside them and removes none.
    out = tmp_path / "out"
    (out / "render").mkdir(parents=True)
    (out / "render" / "holiday.mp4").write_text("mine")
    (out / "scene.json").write_text("mine")
    sim = upf.Simulation.from_dict(free_particle_scene())
    with pytest.raises(upf.SceneError, match="no upf run recorded"):
        sim.run(out, end=0.02)
    summary = sim.run(out, end=0.02, overwrite=True)
    assert summary["status"] == "completed"
    assert (out / "render" / "holiday.mp4").read_text() == "mine"
    assert (out / "scene.json").read_text() == "mine"
    assert "f upf_scene.json\n" in (out / "upf_manifest.txt").read_text()


class Lazy(upf.Solver):
    """Moves nothing; its max_time_step and stats return what the test asks for."""

    dt = 0.001
    stats_value = {}

    def max_time_step(self, world):
        return Lazy.dt

    def step(self, world, dt):
        pass

    def stats(self):
        return Lazy.stats_value


@pytest.mark.parametrize("method,value,error,expected", [
    ("max_time_step", "soon", TypeError, "must be a number"),
    ("max_time_step", None, TypeError, "must be a number"),
    ("max_time_step", -1.0, ValueError, "above 0"),
    ("stats", [("iterations", 3)], TypeError, "must return a dict"),
    ("stats", {"iterations": "many"}, TypeError, r"stats\(\)\['iterations'\] must be an int"),
    ("stats", {"max_density_error": "small"}, TypeError,
     r"\['max_density_error'\] must be a number"),
])
def test_a_python_solvers_bad_return_value_names_the_solver_and_the_method(
        monkeypatch, method, value, error, expected):
    monkeypatch.setattr(Lazy, "dt" if method == "max_time_step" else "stats_value", value)
    registry = upf.Registry()
    registry.add_solver("lazy", lambda params, materials: Lazy(params, materials))
    scene = free_particle_scene(fixed_dt=0)  # the solvers' max_time_step sets the step
    scene["materials"]["water"]["solver"] = "lazy"
    sim = upf.Simulation.from_dict(scene, registry=registry)
    with pytest.raises(error) as raised:
        sim.step()
    message = str(raised.value)
    assert "solver 'lazy'" in message and f"{method}()" in message, message
    assert re.search(expected, message), message


@pytest.mark.parametrize("call", ["step", "advance_to", "run"])
def test_a_force_that_steps_its_own_simulation_is_refused(call, tmp_path):
    sim = upf.Simulation.from_dict(free_particle_scene())
    again = {"step": lambda: sim.step(), "advance_to": lambda: sim.advance_to(0.05),
             "run": lambda: sim.run(tmp_path / "out", end=0.05)}[call]
    seen = []

    def reentrant(p):
        seen.append(p.time)
        again()
        return np.zeros(3)

    sim.add_force(reentrant)
    with pytest.raises(RuntimeError, match=f"Simulation.{call}.*middle of a step"):
        sim.step()
    assert len(seen) == 1, "refused, not recursed"
