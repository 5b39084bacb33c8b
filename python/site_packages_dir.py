# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
"""Prints where the floodplane package goes under an install prefix, relative to it, as the
interpreter that runs this script sees it (CMake runs it with the one it builds for).

    python3 site_packages_dir.py /usr/local     ->  lib/python3.11/dist-packages (Debian 12)

Under a prefix the interpreter searches, the folder it searches there, its default install
folder first: Debian's python3 looks in /usr/local/lib/python3.X/dist-packages, not in
/usr/local/lib/python3/dist-packages, and in /usr/lib/python3/dist-packages. Under any other
prefix, the same layout as that default folder's (lib/python3.X/dist-packages on Debian), for
PYTHONPATH."""

import os
import site
import sys
import sysconfig


def relative_folder(folder, prefix):
    """`folder` relative to `prefix` when it lies under prefix/lib, else None."""
    relative = os.path.relpath(os.path.realpath(folder), os.path.realpath(prefix))
    return relative if relative.split(os.sep)[0] == "lib" else None


def main(prefix):
    default = sysconfig.get_path("platlib")
    searched = [default] + site.getsitepackages()
    for folder in searched:
        relative = relative_folder(folder, prefix)
        if relative:
            return relative
    # Another prefix: the default folder's path from its lib/ on.
    parts = os.path.realpath(default).split(os.sep)
    if "lib" not in parts:
        return os.path.join("lib", f"python{sys.version_info.major}.{sys.version_info.minor}", "site-packages")
    lib = len(parts) - 1 - parts[::-1].index("lib")
    return os.path.join(*parts[lib:])


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: site_packages_dir.py <install prefix>")
    print(main(sys.argv[1]))
