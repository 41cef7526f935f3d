"""What stepping from Python costs over `upf run`: the demo scene (samples/dam_break.json) run to
--end with no frames, by the `upf` program and by Python calling Simulation.step() once per step
(the GIL released in each), each timed over its stepping loop only. Prints the median of --runs
runs of each, their ratio, and steps per second.

    PYTHONPATH=build/release/python /usr/bin/python3 bench/python_stepping.py \
        [--upf build/release/apps/upf/upf] [--end 0.3] [--runs 5] [--threads 2]

Figures, not a test: the note quotes them.
"""

import argparse
import json
import statistics
import subprocess
import tempfile
import time
from pathlib import Path

import upf

ROOT = Path(__file__).resolve().parent.parent


def cli_seconds(args, scene):
    with tempfile.TemporaryDirectory() as out:
        subprocess.run([args.upf, "run", str(scene), "--out", out, "--end", str(args.end),
                        "--threads", str(args.threads), "--no-frames", "--quiet"], check=True,
                       capture_output=True)
        summary = json.loads((Path(out) / "summary.json").read_text())
    return summary["wall_time_s"], summary["steps"]


def python_seconds(args, scene):
    sim = upf.Simulation.from_file(scene, threads=args.threads)
    sim.step()  # prepares the world (boundary volumes, neighbour lists) outside the timing,
    start = time.perf_counter()  # as the program's wall time leaves out its setup
    while sim.time < args.end - 1e-12:
        sim.step()
    return time.perf_counter() - start, sim.step_count - 1


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--upf", default=str(ROOT / "build/release/apps/upf/upf"))
    parser.add_argument("--scene", default=ROOT / "samples/dam_break.json", type=Path)
    parser.add_argument("--end", type=float, default=0.3)
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--threads", type=int, default=2)
    args = parser.parse_args()

    cli, py = [], []
    for _ in range(args.runs):  # alternating, so drifts of the machine hit both alike
        cli.append(cli_seconds(args, args.scene))
        py.append(python_seconds(args, args.scene))
    cli_s = statistics.median(s for s, _ in cli)
    py_s = statistics.median(s for s, _ in py)
    print(f"scene {args.scene.name}, to t = {args.end} s, {args.threads} threads, "
          f"median of {args.runs}")
    print(f"upf run:        {cli_s:8.3f} s stepping, {cli[0][1]} steps, "
          f"{cli[0][1] / cli_s:7.2f} steps/s")
    print(f"Python step():  {py_s:8.3f} s stepping, {py[0][1]} steps (after the first), "
          f"{py[0][1] / py_s:7.2f} steps/s")
    print(f"Python / upf run per step: {(py_s / py[0][1]) / (cli_s / cli[0][1]):.4f}")


if __name__ == "__main__":
    main()
