# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
"""bench/targets.py, the table of issue 16's speed targets, on made-up benchmark results: each
target's verdict follows its figure, and a run without the benchmarks it needs is an error."""

import json
import os
import pathlib
import subprocess
import sys

import pytest

SOURCE = pathlib.Path(os.environ.get("FLOODPLANE_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
FRAMES = ["desk", "office"]
SIZES = {"320x240": 0.0768, "640x480": 0.3072, "1280x960": 1.2288, "1920x1080": 2.0736, "3840x2160": 8.2944}


def results(s1=0.8, s2=0.4, omps=60.0, outside=0.001, ms_per_mp=2.5):
    """Google Benchmark JSON of a run: every frame at `s1`, `s2`, `omps` ms."""
    bench = []

    def add(name, ms, **counters):
        bench.append({"name": name, "run_type": "iteration", "real_time": ms * 1e6, "time_unit": "ns", **counters})

    for frame in FRAMES:
        add(f"floodplane/s1/real:{frame}", s1)
        add(f"floodplane/s2/real:{frame}", s2)
        add(f"omps/real:{frame}", omps)
        add(f"floodplane/phases/real:{frame}", s1, outside_ms=outside)
        add(f"floor/real:{frame}", 0.09)
    add("floor/cold", 0.2)
    for size, megapixels in SIZES.items():
        add(f"floodplane/s1/size:{size}", ms_per_mp * megapixels)
    return {"context": {"date": "today"}, "benchmarks": bench}


def table(tmp_path, data):
    path = tmp_path / "run.json"
    path.write_text(json.dumps(data))
    return subprocess.run([sys.executable, str(SOURCE / "bench/targets.py"), "--json", str(path)],
                          capture_output=True, text=True)


def verdicts(output):
    """{first words of a target: its last column} of the target table."""
    rows = {}
    for line in output.splitlines():
        cells = [c.strip() for c in line.strip("|").split("|")]
        if len(cells) == 3 and cells[0] and not cells[0].startswith(("target", "---", "(")):
            rows[cells[0]] = cells[2]
    return rows


def test_a_run_meeting_every_target_is_reported_met(tmp_path):
    done = table(tmp_path, results())
    assert done.returncode == 0, done.stderr
    rows = verdicts(done.stdout)
    assert len(rows) == 7
    assert set(rows.values()) == {"yes"}, rows


@pytest.mark.parametrize("change, target", [
    ({"s1": 1.5}, "median <= 1.0 ms"),
    ({"omps": 30.0}, ">= 50x PCL OMPS"),
    ({"s2": 0.6}, "sub-sampling 2 <= 0.5 ms"),
    ({"s1": 0.3}, "sub-sampling 2 faster than 1"),
    ({"outside": 0.05}, "phases add up"),
])
def test_each_missed_target_is_reported_missed(tmp_path, change, target):
    rows = verdicts(table(tmp_path, results(**change)).stdout)
    missed = [name for name, verdict in rows.items() if verdict != "yes"]
    assert [name for name in missed if name.startswith(target)], rows


def test_nonlinear_cost_is_reported(tmp_path):
    data = results()
    for b in data["benchmarks"]:
        if b["name"].endswith("3840x2160"):
            b["real_time"] *= 2
    rows = verdicts(table(tmp_path, data).stdout)
    assert [v for name, v in rows.items() if name.startswith("linear in pixels")] == ["**no**"]


def test_a_run_without_the_real_frames_is_an_error(tmp_path):
    data = results()
    data["benchmarks"] = [b for b in data["benchmarks"] if "/real:" not in b["name"]]
    done = table(tmp_path, data)
    assert done.returncode != 0
    assert "floodplane/s1/real" in done.stderr


@pytest.mark.parametrize("data", [[1, 2], {"benchmarks": [{"name": "floor/cold"}]}])
def test_a_file_that_is_not_a_run_is_an_error(tmp_path, data):
    done = table(tmp_path, data)
    assert done.returncode != 0
    assert "not a JSON run of bench_segmentation" in done.stderr
    assert "Traceback" not in done.stderr
