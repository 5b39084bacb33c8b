#!/usr/bin/python3
# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
"""The speed-against-accuracy chart of the methods, drawn with matplotlib from pcd_compare's
JSON (`pcd_compare --json`): one panel per run (a data set), one marker per method, its time a
frame against its accuracy. The time is the mean over the files of each file's median [ms]
(the "median ms" of pcd_compare's means, log scale); the accuracy is the mean IoU where the
files have ground truth, else the planes found per frame (the real frames have none). Baselines
at their tuned values (--tuned) have hollow markers. Figures are counted as pcd_compare and
compare_tables.py count them (compare_tables.MeanRow); methods without a time (--labels) are
left out. The same inputs give the same picture, byte for byte.

bench/update_figures.py draws it with the tables from the same runs (--chart); alone:

  bench/speed_accuracy_chart.py "bundled scenes=scenes.json" "real frames=real.json" \\
      -o bench/figures/speed_accuracy.png
"""

import argparse
import math
import os
import pathlib
import sys
import tempfile

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import compare_tables  # noqa: E402  (the report reader and its means)

# Each method's colour and marker, fixed so that a method looks the same in every panel and
# every run. floodplane's sub-sampling factors share its colour.
STYLES = {
    "floodplane": ("#1f77b4", "o"),
    "floodplane/1": ("#1f77b4", "h"),
    "floodplane/2": ("#1f77b4", "s"),
    "floodplane/4": ("#1f77b4", "D"),
    "floodplane/8": ("#1f77b4", "v"),
    "omps": ("#d62728", "^"),
    "ransac": ("#2ca02c", "P"),
    "open3d_ransac": ("#ff7f0e", "X"),
}
OTHER_STYLE = ("#7f7f7f", "*")
TUNED = " (tuned)"


class Unusable(Exception):
    """An input the chart cannot be drawn from; the message says which and why."""


def style(method):
    base = method[:-len(TUNED)] if method.endswith(TUNED) else method
    colour, marker = STYLES.get(base, OTHER_STYLE)
    return colour, marker, method.endswith(TUNED)


def panel(title, scenes):
    """The panel of one run: (title, y label, [(method, ms, y)]) in the report's method order."""
    rows = {}
    for scene in scenes:
        for result in scene.methods:
            rows.setdefault(result.method, compare_tables.MeanRow()).add(scene, result)
    scored = any(row.scored > 0 for row in rows.values())
    points = []
    for method in compare_tables.method_order(scenes):
        row = rows[method]
        ms = row.time(row.median_ms)
        y = row.accuracy("mean_iou") if scored else row.time(row.planes)
        if math.isfinite(ms) and ms > 0.0 and math.isfinite(y):
            points.append((method, ms, y))
    if not points:
        raise Unusable(f"{title}: no method with a time and a figure to draw")
    label = "mean IoU" if scored else "planes found per frame (no ground truth)"
    return f"{title} ({len(scenes)} files)", label, points


def read_panel(title, path):
    _, scenes = compare_tables.read_report(path)
    if not scenes:
        raise Unusable(f"{path}: no file was compared")
    return panel(title, scenes)


def draw(panels, path):
    """Draws `panels` (from panel()) side by side into the PNG `path`, whole or not at all."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    with matplotlib.rc_context({"font.size": 9}):
        figure, axes = plt.subplots(1, len(panels), figsize=(4.6 * len(panels), 4.2), squeeze=False)
        legend = {}
        for ax, (title, label, points) in zip(axes[0], panels):
            for method, ms, y in points:
                colour, marker, tuned = style(method)
                handle = ax.scatter([ms], [y], s=70, marker=marker, edgecolors=colour, linewidths=1.5,
                                    facecolors="none" if tuned else colour, zorder=3)
                legend.setdefault(method, handle)
            ax.set_xscale("log")
            ax.set_title(title)
            ax.set_xlabel("ms per frame, mean of each file's median (log scale: left is faster)")
            if label == "mean IoU":
                ax.set_ylabel("mean IoU (higher is better)")
                ax.set_ylim(0.0, 1.05)
            else:
                ax.set_ylabel(label)
                ax.set_ylim(0.0, max(y for _, _, y in points) * 1.15 + 0.5)
            lows = [ms for _, ms, _ in points]
            ax.set_xlim(min(lows) / 2.0, max(lows) * 4.0)
            ax.grid(True, which="major", color="#dddddd", zorder=0)
        figure.legend(list(legend.values()), list(legend), loc="lower center", ncol=min(len(legend), 5),
                      frameon=False, fontsize=8)
        figure.suptitle("Each method's time a frame against its accuracy (hollow: baselines tuned per sensor model)",
                        fontsize=10)
        rows = (len(legend) + 4) // 5
        figure.tight_layout(rect=(0.0, 0.04 + 0.035 * rows, 1.0, 0.95))
        write_figure(figure, pathlib.Path(path))
        plt.close(figure)


def write_figure(figure, path):
    """The PNG through a temporary beside `path`, renamed: never half a picture."""
    fd, partial = tempfile.mkstemp(dir=path.parent, prefix=path.name, suffix=".partial")
    try:
        with os.fdopen(fd, "wb") as f:
            figure.savefig(f, format="png", dpi=110, metadata={"Software": None})
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(partial, 0o666 & ~umask)
        os.replace(partial, path)
    except BaseException:
        pathlib.Path(partial).unlink(missing_ok=True)
        raise


def titled_run(text):
    title, equals, path = text.partition("=")
    if not equals or not title.strip() or not path:
        raise argparse.ArgumentTypeError(f"'{text}' is not TITLE=JSON")
    return title.strip(), path


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    parser.add_argument("runs", nargs="+", type=titled_run, metavar="TITLE=JSON",
                        help="a pcd_compare run and the title of its panel")
    parser.add_argument("-o", "--output", required=True, help="the PNG to write")
    args = parser.parse_args()
    try:
        panels = [read_panel(title, path) for title, path in args.runs]
        draw(panels, args.output)
    except ImportError as error:
        print(f"speed_accuracy_chart.py: matplotlib is needed ({error}); Debian: python3-matplotlib", file=sys.stderr)
        return 1
    except (Unusable, OSError) as error:
        print(f"speed_accuracy_chart.py: {error}", file=sys.stderr)
        return 1
    print(f"speed_accuracy_chart.py: {args.output}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
