# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
"""What the Python benchmarks share: the machine description printed before the figures,
medians, and the project's default paths (the build tree's package and apps)."""

import os
import pathlib
import platform
import statistics
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent


REAL_FRAMES = ROOT.parent / "shared/data/real"


def pcd_files_or_real_frames(parser, files):
    """`files`, or when none are given the real frames beside the project; a usage error
    through `parser` when there are none either."""
    files = files or sorted(REAL_FRAMES.glob("*.pcd"))
    if not files:
        parser.error(f"no PCD files given and none in {REAL_FRAMES}")
    return files


def use_build_tree(build):
    """Imports floodplane from `build`/python unless it is importable already."""
    package = pathlib.Path(build, "python")
    if package.is_dir() and str(package) not in sys.path:
        sys.path.insert(0, str(package))


def machine():
    """One line: CPU model, cores, memory, Python and load average."""
    model = "unknown CPU"
    try:
        for line in pathlib.Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                model = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    memory = ""
    try:
        kib = int(pathlib.Path("/proc/meminfo").read_text().split()[1])
        memory = f", {kib / 2**20:.0f} GiB"
    except (OSError, ValueError, IndexError):
        pass
    load = ", load average %.2f %.2f %.2f" % os.getloadavg()
    return f"{model}, {os.cpu_count()} cores{memory}, Python {platform.python_version()}{load}"


def median(values):
    return statistics.median(values)


def run_or_exit(command):
    """Runs `command` (its words, paths and numbers too) and returns its stdout; when it fails,
    exits with one line naming the script, the program and the first line it said."""
    completed = subprocess.run([str(word) for word in command], capture_output=True, text=True)
    if completed.returncode != 0:
        lines = (completed.stderr.strip() or completed.stdout.strip() or "no message").splitlines()
        sys.exit(f"{pathlib.Path(sys.argv[0]).name}: {pathlib.Path(command[0]).name} failed: {lines[0]}")
    return completed.stdout


def run_pcd_segment(binary, inputs, out_dir, *options):
    """Runs pcd_segment quietly; raises with its stderr when it fails."""
    completed = subprocess.run([str(binary), *map(str, inputs), "-o", str(out_dir), "-q", *map(str, options)],
                               capture_output=True, text=True)
    if completed.returncode != 0:
        raise RuntimeError(f"pcd_segment failed: {completed.stderr.strip()}")
