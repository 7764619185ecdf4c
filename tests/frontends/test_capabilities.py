"""What a user sees first lists what crspline does today (issue 42, point 4).

`crspline --help`, `help(crspline)` in Python and the npm package's README
(js/README.md) each have one entry per capability below, each entry naming
the capability's page (docs/NAME.md), and that page exists. An entry is a
line starting with the capability's name (`  NAME  ` in the command's
footer, `* NAME:` in the docstring, `- NAME:` in the README) and the lines
that continue it. The project's README.md links every one of those pages.
A capability added to crspline is added here, and the four places then
fail until they list it.

Needs the built CLI (CRSPLINE_BIN) and the Python package on PYTHONPATH, as
the other tests of this folder.
"""
import os
import pathlib
import pydoc
import re
import subprocess

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]

# Capability -> its page (curves: each front end's own page).
CAPABILITIES = {
    "curves": None,
    "decision": "docs/analysis.md",
    "rotations": "docs/rotation.md",
    "GIS smoothing": "docs/geo.md",
    "fit": "docs/fit.md",
    "sweeps/strokes": "docs/sweep.md",
    "rotation fit": "docs/rotation.md",
}
CURVES_PAGE = {"cli": "docs/cli.md", "python": "docs/python.md", "js": "docs/js.md"}


def entries(text, start):
    """{name: entry text} for the lines matching `start` (a regex whose group 1
    is the name) and their continuation lines (more indented, or not starting
    another entry)."""
    out = {}
    lines = text.split("\n")
    for i, line in enumerate(lines):
        m = re.match(start, line)
        if not m:
            continue
        indent = len(line) - len(line.lstrip())
        body = [line]
        for nxt in lines[i + 1:]:
            if not nxt.strip() or re.match(start, nxt) or len(nxt) - len(nxt.lstrip()) <= indent:
                break
            body.append(nxt)
        out[m.group(1)] = " ".join(s.strip() for s in body)
    return out


def check(where, found):
    problems = []
    for name, page in CAPABILITIES.items():
        page = page or CURVES_PAGE[where]
        if name not in found:
            problems.append(f"{where}: no entry for {name!r} (entries: {sorted(found)})")
        elif page not in found[name]:
            problems.append(f"{where}: the entry for {name!r} does not point to {page}: {found[name]!r}")
        if not (ROOT / page).is_file():
            problems.append(f"{where}: {page} does not exist")
    return problems


def cli_help():
    cli = os.environ.get("CRSPLINE_BIN")
    if not cli:
        raise RuntimeError("set CRSPLINE_BIN to the crspline executable (CTest does this)")
    p = subprocess.run([cli, "--help"], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, check=True)
    return p.stdout


def python_help():
    import crspline
    return pydoc.render_doc(crspline, renderer=pydoc.plaintext)


NAMES = "|".join(re.escape(n) for n in CAPABILITIES)
SOURCES = {
    "cli": (cli_help, rf"^  ({NAMES})  "),
    "python": (python_help, rf"^\s*\* ({NAMES}): "),
    "js": (lambda: (ROOT / "js" / "README.md").read_text(encoding="utf-8"), rf"^- ({NAMES}): "),
}


@pytest.mark.parametrize("where", sorted(SOURCES))
def test_lists_every_capability(where):
    read, start = SOURCES[where]
    problems = check(where, entries(read(), start))
    assert not problems, "\n".join(problems)


def test_a_missing_entry_fails():
    """The check can fail: the README without its fit line, and with the
    decision line pointing elsewhere."""
    text = (ROOT / "js" / "README.md").read_text(encoding="utf-8")
    start = SOURCES["js"][1]
    without_fit = "\n".join(l for l in text.split("\n") if not l.startswith("- fit:"))
    assert check("js", entries(without_fit, start)) == [
        f"js: no entry for 'fit' (entries: {sorted(set(CAPABILITIES) - {'fit'})})"]
    moved = text.replace("crosses or touches (docs/analysis.md)", "crosses or touches (docs/report.md)")
    assert len(check("js", entries(moved, start))) == 1


def readme_problems(text):
    """The project's README.md links every capability's page (and each front
    end's curves page) as `](docs/NAME.md)`: a reader of the first page
    finds them all."""
    pages = {p for p in CAPABILITIES.values() if p} | set(CURVES_PAGE.values())
    return [f"README.md: no link to {p}" for p in sorted(pages) if f"]({p})" not in text]


def test_readme_links_every_capability_page():
    assert not readme_problems((ROOT / "README.md").read_text(encoding="utf-8"))
    # The check can fail: the README without its fitting line.
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    without = "\n".join(l for l in text.split("\n") if not l.startswith("Fitting ("))
    assert readme_problems(without) == ["README.md: no link to docs/fit.md"]
