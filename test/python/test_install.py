# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
"""cmake --install puts a working package under <prefix>/lib/python3/dist-packages."""

import os
import pathlib
import subprocess
import sys


def test_the_installed_package_imports_and_segments(tmp_path):
    build = os.environ["FLOODPLANE_BUILD_DIR"]
    prefix = tmp_path / "prefix"
    installed = subprocess.run(["cmake", "--install", build, "--prefix", str(prefix)], capture_output=True,
                               text=True, timeout=300)
    assert installed.returncode == 0, installed.stderr
    packages = prefix / "lib/python3/dist-packages"
    files = sorted(p.name for p in (packages / "floodplane").iterdir())
    assert "__init__.py" in files and "distributed.py" in files
    assert any(name.startswith("_floodplane") and name.endswith(".so") for name in files), files

    program = ("import floodplane, floodplane.distributed, numpy as np\n"
               "print(floodplane.__file__)\n"
               "v, u = np.mgrid[0:40, 0:50]\n"
               "z = np.full((40, 50), 2.0)\n"
               "points = np.stack([(u - 24.5) * z / 40, (v - 19.5) * z / 40, z], -1)\n"
               "print(len(floodplane.segment(points).planes))\n")
    environment = {key: value for key, value in os.environ.items() if key != "PYTHONPATH"}
    environment["PYTHONPATH"] = str(packages)
    completed = subprocess.run([sys.executable, "-c", program], capture_output=True, text=True, env=environment,
                               cwd=tmp_path, timeout=120)
    assert completed.returncode == 0, completed.stderr
    location, planes = completed.stdout.split()
    assert pathlib.Path(location).is_relative_to(packages)
    assert planes == "1"
