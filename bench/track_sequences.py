#!/usr/bin/python3
# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
"""Plane tracking against ground truth (issue 28): renders a walking camera's sequence per seed
with `pcd_synth --sequence`, segments each with `pcd_segment --track` (the label field of its
outputs holds track ids) and prints, per seed and over all, the id switches, lost planes and
re-entries.

The figures follow toolkit/eval/tracking_metrics.h, which is the reference for their definitions;
this script counts the same in Python from the text PCDs (`--ascii`) of both tools:
- a ground-truth plane is present in a frame with at least --min-fraction of its pixels (valid
  ones: a finite ground-truth point); each present plane in a frame is a plane-frame;
- it is matched to the track id overlapping it most (the smaller id on a tie) when their IoU is
  at least --min-iou, else it is lost in that frame;
- an id switch is a match to another id than the plane's remembered one (its last match's),
  which it forgets after more than --max-gap absent frames in a row;
- a re-entry is a return after 1..--max-gap absent frames with a remembered id, kept when its
  first match from the return on has that id, switched when another.
Targets (issue 28): at most 1 switch per 100 plane-frames for planes of at least 1 % of the
frame; re-entries within 30 frames keep their id in at least 95 % of cases.

With --look-away the camera glances away from its walking direction now and then and back
(pcd_synth --look-away), so that planes leave the view for a moment and return: the re-entries
that a plain walk hardly has.

pcd_segment takes the camera poses pcd_synth writes (<scene>.poses.json) with --poses, so that
the tracker knows the camera's motion between frames; --no-poses leaves them out (the tracker
then matches planes by their parameters and pixel overlap alone). pcd_segment --track continues
each frame from the one before (the head start); --cold-starts segments every frame from nothing.

Example:
  bench/track_sequences.py --seeds 1-5 --frames 300
  bench/track_sequences.py --seeds 101-102 --frames 150 --look-away   # re-entries
  bench/track_sequences.py --seeds 101-102 --frames 150 --look-away --no-poses   # without the motions
  bench/track_sequences.py --seeds 1 --frames 30 --ground-truth-as-tracks   # checks this script
"""

import argparse
import json
import math
import pathlib
import sys
import tempfile
import warnings

import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from bench_common import ROOT, machine, run_or_exit  # noqa: E402


class TrackingEvaluator:
    """Mirrors floodplane::eval::TrackingEvaluator (toolkit/eval/tracking_metrics.h)."""

    def __init__(self, min_fraction=0.01, min_iou=0.5, max_gap=29):
        self.min_fraction, self.min_iou, self.max_gap = min_fraction, min_iou, max_gap
        self.planes = {}  # label -> {"remembered": id or None, "absent": frames, "pending": bool}
        self.scores = dict(frames=0, plane_frames=0, matched=0, id_switches=0, lost=0, re_entries=0,
                           re_entries_kept=0, re_entries_switched=0)

    def add_frame(self, ground_truth, predicted, valid):
        if not len(ground_truth) == len(predicted) == len(valid):
            raise ValueError(f"ground truth, prediction and mask differ in size "
                             f"({len(ground_truth)}, {len(predicted)}, {len(valid)})")
        # Pixel counts per plane, per id and per (plane, id) pair, over the valid pixels: numpy
        # counts a 640x480 frame in milliseconds where a loop over its pixels took a tenth of a second.
        mask = np.asarray(valid, dtype=bool)
        plane_of = np.asarray(ground_truth, dtype=np.int64)[mask]
        id_of = np.asarray(predicted, dtype=np.int64)[mask]

        def counts(values):
            labels, pixels = np.unique(values[values != 0], return_counts=True)
            return dict(zip(labels.tolist(), pixels.tolist()))

        plane_pixels, id_pixels = counts(plane_of), counts(id_of)
        both = (plane_of != 0) & (id_of != 0)
        base = int(id_of.max(initial=0)) + 1  # a (plane, id) pair as one number: plane * base + id
        pairs, overlap_pixels = np.unique(plane_of[both] * base + id_of[both], return_counts=True)
        candidates = {}  # plane -> (overlap, id): the id overlapping it most, the smaller one on a tie
        for pair, overlap in zip(pairs.tolist(), overlap_pixels.tolist()):
            plane, track_id = divmod(pair, base)
            best = candidates.get(plane)
            if best is None or overlap > best[0] or (overlap == best[0] and track_id < best[1]):
                candidates[plane] = (overlap, track_id)
        min_pixels = math.ceil(self.min_fraction * len(ground_truth))
        present = {g for g, pixels in plane_pixels.items() if pixels >= min_pixels}
        for g, history in self.planes.items():
            if g in present:
                continue
            history["absent"] += 1
            history["pending"] = False
            if history["absent"] > self.max_gap:
                history["remembered"] = None
        for g in sorted(present):
            overlap, p = candidates.get(g, (0, 0))
            union = plane_pixels[g] + (id_pixels[p] if p else 0) - overlap
            self._present(g, p if p and overlap >= self.min_iou * union else None)
        self.scores["frames"] += 1

    def _present(self, plane, track_id):
        history = self.planes.setdefault(plane, {"remembered": None, "absent": 0, "pending": False})
        scores = self.scores
        if history["absent"] > 0 and history["remembered"] is not None:
            scores["re_entries"] += 1
            history["pending"] = True
        history["absent"] = 0
        scores["plane_frames"] += 1
        if track_id is None:
            scores["lost"] += 1
            return
        scores["matched"] += 1
        switched = history["remembered"] is not None and history["remembered"] != track_id
        scores["id_switches"] += switched
        if history["pending"]:
            scores["re_entries_switched" if switched else "re_entries_kept"] += 1
            history["pending"] = False
        history["remembered"] = track_id


def read_ascii_pcd(path):
    """The label of every point and whether its x is finite, from a text PCD: two numpy arrays
    (int64, bool)."""
    with open(path) as f:
        fields, points = None, None
        for line in f:
            words = line.split()
            if not words or words[0].startswith("#"):
                continue
            if words[0] == "FIELDS":
                fields = words[1:]
            elif words[0] == "POINTS":
                points = int(words[1])
            elif words[0] == "DATA":
                if words[1] != "ascii":
                    raise ValueError(f"{path}: DATA {words[1]}: text PCDs only (--ascii)")
                break
        if fields is None or "label" not in fields or "x" not in fields or points is None:
            raise ValueError(f"{path}: not a PCD with x and label fields")
        x_column, label_column = fields.index("x"), fields.index("label")
        body = f.read()
    # All the numbers at once (numpy parses "nan" too): what both tools write, one value a
    # field; anything else (or a malformed body) goes line by line, which says what is wrong.
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", DeprecationWarning)  # numpy's note on a body it could not read to its end
        values = np.fromstring(body, sep=" ")
    if values.size == points * len(fields):
        return values[label_column::len(fields)].astype(np.int64), ~np.isnan(values[x_column::len(fields)])
    lines = body.splitlines()
    if len(lines) != points:
        raise ValueError(f"{path}: {len(lines)} points, the header says {points}")
    rows = [line.split() for line in lines]
    labels = np.array([int(row[label_column]) for row in rows], dtype=np.int64)
    valid = np.array([row[x_column].lower() not in ("nan", "-nan") for row in rows], dtype=bool)
    return labels, valid


def parse_seeds(text):
    """'1-5' or '1,3,7' (or both: '1-3,9')."""
    seeds = []
    for part in text.split(","):
        low, _, high = part.partition("-")
        if not low.isdigit() or (high and not high.isdigit()):
            raise argparse.ArgumentTypeError(f"not a seed list: {text!r} (e.g. 1-5 or 1,3,7)")
        seeds.extend(range(int(low), int(high or low) + 1))
    if not seeds:
        raise argparse.ArgumentTypeError(f"no seeds in {text!r}")
    return seeds


def has_option(pcd_segment, option):
    return option in run_or_exit([pcd_segment, "--help"])


def evaluate_seed(seed, args, work):
    """Renders, segments and scores one seed's sequence; returns its scores and whether
    pcd_segment had the sequence's camera poses."""
    name = f"random_{seed:04d}"
    truth, tracks = work / name / "truth", work / name / "tracks"
    run_or_exit([args.pcd_synth, "--random", 1, "--seed", seed, "--sequence", args.frames, "--sensor", args.sensor,
                 *(["--look-away"] if args.look_away else []), "--ascii", "-q", "-o", truth])
    frames = sorted(truth.glob(f"{name}_f*.{args.sensor}.pcd"))
    if len(frames) != args.frames:
        sys.exit(f"track_sequences.py: {truth}: {len(frames)} frames, expected {args.frames}")
    poses = truth / f"{name}.poses.json"
    with_poses = not args.no_poses and not args.ground_truth_as_tracks and poses.is_file()
    if args.ground_truth_as_tracks:
        outputs = frames
    else:
        run_or_exit([args.pcd_segment, *frames, "-o", tracks, "--track",
                     *(["--poses", poses] if with_poses else []), *(["--cold-starts"] if args.cold_starts else []),
                     "--ascii", "-q"])
        outputs = [tracks / (frame.name[:-len(".pcd")] + ".labels.pcd") for frame in frames]
    evaluator = TrackingEvaluator(args.min_fraction, args.min_iou, args.max_gap)
    for frame, output in zip(frames, outputs):
        try:
            ground_truth, valid = read_ascii_pcd(frame)
            predicted, _ = read_ascii_pcd(output)
            evaluator.add_frame(ground_truth, predicted, valid)
        except (OSError, ValueError) as error:
            sys.exit(f"track_sequences.py: {error}")
    return evaluator.scores, with_poses


def per100(count, total):
    return f"{100.0 * count / total:.2f}" if total else "-"


def row(label, s):
    kept = f"{s['re_entries_kept'] / s['re_entries']:.3f}" if s["re_entries"] else "-"
    return (f"| {label} | {s['frames']} | {s['plane_frames']} | {s['id_switches']} | "
            f"{per100(s['id_switches'], s['plane_frames'])} | {s['lost']} | {per100(s['lost'], s['plane_frames'])} | "
            f"{s['re_entries']} | {s['re_entries_kept']} | {s['re_entries_switched']} | {kept} |")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--seeds", type=parse_seeds, default=parse_seeds("1-5"),
                        help="random scene seeds: 1-5, 1,3,7 (default 1-5)")
    parser.add_argument("--frames", type=int, default=300, help="frames a sequence (default 300: 10 s at 30 Hz)")
    parser.add_argument("--look-away", action="store_true",
                        help="the camera glances away from its walking direction and back (pcd_synth --look-away): "
                        "planes leave the view and return")
    parser.add_argument("--no-poses", action="store_true",
                        help="do not give pcd_segment the sequence's camera poses (--poses <scene>.poses.json): "
                        "the tracker then knows no camera motion")
    parser.add_argument("--cold-starts", action="store_true",
                        help="pcd_segment --cold-starts: every frame segmented from nothing, without the head start "
                        "from the frame before")
    parser.add_argument("--sensor", choices=["kinect", "none"], default="kinect", help="sensor model (default kinect)")
    parser.add_argument("--min-fraction", type=float, default=0.01,
                        help="share of the frame from which a plane is present (default 0.01)")
    parser.add_argument("--min-iou", type=float, default=0.5, help="IoU from which a plane is matched (default 0.5)")
    parser.add_argument("--max-gap", type=int, default=29,
                        help="longest absence in frames after which a return is a re-entry (default 29)")
    parser.add_argument("--work", help="keep the rendered and segmented frames here (default: a temporary directory)")
    parser.add_argument("--json", help="also write the figures, per seed and over all, to this file")
    parser.add_argument("--ground-truth-as-tracks", action="store_true",
                        help="score the ground truth as if it were the tracker's output (no pcd_segment; 0 "
                        "switches, 0 lost): checks this script")
    parser.add_argument("--pcd-synth", default=ROOT / "build/apps/pcd_synth/pcd_synth", help="pcd_synth binary")
    parser.add_argument("--pcd-segment", default=ROOT / "build/apps/pcd_segment/pcd_segment",
                        help="pcd_segment binary (with --track)")
    args = parser.parse_args()
    if args.frames < 1:
        parser.error(f"--frames must be at least 1, got {args.frames}")
    if not 0.0 < args.min_fraction <= 1.0:
        parser.error(f"--min-fraction must be in (0, 1], got {args.min_fraction}")
    if not 0.0 < args.min_iou <= 1.0:
        parser.error(f"--min-iou must be in (0, 1], got {args.min_iou}")
    if args.max_gap < 0:
        parser.error(f"--max-gap must not be negative, got {args.max_gap}")
    for binary in [args.pcd_synth] + ([] if args.ground_truth_as_tracks else [args.pcd_segment]):
        if not pathlib.Path(binary).is_file():
            sys.exit(f"track_sequences.py: no binary {binary} (build it, or give its path)")
    if not args.ground_truth_as_tracks and not has_option(args.pcd_segment, "--track"):
        sys.exit(f"track_sequences.py: {args.pcd_segment} has no --track option (issue 28's tracking is not built)")
    if not args.ground_truth_as_tracks and not args.no_poses and not has_option(args.pcd_segment, "--poses"):
        sys.exit(f"track_sequences.py: {args.pcd_segment} has no --poses option (give --no-poses)")

    tracker = "ground truth as tracks" if args.ground_truth_as_tracks else f"{args.pcd_segment} --track"
    if not args.ground_truth_as_tracks:
        tracker += " without poses" if args.no_poses else " --poses <scene>.poses.json"
        tracker += " --cold-starts" if args.cold_starts else ""
    print(f"machine: {machine()}")
    print(f"sequences: seeds {','.join(map(str, args.seeds))}, {args.frames} frames each, sensor {args.sensor}"
          f"{', looking away' if args.look_away else ''}; tracker: {tracker}")
    print(f"present from {args.min_fraction:g} of the frame, matched from IoU {args.min_iou:g}, "
          f"re-entries after 1-{args.max_gap} absent frames\n")
    with tempfile.TemporaryDirectory() as scratch:
        work = pathlib.Path(args.work or scratch)
        per_seed, with_poses = {}, {}
        for seed in args.seeds:
            per_seed[seed], with_poses[seed] = evaluate_seed(seed, args, work)
            print(f"seed {seed}: done", file=sys.stderr, flush=True)
    total = {key: sum(s[key] for s in per_seed.values()) for key in next(iter(per_seed.values()))}
    print("| seed | frames | plane-frames | switches | per 100 | lost | per 100 | re-entries | kept | switched "
          "| kept share |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for seed, s in per_seed.items():
        print(row(str(seed), s))
    print(row("all", total))
    if args.json:
        try:
            pathlib.Path(args.json).write_text(json.dumps({"look_away": args.look_away,
                                                           "poses": all(with_poses.values()),
                                                           "seeds": {str(k): v for k, v in per_seed.items()},
                                                           "all": total}, indent=2) + "\n")
        except OSError as error:
            sys.exit(f"track_sequences.py: cannot write {args.json}: {error}")


if __name__ == "__main__":
    main()
