"""docs/architecture.md matches the tree (issue 42).

What the page names in backticks must exist, and what the core has must be
named:

* every path it names (a file with an extension or a folder ending in `/`)
  exists: one starting with a top-level folder of the repository (`cli/`,
  `web/src/`, ...) from the repository's root, any other from
  include/crspline/ (so `decision/engine.hpp` is
  include/crspline/decision/engine.hpp; `NAME` in a path is a placeholder
  and is not checked);
* every public header (include/crspline/**/*.hpp outside a detail/ folder)
  is named, by its path relative to include/crspline/;
* every folder of include/crspline/ is named (with its trailing `/`).

A header added to the core without a line on the page fails the second
check: test_an_unnamed_header_fails checks that it does, on a copy of the
page with one header's name removed. Needs nothing built.
"""
import pathlib
import re

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
CORE = ROOT / "include" / "crspline"
PAGE = ROOT / "docs" / "architecture.md"

CODE = re.compile(r"`([^`\s]+)`")
PATHLIKE = re.compile(r"^[\w./-]+(/|\.(hpp|cpp|py|mjs|js|md|sh|txt))$")


def named_paths(text):
    """The paths a page names in backticks (placeholders with NAME left out)."""
    return {m for m in CODE.findall(text) if PATHLIKE.match(m) and "NAME" not in m}


def resolve(name):
    top = name.split("/", 1)[0]
    if "/" in name and (ROOT / top).is_dir() and top not in {p.name for p in CORE.iterdir() if p.is_dir()}:
        return ROOT / name
    return CORE / name


def public_headers():
    return sorted(p.relative_to(CORE).as_posix() for p in CORE.rglob("*.hpp")
                  if "detail" not in p.relative_to(CORE).parts)


def core_folders():
    return sorted(p.relative_to(CORE).as_posix() + "/" for p in CORE.rglob("*") if p.is_dir())


def problems(text):
    names = named_paths(text)
    out = [f"the page names `{n}`, which does not exist ({resolve(n)})" for n in sorted(names)
           if not resolve(n).exists()]
    out += [f"public header {h} is not named on the page" for h in public_headers() if h not in names]
    out += [f"folder include/crspline/{f} is not named on the page" for f in core_folders()
            if f not in names and "include/crspline/" + f not in names]
    return out


def test_page_matches_tree():
    text = PAGE.read_text(encoding="utf-8")
    # The check has something to check: the core's headers and folders, and the page's names.
    assert len(public_headers()) >= 40 and len(core_folders()) >= 5 and len(named_paths(text)) >= 60
    found = problems(text)
    assert not found, "docs/architecture.md does not match the tree:\n" + "\n".join(found)


@pytest.mark.parametrize("header", ["decision/krawczyk.hpp", "arc_length_table.hpp"])
def test_an_unnamed_header_fails(header):
    """The page without one header's name (as if the header were new) fails."""
    text = PAGE.read_text(encoding="utf-8")
    assert f"`{header}`" in text
    found = problems(text.replace(f"`{header}`", "the header"))
    assert found == [f"public header {header} is not named on the page"]


def test_a_missing_path_fails():
    text = PAGE.read_text(encoding="utf-8") + "\n`decision/no_such_part.hpp`, `web/src/no_such.cpp`\n"
    found = problems(text)
    assert len(found) == 2 and all("does not exist" in f for f in found), found
