#!/usr/bin/python3
# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
"""Fails when a function in the library's sources is longer than the limit (60 lines).

Usage: scripts/check_function_size.py [--limit N] [--list] [PATH ...]   (default: src/)

A function's length is the lines of its body, from the line of its opening brace to the line
of its closing brace, as clang-tidy's readability-function-size counts them (LineThreshold),
for every function, member function, constructor, operator and lambda defined at namespace or
class scope; a lambda or local class inside a function counts as part of that function.
A long function is a reader's problem wherever it is: a stage that needs more is several
steps, each with a name. The check reads the sources as text: comments and string literals
are blanked first, then each `{` whose statement (the text since the last `;`, `{` or `}` at
that scope) looks like a function head -- a parenthesised parameter list, possibly followed by
qualifiers, a trailing return type or a constructor's initializer list -- opens a function.
`--list` prints every function's length, longest first.
"""

import argparse
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
EXTENSIONS = {".cpp", ".h", ".hpp"}
# Statements that open a scope which is not a function.
NOT_FUNCTION = re.compile(r"^\s*(template\s*<.*>\s*)?(namespace|class|struct|union|enum|extern)\b", re.S)
CONTROL = re.compile(r"\b(if|for|while|switch|catch|do|else|try)\s*(\(|$)")


def blank(text):
    """`text` with comments, string and character literals replaced by spaces (newlines kept)."""
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i))
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c == 'R' and text.startswith('R"', i):
            m = re.match(r'R"([^(]*)\(', text[i:])
            end = text.find(")" + m.group(1) + '"', i) if m else -1
            j = n if end < 0 else end + len(m.group(1)) + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c in "\"'":
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == "\\" else 1
            out.append(" " * (min(j + 1, n) - i))
            i = j + 1
        else:
            out.append(c)
            i += 1
    return "".join(out)


def looks_like_function(head):
    head = head.strip()
    if not head or NOT_FUNCTION.match(head) or head.endswith("="):
        return False
    # The last top-level parenthesis group, then what may follow a parameter list.
    if CONTROL.search(head.split("\n")[-1]) and not re.search(r"\)\s*(const|noexcept|override|->)", head):
        return False
    m = re.search(r"\)\s*(const\b|noexcept\b(\s*\([^)]*\))?|override\b|final\b|mutable\b|&&?|->[^{;]*|\s)*"
                  r"(:\s*[\w:<>,\s]+\s*[({][\s\S]*)?$", head)
    if not m:
        return False
    name = head[:head.find("(")] if "(" in head else ""
    if re.search(r"\b(if|for|while|switch|catch|return)\s*$", name):
        return False
    return "(" in head


def functions(path):
    """(name, first line, body lines) of each function defined at namespace or class scope."""
    text = blank(path.read_text(encoding="utf-8"))
    found = []
    stack = []  # per open brace: (is function, start line, head)
    head_start = 0
    line = 1
    inside = 0  # open braces of functions on the stack
    for i, c in enumerate(text):
        if c == "\n":
            line += 1
        elif c == "{":
            head = text[head_start:i]
            is_function = inside == 0 and looks_like_function(head)
            stack.append((is_function, line, head))
            if is_function or inside:
                inside += 1
            head_start = i + 1
        elif c == "}":
            if stack:
                is_function, start, head = stack.pop()
                if inside:
                    inside -= 1
                if is_function:
                    name = re.sub(r"\s+", " ", head.strip().split("(")[0]).split(" ")[-1]
                    found.append((name, start, line - start + 1))
            head_start = i + 1
        elif c == ";" and not inside:
            head_start = i + 1
    return found


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--limit", type=int, default=60)
    parser.add_argument("--list", action="store_true")
    parser.add_argument("paths", nargs="*")
    args = parser.parse_args()
    paths = [pathlib.Path(p) for p in args.paths] or [ROOT / "src"]
    files = []
    for p in paths:
        files += sorted(f for f in p.rglob("*") if f.suffix in EXTENSIONS) if p.is_dir() else [p]
    rows = []
    for f in files:
        for name, start, length in functions(f):
            rows.append((length, f"{f.relative_to(ROOT) if f.is_relative_to(ROOT) else f}:{start}", name))
    rows.sort(reverse=True)
    if args.list:
        for length, where, name in rows:
            print(f"{length:5d}  {where}  {name}")
        return 0
    long = [r for r in rows if r[0] > args.limit]
    for length, where, name in long:
        print(f"{where}: {name} is {length} lines long (limit {args.limit}): split it into named steps",
              file=sys.stderr)
    if long:
        print(f"check_function_size: {len(long)} functions over {args.limit} lines", file=sys.stderr)
        return 1
    print(f"check_function_size: {len(rows)} functions in {len(files)} files, none over {args.limit} lines")
    return 0


if __name__ == "__main__":
    sys.exit(main())
