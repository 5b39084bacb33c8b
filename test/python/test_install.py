# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
"""cmake --install puts a working package, with its stubs, in the folder where catkin puts a
ROS package's Python messages (Debian: <prefix>/lib/python3/dist-packages), so that one
PYTHONPATH entry finds both: under the default prefix Debian's python3 reads it with nothing
set (directly under /usr, through the floodplane.pth the install adds under /usr/local); under
any other prefix it is the folder the install names ("floodplane: the Python package is in
..."), which the README tells users to add to PYTHONPATH. Each run imports it with a clean
environment and segments something. Only the python component is installed (the rest of the
install is the C++ package test's)."""

import os
import pathlib
import re
import subprocess
import sys

import pytest

BUILD = os.environ["FLOODPLANE_BUILD_DIR"]
PREFIX = os.environ["FLOODPLANE_INSTALL_PREFIX"]
INSTALL_DIR = os.environ["FLOODPLANE_PYTHON_INSTALL_DIR"]  # relative to the prefix, as configured

# A stand-in for the ROS node's generated messages, which catkin installs into the same folder.
MESSAGES = ("floodplane_ros/__init__.py", "floodplane_ros/msg/__init__.py")

PROGRAM = ("import floodplane, floodplane.distributed, numpy as np\n"
           "print(floodplane.__file__)\n"
           "v, u = np.mgrid[0:40, 0:50]\n"
           "z = np.full((40, 50), 2.0)\n"
           "points = np.stack([(u - 24.5) * z / 40, (v - 19.5) * z / 40, z], -1)\n"
           "print(len(floodplane.segment(points).planes))\n")


def install(prefix=None, destdir=None):
    """Installs the python component; returns the folder the install names and its output."""
    command = ["cmake", "--install", BUILD, "--component", "python"] + (["--prefix", str(prefix)] if prefix else [])
    environment = dict(os.environ)
    if destdir:
        environment["DESTDIR"] = str(destdir)
    installed = subprocess.run(command, capture_output=True, text=True, timeout=300, env=environment)
    assert installed.returncode == 0, installed.stderr
    named = re.search(r"floodplane: the Python package is in (.+)", installed.stdout)
    assert named, installed.stdout
    return pathlib.Path(named.group(1).strip()), installed.stdout


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


def add_messages(folder):
    for name in MESSAGES:
        (folder / name).parent.mkdir(parents=True, exist_ok=True)
        (folder / name).write_text("")


def assert_imports_and_segments(folder, cwd, pythonpath=None, site_folder=None):
    """The package and the messages beside it import from `folder`, found through `pythonpath`,
    or through `site_folder` read as the interpreter reads its own site folders (.pth files
    included)."""
    program = PROGRAM + "import floodplane_ros.msg\n"
    if site_folder:
        program = f"import site; site.addsitedir({str(site_folder)!r})\n" + program
    completed = clean_python(program, cwd, pythonpath)
    assert completed.returncode == 0, completed.stderr
    location, planes = completed.stdout.split()
    assert pathlib.Path(location).is_relative_to(folder)
    assert planes == "1"


def catkin_python_install_dir():
    """Where catkin installs a package's Python modules, relative to the prefix."""
    completed = clean_python("import catkin.builder; print(catkin.builder.get_python_install_dir())", "/")
    if completed.returncode != 0:
        return None
    return completed.stdout.strip()


def test_installs_where_catkin_puts_the_ros_nodes_messages():
    if os.path.exists("/etc/debian_version"):
        assert INSTALL_DIR == "lib/python3/dist-packages"
    catkin = catkin_python_install_dir()
    if catkin is None:
        pytest.skip("catkin is not installed (scripts/install_ros_deps.sh): its folder is not known here")
    assert INSTALL_DIR == catkin


def test_the_folder_the_install_names_is_the_pythonpath_for_another_prefix(tmp_path):
    prefix = tmp_path / "prefix"
    folder, said = install(prefix)
    assert folder == prefix / INSTALL_DIR
    assert "add it to PYTHONPATH" in said
    assert_complete_package(folder)
    assert not list(prefix.rglob("*.pth")), "nothing outside the package's folder"
    add_messages(folder)
    assert_imports_and_segments(folder, tmp_path, pythonpath=folder)


def test_the_default_prefix_needs_nothing_set(tmp_path):
    if not any(os.path.realpath(PREFIX) == os.path.realpath(p) for p in ("/usr/local", "/usr")):
        pytest.skip(f"configured for the prefix {PREFIX}, not the interpreter's own")
    searched = clean_python("import sys; print('\\n'.join(sys.path))", tmp_path).stdout.split()
    folder = os.path.join(PREFIX, INSTALL_DIR)
    # Installed as a packager would (DESTDIR), the package lands in that folder of the staging tree.
    staging = tmp_path / "staging"
    named, said = install(destdir=staging)
    assert named == pathlib.Path(folder)  # the install names the final folder
    staged = pathlib.Path(str(staging) + folder)
    assert_complete_package(staged)
    add_messages(staged)
    path_files = list(staging.rglob("*.pth"))
    if folder in searched:  # /usr: the interpreter reads lib/python3/dist-packages itself
        assert not path_files
        assert_imports_and_segments(staged, tmp_path, pythonpath=staged)
        return
    # /usr/local: a floodplane.pth in the folder the interpreter reads there names the package's.
    site_folders = [p for p in searched if pathlib.Path(p).is_relative_to(os.path.join(PREFIX, "lib"))]
    assert site_folders, f"{sys.executable} reads no folder under {PREFIX}: {searched}"
    path_file = pathlib.Path(str(staging) + site_folders[0]) / "floodplane.pth"
    assert path_files == [path_file]
    assert f"{site_folders[0]}/floodplane.pth adds it" in said
    assert_imports_and_segments(staged, tmp_path, site_folder=path_file.parent)
