# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
"""The documentation holds to the code: the README is a front page of at most 300 lines that
opens with its two commands and links every page of docs/; every relative link of the README,
docs/ and bench/README.md names a file that exists (and a heading of it, for an #anchor); and
every code block marked `<!-- example: FILE -->` is lines of FILE, in order, a file the tests
build and run (examples/consumer by the Package tests, examples/python by test_example.py)."""

import os
import pathlib
import re

import pytest

SOURCE = pathlib.Path(os.environ.get("FLOODPLANE_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
PAGES = [SOURCE / "README.md", SOURCE / "bench/README.md", *sorted((SOURCE / "docs").glob("*.md"))]


def slug(heading):
    """The anchor GitHub gives a heading: lower case, punctuation dropped, spaces as hyphens."""
    return re.sub(r"[^\w\- ]", "", heading.strip().lower()).replace(" ", "-")


def anchors(page):
    text = re.sub(r"```.*?```", "", page.read_text(encoding="utf-8"), flags=re.S)
    return {slug(heading) for heading in re.findall(r"^#+ (.*?)(?: \{#\w+\})?$", text, flags=re.M)}


def links(page):
    """The relative targets of a page's markdown links and images (outside code)."""
    text = re.sub(r"```.*?```", "", page.read_text(encoding="utf-8"), flags=re.S)
    text = re.sub(r"`[^`\n]*`", "", text)
    targets = re.findall(r"\]\(([^)\s]+)\)", text) + re.findall(r'<img src="([^"]+)"', text)
    return [target for target in targets if not re.match(r"^[a-z]+:", target)]


def test_the_readme_is_a_front_page_with_its_two_commands_first():
    readme = (SOURCE / "README.md").read_text(encoding="utf-8")
    assert readme.count("\n") <= 300
    first_block = re.search(r"```\n(.*?)```", readme, flags=re.S).group(1).splitlines()
    assert [line.split()[0] for line in first_block] == ["scripts/demo.sh", "scripts/test.sh"]
    for page in sorted((SOURCE / "docs").glob("*.md")):
        if page.name != "api.md":  # Doxygen's main page, built by the target docs
            assert f"(docs/{page.name})" in readme, f"the README does not link docs/{page.name}"


def test_the_benchmarks_page_is_one_page_of_figures():
    assert (SOURCE / "bench/README.md").read_text(encoding="utf-8").count("\n") <= 250


@pytest.mark.parametrize("page", PAGES, ids=lambda page: str(page.relative_to(SOURCE)))
def test_every_relative_link_names_a_file_and_a_heading_there(page):
    for target in links(page):
        path, _, anchor = target.partition("#")
        linked = (page.parent / path).resolve() if path else page
        assert linked.exists(), f"{page.name} links {target}, which does not exist"
        if anchor and linked.suffix == ".md":
            assert anchor in anchors(linked), f"{page.name} links {target}: {linked.name} has no such heading"


def examples():
    for page in PAGES:
        text = page.read_text(encoding="utf-8")
        for source, block in re.findall(r"<!-- example: (\S+) -->\n```\w*\n(.*?)```", text, flags=re.S):
            yield pytest.param(page, source, block, id=f"{page.relative_to(SOURCE)}:{source}")


@pytest.mark.parametrize("page,source,block", list(examples()))
def test_every_marked_example_is_lines_of_its_source_in_order(page, source, block):
    lines = iter(line.strip() for line in (SOURCE / source).read_text(encoding="utf-8").splitlines())
    for line in block.splitlines():
        line = line.strip()
        if not line or line.startswith("..."):  # an elision: what the reader may fill in
            continue
        assert any(line == candidate for candidate in lines), f"{page.name}: not in {source} (in order): {line}"


def test_there_are_marked_examples_in_the_readme():
    assert {source for page, source, _ in (p.values for p in examples()) if page.name == "README.md"} == {
        "examples/consumer/main.cpp", "examples/python/planes_and_objects.py"}
