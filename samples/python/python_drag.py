"""A force written in Python: quadratic air drag on the liquid, F = -1/2 rho_air C_d A |v| v per
particle (A the particle's cross-section, spacing squared), added to the dam break. The run
writes what `upf run` writes; the surge front it prints is slowed by the drag.

    PYTHONPATH=build/release/python /usr/bin/python3 samples/python/python_drag.py \
        [--drag 50] [--end 0.5] [--out out/python_drag]

The drag coefficient is exaggerated (real air barely slows a dam break) so that the effect shows.
"""

import argparse
from pathlib import Path

import numpy as np

import upf

HERE = Path(__file__).resolve().parent
RHO_AIR = 1.2  # kg/m^3


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--scene", default=HERE.parent / "dam_break.json", type=Path)
    parser.add_argument("--drag", type=float, default=50.0, help="drag coefficient C_d")
    parser.add_argument("--end", type=float, default=0.5)
    parser.add_argument("--threads", type=int, default=0)
    parser.add_argument("--out", type=Path, default=Path("out/python_drag"))
    args = parser.parse_args()

    sim = upf.Simulation.from_file(args.scene, threads=args.threads)
    area = sim.spacing ** 2

    def air_drag(p):
        speed = np.linalg.norm(p.velocity, axis=1, keepdims=True)
        return -0.5 * RHO_AIR * args.drag * area * speed * p.velocity

    sim.add_force(air_drag, types=["liquid"])
    summary = sim.run(args.out, end=args.end)
    front = summary["final_probes"].get("surge_front")
    print(f"{summary['steps']} steps to t = {summary['simulated_time_s']:.3f} s; surge front "
          f"{front} m (C_d = {args.drag:g}) -> {args.out}")


if __name__ == "__main__":
    main()
