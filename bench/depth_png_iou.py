#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
"""Does a depth PNG give the planes its point cloud gives? Each bundled scene (rendered by the
build: build/data/rendered/*.pcd, exact and Kinect-noise sensors) is converted into a 16-bit
depth PNG (pcd_to_depth_png.py) and pcd_segment segments both. Reported per scene: the mean
IoU against the ground truth of either (../shared/reference/metrics.md: ground-truth planes of
>= 500 pixels at 640x480, predicted segments of the same size, NaN ground truth ignored) and
their difference, and the agreement of the two segmentations (mean over the PCD's planes of
the best IoU with a PNG plane).

    /usr/bin/python3 bench/depth_png_iou.py [--build build] [--depth-scale 5000]
"""

import argparse
import pathlib
import sys
import tempfile

import numpy as np

from bench_common import ROOT, machine, run_pcd_segment, use_build_tree
from pcd_to_depth_png import convert


def kept_sizes(labels, valid, minimum):
    sizes = np.bincount(labels[valid], minlength=labels.max() + 1)
    keep = sizes >= minimum
    keep[0] = False
    return sizes, keep


def best_iou(reference, other, valid, minimum):
    """For each kept region of `reference`: the best IoU with a kept region of `other`."""
    ref = reference[valid].astype(np.int64)
    oth = other[valid].astype(np.int64)
    ref_sizes, ref_keep = kept_sizes(reference, valid, minimum)
    oth_sizes, oth_keep = kept_sizes(other, valid, minimum)
    width = oth_sizes.size
    overlap = np.bincount(ref * width + oth, minlength=ref_sizes.size * width).reshape(ref_sizes.size, width)
    union = ref_sizes[:, None] + oth_sizes[None, :] - overlap
    iou = np.where(union > 0, overlap / np.maximum(union, 1), 0.0)
    iou[:, ~oth_keep] = 0.0
    return iou[ref_keep].max(axis=1) if iou.shape[1] else np.zeros(ref_keep.sum())


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--build", type=pathlib.Path, default=ROOT / "build")
    parser.add_argument("--depth-scale", type=float, default=5000.0, help="PNG units per metre (TUM: 5000)")
    arguments = parser.parse_args()
    use_build_tree(arguments.build)
    import floodplane

    scenes = sorted((arguments.build / "data/rendered").glob("*.pcd"))
    if not scenes:
        print(f"depth_png_iou: no rendered scenes in {arguments.build}/data/rendered", file=sys.stderr)
        return 1
    pcd_segment = arguments.build / "apps/pcd_segment/pcd_segment"
    print(f"machine: {machine()}")
    print(f"{len(scenes)} scenes, depth PNG at {arguments.depth_scale:g} units per metre, pcd_segment defaults")
    print()
    print("| scene | mean IoU, PCD | mean IoU, PNG | difference | agreement PCD-PNG | points lost |")
    print("|---|---|---|---|---|---|")
    differences, agreements = [], []
    with tempfile.TemporaryDirectory() as work:
        work = pathlib.Path(work)
        for scene in scenes:
            png = work / (scene.stem + ".png")
            intrinsics, lost = convert(floodplane, scene, png, arguments.depth_scale)
            run_pcd_segment(pcd_segment, [scene], work / "pcd")
            run_pcd_segment(pcd_segment, [png], work / "png", "--intrinsics", ",".join(map(str, intrinsics)),
                            "--depth-scale", arguments.depth_scale)
            truth = floodplane.read_labels_pcd(str(scene))
            valid = np.isfinite(floodplane.read_pcd(str(scene))[..., 2])
            from_pcd = floodplane.read_labels_pcd(str(work / "pcd" / (scene.stem + ".labels.pcd")))
            from_png = floodplane.read_labels_pcd(str(work / "png" / (scene.stem + ".labels.pcd")))
            minimum = 500 * truth.size / (640 * 480)
            iou_pcd = best_iou(truth, from_pcd, valid, minimum).mean()
            iou_png = best_iou(truth, from_png, valid, minimum).mean()
            agreement = best_iou(from_pcd, from_png, valid, minimum).mean()
            differences.append(iou_png - iou_pcd)
            agreements.append(agreement)
            print(f"| {scene.stem} | {iou_pcd:.4f} | {iou_png:.4f} | {iou_png - iou_pcd:+.4f} | {agreement:.4f} | "
                  f"{lost} |")
    worst = max(differences, key=abs)
    print(f"| mean of {len(scenes)} | | | {np.mean(differences):+.4f} (largest {worst:+.4f}) | "
          f"{np.mean(agreements):.4f} (lowest {min(agreements):.4f}) | |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
