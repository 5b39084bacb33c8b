#!/usr/bin/python3
# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
"""Every accuracy floor a change of labels is held to, from one build, in one table:

  osd-learn (45 real Kinect frames, ../shared/tools/osd_scores.py): table_iou, table_pieces,
            bleed, box_cover, box_faces, wall_on_plane; with --objects: object_iou, found, under
  five_people's people on planes (../shared/tools/people_on_planes.py)
  ABW ten (bench/abw_scores.py): correct / regions, mean IoU
  report split, with and without the quirks (pcd_compare on build/data/random/report[_quirks]):
            mean IoU and false planes per sensor model
  the 7 real frames: split planes (../shared/tools/split_planes.py) and, given --reference,
            how many of the reference run's five largest segments per frame the new labels keep
            in one segment (IoU >= 0.8 with one of its segments)

Usage: bench/floors.py BUILD OUT [--reference OUT_OF_ANOTHER_RUN] [--skip abw,report,...]
       bench/floors.py --table RUN.json [RUN.json ...]    the runs side by side
Writes OUT/floors.json (and the label files it scored under OUT/); prints the table. The
report split must be rendered (cmake --build BUILD --target render_random_report
render_random_report_quirks). Nothing is tuned here: it measures.
"""

import argparse
import json
import pathlib
import re
import subprocess
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import compare_tables  # noqa: E402
from bench_common import ROOT  # noqa: E402

SHARED = ROOT.parent / "shared"
TOOLS = SHARED / "tools"
PY = "/usr/bin/python3"
SENSORS = [("none", "exact"), ("kinect", "Kinect"), ("scanner", "scanner")]
PARTS = ["osd", "objects", "people", "abw", "report", "quirks", "real"]


def run(command, **kw):
    result = subprocess.run([str(c) for c in command], capture_output=True, text=True, **kw)
    if result.returncode != 0:
        sys.exit(f"floors: {' '.join(map(str, command))} failed ({result.returncode}):\n{result.stderr[-2000:]}")
    return result.stdout


def segment(build, inputs, out, *extra):
    out.mkdir(parents=True, exist_ok=True)
    run([build / "apps/pcd_segment/pcd_segment", "-q", *extra, *inputs, "-o", str(out) + "/"])


def osd(build, out, objects):
    seg = out / "osd"
    segment(build, [SHARED / "data/osd-learn"], seg, "--objects", "--ascii")
    result = {}
    scores = json.loads(run([PY, TOOLS / "osd_scores.py", "--json", SHARED / "data/osd-learn", seg]))
    result["osd"] = scores.get("means", scores)
    if objects:
        # osd_scores --objects prefers learnN.labels.pcd where both are in one folder: the
        # objects alone in a folder of their own.
        only = out / "osd_objects"
        only.mkdir(exist_ok=True)
        for f in seg.glob("*.objects.pcd"):
            link = only / f.name
            if not link.exists():
                link.symlink_to(f.resolve())
        scores = json.loads(run([PY, TOOLS / "osd_scores.py", "--json", "--objects", SHARED / "data/osd-learn", only]))
        result["objects"] = scores.get("means", scores)
    return result


def people(build, out):
    seg = out / "people"
    segment(build, [SHARED / "data/real/five_people.pcd"], seg, "--ascii")
    line = run([PY, TOOLS / "people_on_planes.py", seg / "five_people.labels.pcd"])
    fields = dict(kv.split("=") for kv in line.split())
    return {"people_on_planes": float(fields["on_plane"]), "segments_on_people": int(fields["segments_on_people"])}


def abw(build):
    text = run([PY, ROOT / "bench/abw_scores.py", build])
    m = re.search(r"### floodplane: (\d+) of (\d+) regions correct \(([\d.]+) %\), mean IoU ([\d.]+), (\d+) noise", text)
    if not m:
        sys.exit(f"floors: no floodplane row in abw_scores.py's output:\n{text}")
    return {"correct": f"{m.group(1)} / {m.group(2)}", "mean_iou": float(m.group(4)), "noise": int(m.group(5))}


def report(build, out, name):
    folder = build / "data/random" / name
    if len(list(folder.glob("random_*.pcd"))) != 300:
        sys.exit(f"floors: {folder} does not hold the 300 clouds: cmake --build {build} --target render_random_{name}")
    path = out / f"{name}.json"
    run([build / "apps/pcd_compare/pcd_compare", "-q", "--methods", "floodplane", "--repeat", "0", "--json", path,
         folder])
    _, scenes = compare_tables.read_report(path)
    result = {}
    for key, title in SENSORS:
        row = compare_tables.MeanRow()
        for scene in scenes:
            r = scene.find("floodplane")
            if scene.sensor == key and r is not None:
                row.add(scene, r)
        result[title] = {"mean_iou": row.accuracy("mean_iou"), "false_planes": row.false_plane_fraction()}
    return result


def read_labels(path):
    """The label field of an ASCII PCD, as a list of ints (organized order)."""
    lines = pathlib.Path(path).read_text().splitlines()
    fields = []
    for k, line in enumerate(lines):
        if line.startswith("FIELDS"):
            fields = line.split()[1:]
        if line.startswith("DATA"):
            column = fields.index("label")
            return [int(float(row.split()[column])) for row in lines[k + 1:] if row.strip()]
    raise ValueError(f"{path}: no DATA line")


def largest_kept(reference, labels, count=5):
    """How many of `reference`'s `count` largest segments have IoU >= 0.8 with one segment of `labels`."""
    sizes = {}
    for r in reference:
        if r:
            sizes[r] = sizes.get(r, 0) + 1
    own = {}
    for l in labels:
        if l:
            own[l] = own.get(l, 0) + 1
    kept = 0
    for r, size in sorted(sizes.items(), key=lambda kv: -kv[1])[:count]:
        overlap = {}
        for a, b in zip(reference, labels):
            if a == r and b:
                overlap[b] = overlap.get(b, 0) + 1
        best = max((n / (size + own[b] - n) for b, n in overlap.items()), default=0.0)
        kept += best >= 0.8
    return kept, min(count, len(sizes))


def real(build, out, reference):
    seg = out / "real"
    segment(build, [SHARED / "data/real"], seg, "--ascii")
    files = sorted(seg.glob("*.labels.pcd"))
    text = run([PY, TOOLS / "split_planes.py", *files])
    split = sum(int(w.split("=")[1]) for w in text.split() if w.startswith("split_pairs="))
    result = {"split_planes": split, "split_output": text.strip().splitlines()[-1:]}
    if reference:
        kept = total = 0
        for f in files:
            ref = pathlib.Path(reference) / "real" / f.name
            if ref.exists():
                k, n = largest_kept(read_labels(ref), read_labels(f))
                kept += k
                total += n
        result["largest_kept"] = f"{kept} of {total}"
    return result


def measure(args):
    build = pathlib.Path(args.build).resolve()
    out = pathlib.Path(args.out).resolve()
    out.mkdir(parents=True, exist_ok=True)
    skip = set(args.skip.split(",")) if args.skip else set()
    result = {"build": str(build), "commit": run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"]).strip()}
    if "osd" not in skip:
        result.update(osd(build, out, "objects" not in skip))
    if "people" not in skip:
        result["people"] = people(build, out)
    if "abw" not in skip:
        result["abw"] = abw(build)
    for name, key in (("report", "report"), ("report_quirks", "quirks")):
        if key not in skip:
            result[key] = report(build, out, name)
    if "real" not in skip:
        result["real"] = real(build, out, args.reference)
    (out / "floors.json").write_text(json.dumps(result, indent=1))
    return result


def cell(run_result, path):
    value = run_result
    for key in path:
        if not isinstance(value, dict) or key not in value:
            return "-"
        value = value[key]
    if isinstance(value, float):
        return f"{value:.4f}"
    return str(value)


ROWS = [("osd table_iou", ("osd", "table_iou")), ("osd table_pieces", ("osd", "table_pieces")),
        ("osd bleed", ("osd", "bleed")), ("osd box_cover", ("osd", "box_cover")),
        ("osd box_faces", ("osd", "box_faces")), ("osd wall_on_plane", ("osd", "wall_on_plane")),
        ("objects object_iou", ("objects", "object_iou")), ("objects found", ("objects", "objects_found")),
        ("objects under", ("objects", "under")),
        ("five_people people on planes", ("people", "people_on_planes")),
        ("ABW correct", ("abw", "correct")), ("ABW mean IoU", ("abw", "mean_iou"))]
for key, title in (("report", "report"), ("quirks", "quirks")):
    for _, sensor in SENSORS:
        ROWS.append((f"{title} {sensor} mean IoU", (key, sensor, "mean_iou")))
        ROWS.append((f"{title} {sensor} false planes", (key, sensor, "false_planes")))
ROWS += [("real split planes", ("real", "split_planes")), ("real five largest kept", ("real", "largest_kept"))]


def table(runs):
    out = "| floor | " + " | ".join(r.get("commit", "?") for r in runs) + " |\n|---|" + "---:|" * len(runs) + "\n"
    for title, path in ROWS:
        out += f"| {title} | " + " | ".join(cell(r, path) for r in runs) + " |\n"
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("build", nargs="?")
    parser.add_argument("out", nargs="?")
    parser.add_argument("--reference", help="OUT of an earlier run: its real frames' five largest segments")
    parser.add_argument("--skip", help="comma-separated parts to leave out: " + ",".join(PARTS))
    parser.add_argument("--table", nargs="+", help="floors.json files to print side by side")
    args = parser.parse_args()
    if args.table:
        print(table([json.loads(pathlib.Path(p).read_text()) for p in args.table]), end="")
        return
    if not args.build or not args.out:
        parser.error("give BUILD and OUT, or --table")
    print(table([measure(args)]), end="")


if __name__ == "__main__":
    main()
