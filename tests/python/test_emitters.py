"""Emitters from Python (docs/emitters.md): the count grows between steps, the arrays follow it,
and a view taken before a step is not valid after it (the count changed)."""

import numpy as np
import pytest

import upf


def tank_with_a_tap():
    return {
        "name": "tap",
        "particle_spacing": 0.04,
        "materials": {"water": {"type": "liquid", "density": 1000}, "walls": {"type": "frozen"}},
        "containers": [{"material": "walls", "min": [0, 0, 0], "max": [0.4, 0.6, 0.4]}],
        "emitters": [{"material": "water", "radius": 0.06, "center": [0.2, 0.5, 0.2],
                      "direction": [0, -1, 0], "speed": 1.5}],
        "time": {"end": 0.3},
    }


def test_the_arrays_follow_the_count_an_emitter_changes():
    sim = upf.Simulation.from_dict(tank_with_a_tap())
    assert (sim.copy("type") == 0).sum() == 0
    before = sim.particles()
    size_before = len(before["position"])
    sim.advance_to(0.2)
    liquid = (sim.copy("type") == 0).sum()
    # D = 1.5 m/s x 0.2 s = 0.3 m: floor(0.3 / 0.04) + 1 = 8 layers of the opening's points.
    assert liquid % 8 == 0 and liquid > 0
    assert len(sim.copy("position")) == size_before + liquid
    with pytest.raises(upf.StaleViewError):
        _ = before["position"]  # views of the arrays before the count changed
    ids = sim.copy("id")
    assert len(np.unique(ids)) == len(ids)
