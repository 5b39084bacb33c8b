# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
"""scripts/check_function_size.py, the 60-line rule CI applies to src/: on made-up sources whose
function lengths are known, and on the library itself."""

import os
import pathlib
import subprocess
import sys

SOURCE = pathlib.Path(os.environ.get("FLOODPLANE_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
SCRIPT = SOURCE / "scripts/check_function_size.py"


def check(*args):
    return subprocess.run([sys.executable, str(SCRIPT), *map(str, args)], capture_output=True, text=True)


def body(lines):
    return "".join(f"  x += {k};\n" for k in range(lines))


def test_a_function_over_the_limit_fails_with_its_name_and_length(tmp_path):
    source = tmp_path / "long.cpp"
    # From the opening brace's line to the closing one's: 1 + 61 + 1 + 1.
    source.write_text("namespace a {\nint longOne(int x) {\n" + body(61) + "  return x;\n}\n}  // namespace a\n")
    result = check("--limit", 62, source)
    assert result.returncode == 1
    assert "longOne is 64 lines long (limit 62)" in result.stderr


def test_a_function_at_the_limit_passes(tmp_path):
    source = tmp_path / "short.cpp"
    source.write_text("int shortOne(int x) {\n" + body(57) + "  return x;\n}\n")
    result = check(source)
    assert result.returncode == 0, result.stderr
    assert "none over 60 lines" in result.stdout


def test_lambdas_loops_and_comments_count_towards_their_function(tmp_path):
    source = tmp_path / "inner.cpp"
    inner = "  auto f = [&](int y) {\n" + body(30) + "    return y;\n  };\n"
    loop = "  for (int k = 0; k < 3; ++k) {\n" + body(30) + "  }\n"
    comment = "  // a comment with a { brace\n  const char* s = \"}\";\n"
    source.write_text("struct S {\n  int member(int x) const {\n" + inner + loop + comment + "    return x;\n  }\n};\n")
    listed = check("--list", source)
    assert listed.returncode == 0
    lengths = {line.split()[-1]: int(line.split()[0]) for line in listed.stdout.splitlines()}
    assert lengths == {"member": 70}  # its brace lines, the lambda 33, the loop 32, 4 more
    assert check(source).returncode == 1


def test_the_library_keeps_the_rule():
    result = check()
    assert result.returncode == 0, result.stderr
