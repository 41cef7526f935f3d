"""The dam break's surge front from Python: step the sample scene frame by frame, read the
liquid's largest x as a NumPy view, and plot it against time in the dimensionless form of
Martin & Moyce 1952 (front Z = x / a against T = t sqrt(2 g / a), a the column's width); without
matplotlib the curve goes to a CSV file.

    PYTHONPATH=build/release/python /usr/bin/python3 samples/python/dam_break_front.py \
        [--scene samples/dam_break.json] [--end 1.0] [--out out/python_front]
"""

import argparse
import csv
import json
import math
from pathlib import Path

import numpy as np

import upf

HERE = Path(__file__).resolve().parent


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--scene", default=HERE.parent / "dam_break.json", type=Path)
    parser.add_argument("--end", type=float, default=1.0, help="simulated seconds")
    parser.add_argument("--threads", type=int, default=0)
    parser.add_argument("--out", type=Path, default=Path("out/python_front"))
    args = parser.parse_args()

    scene = json.loads(args.scene.read_text())
    block = scene["fluid_blocks"][0]
    width = block["max"][0] - block["min"][0]  # a: the column's width along x
    g = math.sqrt(sum(c * c for c in scene.get("gravity", [0, -9.81, 0])))

    sim = upf.Simulation.from_file(args.scene, threads=args.threads)
    rows = []
    liquid = upf.PARTICLE_TYPES["liquid"]
    while True:
        with sim.particles() as p:
            front = float(p.position[:, 0][p.type == liquid].max()) - block["min"][0]
        rows.append((sim.time, front, sim.time * math.sqrt(2 * g / width), front / width))
        if sim.time >= args.end - 1e-12:
            break
        sim.advance_to(min(args.end, sim.time + 1.0 / sim.fps))

    args.out.mkdir(parents=True, exist_ok=True)
    with open(args.out / "front.csv", "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["t_s", "front_m", "T", "Z"])
        writer.writerows(rows)
    print(f"{len(rows)} frames; front at t = {rows[-1][0]:.3f} s: {rows[-1][1]:.3f} m "
          f"-> {args.out / 'front.csv'}")
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return
    data = np.array(rows)
    fig, ax = plt.subplots(figsize=(5, 3.5), dpi=120)
    ax.plot(data[:, 2], data[:, 3], marker=".", label=f"upf ({sim.name})")
    containers = scene.get("containers", [])
    if containers:  # the front stops at the tank's far wall
        wall = (containers[0]["max"][0] - block["min"][0]) / width
        ax.axhline(wall, color="grey", linestyle="--", linewidth=1, label="far wall")
    ax.set_xlabel("T = t sqrt(2g/a)")
    ax.set_ylabel("Z = front / a")
    ax.set_title("Dam-break surge front")
    ax.grid(alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(args.out / "front.png")
    print(f"plot: {args.out / 'front.png'}")


if __name__ == "__main__":
    main()
