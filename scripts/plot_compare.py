#!/usr/bin/env python3
"""Draws the PNG plots of `upf compare`, one curve per solver.

Usage: python3 plot_compare.py OUT

Reads OUT/report.json (written by `upf compare`: the solvers, the probes, the files to draw and
their pixel size) and each solver's OUT/<dir>/metrics.csv and probes.csv. Every picture is
exactly width_px x height_px: a fixed figure size at a fixed dpi, saved without a tight bounding
box (which would change the size). Non-finite values (a probe that saw no liquid) leave gaps.

Exit codes: 0 drawn, 1 failed, 2 usage, 3 matplotlib missing (upf then tries another python3).
"""
import csv
import json
import math
import os
import sys
import traceback
from pathlib import Path

MISSING_MODULE_EXIT = 3
DPI = 100

try:
    import matplotlib

    matplotlib.use("Agg")  # no display: files only
    import matplotlib.pyplot as plt
except ImportError as error:
    print(f"matplotlib is not installed for {sys.executable} ({error}); "
          "install python3-matplotlib (scripts/install-deps)", file=sys.stderr)
    sys.exit(MISSING_MODULE_EXIT)


def number(text):
    """A CSV cell as a float; anything non-finite or unreadable becomes NaN (a gap)."""
    try:
        value = float(text)
    except (TypeError, ValueError):
        return math.nan
    return value if math.isfinite(value) else math.nan


def read_columns(path):
    """The columns of a CSV file by header name; no columns when the file is missing or empty."""
    if not path.is_file():
        return {}
    with path.open(newline="") as f:
        rows = list(csv.reader(f))
    if not rows:
        return {}
    header, body = rows[0], rows[1:]
    return {name: [number(r[i]) if i < len(r) else math.nan for r in body]
            for i, name in enumerate(header)}


class Run:
    """One solver's row of report.json with its time series and a colour kept across plots."""

    def __init__(self, out, row, colour):
        self.row = row
        self.colour = colour
        self.metrics = read_columns(out / row["dir"] / "metrics.csv")
        self.probes = read_columns(out / row["dir"] / "probes.csv")

    def name(self):
        """The run's name: the solver, or in a sweep the solver with its swept values."""
        return self.row.get("run", self.row["solver"])

    def label(self):
        if self.row["status"] == "unstable" and self.row.get("failure_time_s") is not None:
            return f'{self.name()} (unstable at t = {self.row["failure_time_s"]:.4g} s)'
        return self.name()

    def curve(self, axes, columns, name, scale=1.0, **style):
        t = columns.get("t", [])
        y = [v * scale for v in columns.get(name, [])]
        n = min(len(t), len(y))
        axes.plot(t[:n], y[:n], color=self.colour, label=self.label(), **style)
        if self.row["status"] == "unstable" and n:  # mark where it broke down
            axes.plot(t[n - 1], y[n - 1], marker="x", markersize=12, color=self.colour)


def new_figure(report, rows=1):
    size = report["plots"]
    figure, axes = plt.subplots(rows, 1, sharex=True, layout="constrained",
                                figsize=(size["width_px"] / DPI, size["height_px"] / DPI),
                                dpi=DPI)
    return figure, axes if rows > 1 else [axes]


def finish(report, figure, axes, title, path):
    figure.suptitle(title)
    for a in axes:
        a.set_xlim(0, report["end_time_s"])  # every plot on the same time axis
        a.grid(True, alpha=0.3)
        a.legend(loc="best")
    axes[-1].set_xlabel("simulated time t [s]")
    temporary = path.with_name(path.name + ".tmp")
    figure.savefig(temporary, dpi=DPI, format="png")  # no bbox_inches: the size stays exact
    plt.close(figure)
    os.replace(temporary, path)


def plot_density_error(report, runs, spec, path):
    figure, (average, maximum) = new_figure(report, rows=2)
    for run in runs:
        run.curve(average, run.metrics, "avg_density_error", 100.0)
        run.curve(maximum, run.metrics, "max_density_error", 100.0, linestyle="--")
    average.set_ylabel("average density error [%]")
    maximum.set_ylabel("max density error [%]")
    finish(report, figure, [average, maximum], spec["title"], path)


def plot_dt(report, runs, spec, path):
    figure, (axes,) = new_figure(report)
    for run in runs:
        run.curve(axes, run.metrics, "dt")
    values = [v for run in runs for v in run.metrics.get("dt", []) if v > 0]
    if values and max(values) > 10 * min(values):  # solvers' steps can differ by decades
        axes.set_yscale("log")
    axes.set_ylabel("time step dt [s]")
    finish(report, figure, [axes], spec["title"], path)


def plot_probe(report, runs, spec, path):
    figure, (axes,) = new_figure(report)
    for run in runs:
        run.curve(axes, run.probes, spec["probe"], marker=".")
    if not any(math.isfinite(v) for run in runs for v in run.probes.get(spec["probe"], [])):
        axes.text(0.5, 0.5, "no value: the probe saw no liquid", transform=axes.transAxes,
                  ha="center", va="center", fontsize=14, color="grey")
    axes.set_ylabel(spec.get("label") or spec["probe"])
    finish(report, figure, [axes], spec["title"], path)


def plot_accuracy_cost(report, runs, spec, path):
    """One point per solver: its largest density error against its cost. Lower left is better:
    as accurate, for less wall time. Unstable runs are left out (their figures cover part of the
    run) and named in a note."""
    figure, (axes,) = new_figure(report)
    left_out = []
    for run in runs:
        cost = run.row.get("wall_seconds_per_simulated_second") or 0
        error = run.row.get("max_density_error")
        if run.row["status"] != "completed" or cost <= 0 or error is None:
            left_out.append(run.name())
            continue
        axes.plot([cost], [100.0 * error], marker="o", markersize=10, linestyle="none",
                  color=run.colour, label=run.label())
        axes.annotate(run.name(), (cost, 100.0 * error), textcoords="offset points",
                      xytext=(8, 6), color=run.colour)
    if left_out:
        axes.text(0.99, 0.01, "not shown (not completed): " + ", ".join(left_out),
                  transform=axes.transAxes, ha="right", va="bottom", color="grey")
    axes.set_xlabel("wall seconds per simulated second (cost)")
    axes.set_ylabel("largest density error over the run [%]")
    axes.set_xlim(left=0)
    axes.set_ylim(bottom=0)
    axes.grid(True, alpha=0.3)
    if axes.get_legend_handles_labels()[0]:
        axes.legend(loc="best")
    figure.suptitle(spec["title"])
    temporary = path.with_name(path.name + ".tmp")
    figure.savefig(temporary, dpi=DPI, format="png")  # no bbox_inches: the size stays exact
    plt.close(figure)
    os.replace(temporary, path)


PLOTTERS = {"density_error": plot_density_error, "dt": plot_dt, "probe": plot_probe,
            "accuracy_cost": plot_accuracy_cost}


def main(argv):
    if len(argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    out = Path(argv[1])
    report = json.loads((out / "report.json").read_text())
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    runs = [Run(out, row, colours[i % len(colours)]) for i, row in enumerate(report["rows"])]
    for spec in report["plots"]["files"]:
        title = f'{spec["title"]} ({report["scene"]})'
        PLOTTERS[spec["kind"]](report, runs, dict(spec, title=title), out / spec["file"])
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main(sys.argv))
    except Exception as error:
        traceback.print_exc()
        # upf quotes the last line of the output in the report: make it the short reason.
        print(f"plot_compare.py: {type(error).__name__}: {error}", file=sys.stderr)
        sys.exit(1)
