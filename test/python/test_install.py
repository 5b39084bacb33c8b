# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
"""cmake --install puts a working package, with its stubs, where Debian's python3 looks for it:
under the default prefix on the interpreter's own path (no PYTHONPATH); under any other
prefix in the folder the install names ("floodplane: the Python package is in ..."), which
the README tells users to add to PYTHONPATH. Each run imports it with a clean environment
and segments something. Only the python component is installed (the rest of the install is
the C++ package test's)."""

import re

import os
import pathlib
import subprocess
import sys

import pytest

BUILD = os.environ["FLOODPLANE_BUILD_DIR"]
PREFIX = os.environ["FLOODPLANE_INSTALL_PREFIX"]
INSTALL_DIR = os.environ["FLOODPLANE_PYTHON_INSTALL_DIR"]  # relative to the prefix, as configured

PROGRAM = ("import floodplane, floodplane.distributed, numpy as np\n"
           "print(floodplane.__file__)\n"
           "v, u = np.mgrid[0:40, 0:50]\n"
           "z = np.full((40, 50), 2.0)\n"
           "points = np.stack([(u - 24.5) * z / 40, (v - 19.5) * z / 40, z], -1)\n"
           "print(len(floodplane.segment(points).planes))\n")


def install(prefix=None, destdir=None):
    """Installs the python component; returns the folder the install names."""
    command = ["cmake", "--install", BUILD, "--component", "python"] + (["--prefix", str(prefix)] if prefix else [])
    environment = dict(os.environ)
    if destdir:
        environment["DESTDIR"] = str(destdir)
    installed = subprocess.run(command, capture_output=True, text=True, timeout=300, env=environment)
    assert installed.returncode == 0, installed.stderr
    named = re.search(r"floodplane: the Python package is in (.+)", installed.stdout)
    assert named, installed.stdout
    return pathlib.Path(named.group(1).strip())


def clean_python(program, cwd, pythonpath=None):
    """Debian's interpreter with nothing of this environment but PATH (and PYTHONPATH if given)."""
    environment = {"PATH": "/usr/bin:/bin"}
    if pythonpath:
        environment["PYTHONPATH"] = str(pythonpath)
    return subprocess.run([sys.executable, "-c", program], capture_output=True, text=True, env=environment,
                          cwd=cwd, timeout=120)


def assert_complete_package(folder):
    files = sorted(p.name for p in (folder / "floodplane").iterdir())
    for name in ("__init__.py", "__init__.pyi", "py.typed", "distributed.py", "open3d.py"):
        assert name in files, files
    assert any(name.startswith("_floodplane") and name.endswith(".so") for name in files), files


def assert_imports_and_segments(folder, cwd, pythonpath):
    completed = clean_python(PROGRAM, cwd, pythonpath)
    assert completed.returncode == 0, completed.stderr
    location, planes = completed.stdout.split()
    assert pathlib.Path(location).is_relative_to(folder)
    assert planes == "1"


def test_the_folder_the_install_names_is_the_pythonpath_for_another_prefix(tmp_path):
    prefix = tmp_path / "prefix"
    folder = install(prefix)
    assert folder == prefix / INSTALL_DIR
    assert_complete_package(folder)
    assert_imports_and_segments(folder, tmp_path, folder)


def test_the_default_prefix_is_on_the_interpreters_own_path(tmp_path):
    searched = clean_python("import sys; print('\\n'.join(sys.path))", tmp_path).stdout.split()
    folder = os.path.join(PREFIX, INSTALL_DIR)
    if not any(os.path.realpath(PREFIX) == os.path.realpath(p) for p in ("/usr/local", "/usr")):
        pytest.skip(f"configured for the prefix {PREFIX}, not the interpreter's own")
    assert folder in searched, f"{folder} is not on {sys.executable}'s path: {searched}"
    # Installed as a packager would (DESTDIR), the package lands in that folder of the staging tree.
    staging = tmp_path / "staging"
    assert install(destdir=staging) == pathlib.Path(folder)  # the install names the final folder
    staged = pathlib.Path(str(staging) + folder)
    assert_complete_package(staged)
    assert_imports_and_segments(staged, tmp_path, staged)
