"""A parameter sweep from Python: PCISPH's stopping tolerance eta against wall time and the
density error it buys, on one scene. Each run is a fresh Simulation from the same dict; the
results are a table (and eta_sweep.csv).

    PYTHONPATH=build/release/python /usr/bin/python3 samples/python/eta_sweep.py \
        [--scene samples/dam_break.json] [--end 0.3] [--etas 0.03 0.01 0.003]
"""

import argparse
import csv
import json
import time
from pathlib import Path

import upf

HERE = Path(__file__).resolve().parent


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--scene", default=HERE.parent / "dam_break.json", type=Path)
    parser.add_argument("--end", type=float, default=0.3)
    parser.add_argument("--etas", type=float, nargs="+", default=[0.03, 0.01, 0.003])
    parser.add_argument("--threads", type=int, default=0)
    parser.add_argument("--out", type=Path, default=Path("out/eta_sweep"))
    args = parser.parse_args()

    base = json.loads(args.scene.read_text())
    rows = []
    print(f"{'eta':>8} {'wall s':>8} {'steps':>6} {'iterations':>10} {'avg err %':>9} "
          f"{'max err %':>9}")
    for eta in args.etas:
        scene = json.loads(json.dumps(base))
        for material in scene["materials"].values():
            if material.get("type") == "liquid":
                material["solver"] = {"name": "pcisph", "eta": eta}
        sim = upf.Simulation.from_dict(scene, threads=args.threads, source=f"{args.scene} eta={eta}")
        iterations, avg_error, max_error = 0, 0.0, 0.0
        start = time.perf_counter()
        while sim.time < args.end - 1e-12:
            sim.step()
            last = sim.last_step()
            iterations += last["iterations"]
            avg_error += last["avg_density_error"]
            max_error = max(max_error, last["max_density_error"])
        wall = time.perf_counter() - start
        n = max(sim.step_count, 1)
        rows.append((eta, wall, sim.step_count, iterations / n, 100 * avg_error / n,
                     100 * max_error))
        print(f"{eta:8.4f} {wall:8.2f} {sim.step_count:6d} {iterations / n:10.2f} "
              f"{100 * avg_error / n:9.3f} {100 * max_error:9.3f}")
    args.out.mkdir(parents=True, exist_ok=True)
    with open(args.out / "eta_sweep.csv", "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["eta", "wall_s", "steps", "mean_iterations", "avg_density_error_pct",
                         "max_density_error_pct"])
        writer.writerows(rows)
    print(f"-> {args.out / 'eta_sweep.csv'}")


if __name__ == "__main__":
    main()
