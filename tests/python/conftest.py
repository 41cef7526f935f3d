"""Shared pieces of the Python tests: paths from ctest's environment, small scenes."""

import os
import sys
from pathlib import Path

import pytest

SOURCE_DIR = Path(os.environ.get("UPF_SOURCE_DIR", Path(__file__).resolve().parents[2]))
sys.path.insert(0, str(SOURCE_DIR / "samples" / "python"))


@pytest.fixture
def source_dir():
    return SOURCE_DIR


@pytest.fixture
def upf_executable():
    path = os.environ.get("UPF_EXECUTABLE")
    if not path:
        pytest.skip("UPF_EXECUTABLE is not set (ctest sets it)")
    return path


def free_particle_scene(fixed_dt=0.001, end=0.1):
    """One liquid particle in free fall in a tall tank, a support radius and more from every wall
    for 0.1 s: no neighbours, no pressure."""
    return {
        "name": "free_particle",
        "gravity": [0, -9.81, 0],
        "particle_spacing": 0.02,
        "materials": {"water": {"type": "liquid", "density": 1000, "viscosity": 0.0},
                      "walls": {"type": "frozen"}},
        "containers": [{"material": "walls", "min": [0, 0, 0], "max": [0.3, 1.1, 0.3]}],
        "fluid_blocks": [{"material": "water", "min": [0.14, 1, 0.14], "max": [0.165, 1.025, 0.165]}],
        "time": {"end": end, "fixed_dt": fixed_dt},
        "output": {"fps": 100},
    }


def free(sim, name):
    """The free particle's value of array `name` (a copy)."""
    return sim.copy(name)[sim.copy("type") == 0][0]
