#!/usr/bin/python3
# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
"""A compiler launcher (CMAKE_CXX_COMPILER_LAUNCHER) that copies an object file from another
build tree instead of compiling it, when that tree compiled the same source with the same
command and its object is newer than every file the compiler read for it; otherwise it
compiles. scripts/check_build_variant.sh uses it so that a variant of the libraries (shared,
without PCL) does not compile again what the tests' own build has just compiled: the library's
sources are compiled with identical flags in each, only the configure, the link and the install
differ, and those are what the variant checks check.

Usage: compile_or_reuse.py <compiler> <arguments...>, with in the environment
  FLOODPLANE_REUSE_BUILD  the build tree to take objects from (configured with
                          CMAKE_EXPORT_COMPILE_COMMANDS, as floodplane's is with tests)
  FLOODPLANE_REUSE_INTO   this build tree (its path stands for the other one's in commands)
  FLOODPLANE_REUSE_LOG    optional: a file that gets one line per object, "reused" or
                          "compiled" and why
Two commands are the same when their words are, after the path of this tree is replaced by the
other's, and without the -D<target>_EXPORTS definition CMake adds to the sources of a shared
library (no floodplane source reads it).
"""
import json
import os
import re
import shlex
import shutil
import subprocess
import sys

EXPORTS_DEFINITION = re.compile(r"^-D\w+_EXPORTS$")


def normalized(words):
    """The words that decide the object: without CMake's shared-library definition and the
    dependency file's options (-MD, -MT <target>, -MF <file>), which compile_commands.json may
    leave out."""
    kept, skip = [], False
    for word in words:
        if skip:
            skip = False
        elif word in ("-MT", "-MF", "-MQ"):
            skip = True
        elif word != "-MD" and not EXPORTS_DEFINITION.match(word):
            kept.append(word)
    return kept


def output_of(words):
    return words[words.index("-o") + 1] if "-o" in words else None


def newer_than_its_inputs(obj):
    """True when the object is newer than every file its depfile (<object>.d) lists."""
    depfile = obj + ".d"
    if not os.path.exists(depfile):
        return False
    with open(depfile, encoding="utf-8", errors="replace") as f:
        text = f.read().replace("\\\n", " ")
    # "target.o: dep dep ...": the first word is the target; escaped spaces do not occur in our paths.
    inputs = text.split(":", 1)[1].split() if ":" in text else []
    stamp = os.path.getmtime(obj)
    try:
        return all(os.path.getmtime(path) <= stamp for path in inputs)
    except OSError:  # a file the object was built from is gone
        return False


def reusable_object(words):
    """The other tree's object for this command, or None and the reason."""
    source_tree = os.environ.get("FLOODPLANE_REUSE_BUILD")
    this_tree = os.environ.get("FLOODPLANE_REUSE_INTO")
    if not source_tree or not this_tree:
        return None, "no FLOODPLANE_REUSE_BUILD/INTO"
    source_tree, this_tree = os.path.realpath(source_tree), os.path.realpath(this_tree)
    out = output_of(words)
    if out is None:
        return None, "no -o"
    out_abs = os.path.realpath(out)
    if not out_abs.startswith(this_tree + os.sep):
        return None, "object outside the tree"
    relative = os.path.relpath(out_abs, this_tree)
    database = os.path.join(source_tree, "compile_commands.json")
    if not os.path.exists(database):
        return None, "no compile_commands.json in " + source_tree
    with open(database, encoding="utf-8") as f:
        entries = json.load(f)
    mapped = normalized([w.replace(this_tree, source_tree) for w in words])
    for entry in entries:
        other = entry.get("arguments") or shlex.split(entry["command"])
        other_out = output_of(other)
        if other_out is None:
            continue
        other_abs = os.path.realpath(os.path.join(entry["directory"], other_out))
        if os.path.relpath(other_abs, source_tree) != relative:
            continue
        if normalized(other) != mapped:
            return None, "another command: " + " ".join(sorted(set(other) ^ set(mapped)))
        if not os.path.exists(other_abs):
            return None, "not built there"
        if not newer_than_its_inputs(other_abs):
            return None, "out of date there"
        return (other_abs, source_tree, this_tree), "same command, up to date"
    return None, "not compiled there"


def main():
    words = sys.argv[1:]
    found, why = reusable_object(words)
    log = os.environ.get("FLOODPLANE_REUSE_LOG")
    if found:
        found, source_tree, this_tree = found
        out = output_of(words)
        os.makedirs(os.path.dirname(os.path.abspath(out)), exist_ok=True)
        shutil.copy2(found, out)
        # make's and Ninja's dependency scanning read the depfile: the same one, for this tree.
        with open(found + ".d", encoding="utf-8", errors="replace") as f:
            dependencies = f.read().replace(source_tree, this_tree)
        with open(out + ".d", "w", encoding="utf-8") as f:
            f.write(dependencies)
    if log:
        with open(log, "a", encoding="utf-8") as f:
            f.write(f"{'reused' if found else 'compiled'} {output_of(words)}: {why}\n")
    if found:
        return 0
    return subprocess.call(words)


if __name__ == "__main__":
    sys.exit(main())
