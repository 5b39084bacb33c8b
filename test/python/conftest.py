# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
"""Shared fixtures of the Python tests: synthetic scenes with known planes, the project's data
(real frames, rendered scenes) when present, the pcd_segment binary, and a small PNG writer
for the files floodplane itself does not write (8-bit, colour)."""

import os
import pathlib
import struct
import subprocess
import zlib

import numpy as np
import pytest


def two_plane_scene(width=160, height=120, dtype=np.float32):
    """A pinhole view (f = 525 scaled to the width) of a wall at z = 2 m and a floor at
    y = 0.5 m, with a 4 x 4 hole: two planes of known extent."""
    focal = 525.0 * width / 640.0
    v, u = np.mgrid[0:height, 0:width].astype(np.float64)
    rx = (u - (width - 1) / 2.0) / focal
    ry = (v - (height - 1) / 2.0) / focal
    t = np.full((height, width), 2.0)
    floor = ry > 0
    t[floor] = np.minimum(2.0, 0.5 / ry[floor])
    points = np.stack([t * rx, t * ry, t], axis=-1).astype(dtype)
    points[10:14, 20:24] = np.nan
    return points


@pytest.fixture
def scene():
    return two_plane_scene()


def env_path(name):
    value = os.environ.get(name)
    return pathlib.Path(value) if value else None


def real_frames():
    folder = env_path("FLOODPLANE_REAL_DATA_DIR")
    if folder is None or not folder.is_dir():
        return []
    return sorted(folder.glob("*.pcd"))


def rendered_scenes():
    folder = env_path("FLOODPLANE_RENDERED_DIR")
    if folder is None or not folder.is_dir():
        return []
    return sorted(folder.glob("*.pcd"))


@pytest.fixture
def pcd_segment():
    binary = env_path("FLOODPLANE_PCD_SEGMENT")
    if binary is None or not binary.exists():
        pytest.skip("pcd_segment is not built (FLOODPLANE_BUILD_APPS=OFF)")

    def run(*arguments):
        return subprocess.run([str(binary), *map(str, arguments)], capture_output=True, text=True, timeout=300)

    return run


def write_png(path, pixels, color_type, bit_depth):
    """Writes `pixels` (H, W) or (H, W, C) as a PNG of `color_type` (0 grey, 2 RGB, 4 grey +
    alpha, 6 RGBA) and `bit_depth` (8 or 16), uncompressed filters, by hand."""

    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)

    pixels = np.asarray(pixels)
    height, width = pixels.shape[:2]
    sample = ">u2" if bit_depth == 16 else "u1"
    rows = pixels.astype(sample).reshape(height, -1)
    raw = b"".join(b"\x00" + row.tobytes() for row in rows)
    header = struct.pack(">IIBBBBB", width, height, bit_depth, color_type, 0, 0, 0)
    data = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b"")
    pathlib.Path(path).write_bytes(data)
