# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
"""The type stubs (floodplane/__init__.pyi, with py.typed) cannot drift from the module: every
public name of the package and of the compiled module is in them and nothing else, every
class has the same public members, every function and method the same argument names, and
the keywords spelled out for **params are PARAMETER_NAMES (Tracker's: its options)."""

import ast
import inspect
import pathlib

import pytest

import floodplane
from floodplane import _floodplane

STUBS = pathlib.Path(floodplane.__file__).with_name("__init__.pyi")


def public(names):
    return {name for name in names if not name.startswith("_")}


@pytest.fixture(scope="module")
def stubs():
    tree = ast.parse(STUBS.read_text(), filename=str(STUBS))
    names, classes, functions = set(), {}, {}
    for node in tree.body:
        if isinstance(node, ast.ClassDef):
            names.add(node.name)
            classes[node.name] = {item.name: item for item in node.body if isinstance(item, ast.FunctionDef)}
            for method in classes[node.name].values():
                if not any(isinstance(d, ast.Name) and d.id == "property" for d in method.decorator_list):
                    functions.setdefault(f"{node.name}.{method.name}", []).append(method)
        elif isinstance(node, ast.FunctionDef):
            names.add(node.name)
            functions.setdefault(node.name, []).append(node)
        elif isinstance(node, ast.AnnAssign):
            names.add(node.target.id)
        elif isinstance(node, ast.Assign):
            names.update(target.id for target in node.targets)
    return names, classes, functions


def stub_arguments(function):
    """The argument names of a stub function (all overloads together), without self."""
    names = []
    for overload in function:
        arguments = overload.args
        for argument in arguments.posonlyargs + arguments.args + arguments.kwonlyargs:
            if argument.arg != "self" and argument.arg not in names:
                names.append(argument.arg)
    return names


def split_top_level(text):
    parts, depth, current = [], 0, ""
    for character in text:
        depth += character in "([{"
        depth -= character in ")]}"
        if character == "," and depth == 0:
            parts.append(current)
            current = ""
        else:
            current += character
    return parts + ([current] if current.strip() else [])


def runtime_arguments(function):
    """The argument names of a function of either kind, without self: from the signature
    (Python) or from the signature pybind11 writes on the docstring's first line."""
    try:
        signature = inspect.signature(function)
    except (TypeError, ValueError):
        line = function.__doc__.splitlines()[0]
        inside = line[line.index("(") + 1:line.rindex(") ->")]
        names = [part.split(":")[0].split("=")[0].strip() for part in split_top_level(inside)]
    else:
        names = [("**" if p.kind == p.VAR_KEYWORD else "") + name for name, p in signature.parameters.items()]
    return [name for name in names if name not in ("self", "*")]


def test_the_stubs_and_the_marker_are_where_the_package_is():
    assert STUBS.is_file()
    assert STUBS.with_name("py.typed").is_file()


def test_every_public_name_is_in_the_stubs_and_nothing_else(stubs):
    names, _, _ = stubs
    runtime = public(floodplane.__all__) | public(dir(_floodplane)) | {"__version__"}
    assert runtime - names == set(), "in the module, not in the stubs"
    assert (public(names) | {"__version__"}) - runtime == set(), "in the stubs, not in the module"


def test_every_class_has_the_same_members(stubs):
    _, classes, _ = stubs
    for name, members in classes.items():
        if name.startswith("_"):
            continue
        runtime = public(dir(getattr(floodplane, name)))
        assert public(members) == runtime, name


def test_every_function_and_method_has_the_same_argument_names(stubs):
    _, _, functions = stubs
    params = list(floodplane.PARAMETER_NAMES)
    tracker_options = list(floodplane.Tracker().options)
    checked = 0
    for qualified, function in functions.items():
        owner, _, name = qualified.rpartition(".")
        if owner.startswith("_") or name.startswith("_") and name != "__init__":
            continue
        target = getattr(getattr(floodplane, owner), name) if owner else getattr(floodplane, name)
        expected = runtime_arguments(target)
        if "**kwargs" in expected or "**params" in expected:
            # The keywords the stubs spell out for **params are the Segmenter's (Tracker's options).
            expected = [n for n in expected if not n.startswith("**")]
            expected += tracker_options if owner == "Tracker" else params
        assert stub_arguments(function) == expected, qualified
        checked += 1
    assert checked >= 20
