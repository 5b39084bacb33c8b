# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
"""Where the floodplane package installs, as the interpreter that runs this script sees it
(CMake runs it with the one it builds for).

    python3 site_packages_dir.py             ->  lib/python3/dist-packages (Debian)
    python3 site_packages_dir.py --searched  ->  the folders the interpreter reads packages
                                                 from, one a line (real paths)

The install folder, relative to the prefix, is the one catkin installs a ROS package's Python
messages in (catkin.builder.get_python_install_dir, PYTHON_INSTALL_DIR in its CMake): Debian's
layout lib/python3/dist-packages on Debian and its derivatives, lib/pythonX.Y/site-packages
elsewhere. The package and the ROS node's messages then share one folder, so one PYTHONPATH
entry (or the ROS install's setup.bash) finds both.

Debian's python3 reads lib/python3/dist-packages under /usr, but under /usr/local it reads
lib/python3.X/dist-packages only: the install then puts a floodplane.pth there naming the
install folder (python/path_file.cmake), from the folders --searched prints."""

import os
import site
import sys
import sysconfig


def install_dir():
    """The rule of catkin.builder.get_python_install_dir, for this interpreter."""
    debian = os.path.exists("/etc/debian_version")
    major, minor = sys.version_info[:2]
    version = str(major) if debian and major == 3 else f"{major}.{minor}"
    return os.path.join("lib", f"python{version}", "dist-packages" if debian else "site-packages")


def searched_dirs():
    """The interpreter's own install folder and its site folders, each once, real paths."""
    folders = []
    for folder in [sysconfig.get_path("platlib"), sysconfig.get_path("purelib")] + site.getsitepackages():
        real = os.path.realpath(folder)
        if real not in folders:
            folders.append(real)
    return folders


if __name__ == "__main__":
    if sys.argv[1:] == ["--searched"]:
        print("\n".join(searched_dirs()))
    elif not sys.argv[1:]:
        print(install_dir())
    else:
        sys.exit("usage: site_packages_dir.py [--searched]")
