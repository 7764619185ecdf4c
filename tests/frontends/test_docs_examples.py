"""The examples in README.md and docs/ are tested text (issue 31, point 6).

Every fenced block of the pages below is read and sorted by what it shows;
the conventions, as a page author writes them:

* ```console (or sh, shell) blocks whose lines start with `$ `: a shell
  session. Each `$ ` line is a command (a line ending in a backslash, or
  lines starting with `> ` after it, continue it); the lines up to the next
  `$ ` line are its output, stdout and stderr together, compared exactly.
  The commands of a page run in order in one fresh folder per page, so an
  earlier command may write a file that a later one reads (the pages create
  their input files that way, in plain sight). `crspline` is the built CLI,
  `python3` the interpreter running this test, with the built module
  importable. The exit status must be 0, or 2 when the shown output has an
  error line (`crspline: ` not followed by `note:`).
* ```pycon blocks: run by Python's doctest module, the page's blocks in one
  namespace, in the same folder as the page's shell commands.
* a ```python block followed directly by a ```text block: the program's
  printed output must be that block; a ```python block without one must run
  without an error.
* `<!-- output of: COMMAND -->` on the line before a block: COMMAND is run as
  a session command and must print the block (for output shown without its
  command, like `./run demo`'s table). A ```json block is compared as JSON:
  the same keys in the same order and the same values (numbers exactly), where
  `...` in place of an object's last members or of a list's last items elides
  the rest; the text's layout does not matter.
* `<!-- not run: REASON -->` on the line before a block: skipped, counted.
* Anything else (```json, ```cpp, ```cmake, plain blocks) is shown text. A
  shown-text block with a line that starts like a command (`$ `, `>>> `)
  fails the test: it would look tested and not be. (README's C++ example and
  its output are checked by the examples.readme_shows_quickstart case.)

Everywhere, doctest's ELLIPSIS applies: `...` in the shown output matches
any text. It is how a page says that digits legitimately vary; the test
has no tolerance of its own. The number of blocks run and skipped per page
is asserted (PAGES), so a block that stops being recognised fails the test,
and test_a_changed_digit_fails checks that a changed digit in a shown output
fails a page.

By hand (a build with the CLI and the Python module):

    CRSPLINE_BIN=build/rel/cli/crspline PYTHONPATH=build/rel/python \\
        /usr/bin/python3 -m pytest -q -p no:cacheprovider tests/frontends/test_docs_examples.py
"""
import contextlib
import doctest
import io
import json
import os
import pathlib
import re
import subprocess
import sys

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]

# Page -> (blocks run, blocks skipped). A run shell block counts once
# however many commands it holds.
PAGES = {
    "README.md": (2, 1),
    "docs/cli.md": (3, 2),
    "docs/python.md": (2, 4),
    "docs/spec.md": (0, 0),
    "docs/report.md": (1, 0),
    "docs/analysis.md": (0, 0),
    # Issue 42: the pages the rotation, GIS, web, fit and sweep rounds
    # added. js.md's and web.md's ```js blocks are run in node against the
    # installed npm package by js/test/docs.test.mjs (the web stage: the
    # WebAssembly module is built there); their shell blocks build, serve or
    # pack, and are marked.
    "docs/geo.md": (3, 4),
    "docs/rotation.md": (2, 0),
    "docs/js.md": (0, 1),
    "docs/web.md": (0, 3),
    "docs/fit.md": (2, 0),
    "docs/sweep.md": (3, 0),
}

FENCE = re.compile(r"^(\s*)(```+)\s*([\w+-]*)\s*$")
MARKER = re.compile(r"^<!--\s*(not run|output of):\s*(.*?)\s*-->$")
SHELL_LANGS = {"console", "sh", "shell", "bash"}
CHECKER = doctest.OutputChecker()


class Block:
    def __init__(self, page, line, lang, text, marker):
        self.page, self.line, self.lang, self.text, self.marker = page, line, lang, text, marker

    def where(self):
        return f"{self.page}:{self.line}"


def read_blocks(page, text):
    """The fenced blocks of a Markdown page, each with its language, its text
    (the fence's indentation removed) and the marker comment on the nearest
    non-blank line above it, if any."""
    blocks = []
    lines = text.split("\n")
    i = 0
    while i < len(lines):
        m = FENCE.match(lines[i])
        if not m:
            i += 1
            continue
        indent, ticks, lang = m.group(1), m.group(2), m.group(3).lower()
        start = i
        body = []
        i += 1
        while i < len(lines) and lines[i].strip() != ticks:
            body.append(lines[i][len(indent):] if lines[i].startswith(indent) else lines[i].lstrip())
            i += 1
        assert i < len(lines), f"{page}:{start + 1}: a code block is not closed"
        above = start - 1
        while above >= 0 and not lines[above].strip():
            above -= 1
        marker = MARKER.match(lines[above].strip()) if above >= 0 else None
        blocks.append(Block(page, start + 1, lang, "\n".join(body) + ("\n" if body else ""),
                            (marker.group(1), marker.group(2)) if marker else None))
        i += 1
    return blocks


def session_commands(block):
    """The `$ ` commands of a shell session and the output shown after each:
    [(line number, command, expected output)]."""
    out = []
    lines = block.text.split("\n")
    if lines and lines[-1] == "":
        lines.pop()
    i = 0
    while i < len(lines):
        line = lines[i]
        assert line.startswith("$ "), (f"{block.where()}: text before the first `$ ` command of a "
                                       f"session: {line!r}")
        number = block.line + 1 + i
        command = line[2:]
        i += 1
        while command.endswith("\\") or (i < len(lines) and lines[i].startswith("> ")):
            if i >= len(lines):
                break
            command += "\n" + (lines[i][2:] if lines[i].startswith("> ") else lines[i])
            i += 1
        expected = []
        while i < len(lines) and not lines[i].startswith("$ "):
            expected.append(lines[i])
            i += 1
        out.append((number, command, "".join(l + "\n" for l in expected)))
    return out


def is_session(block):
    return block.lang in SHELL_LANGS and any(l.startswith("$ ") for l in block.text.split("\n"))


def looks_like_command(block):
    return any(l.startswith(("$ ", ">>> ")) for l in block.text.split("\n"))


class Page:
    """Runs one page's examples in one folder and one Python namespace."""

    def __init__(self, name, folder, env):
        self.name, self.folder, self.env = name, folder, env
        self.globs = {"__name__": "__docs__"}
        self.failures = []

    def fail(self, where, message):
        self.failures.append(f"{where}: {message}")

    def shell(self, where, command, expected):
        p = subprocess.run(["bash", "-o", "pipefail", "-c", command], cwd=self.folder, env=self.env,
                           stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, encoding="utf-8",
                           timeout=120)
        error_shown = any(l.startswith("crspline: ") and not l.startswith("crspline: note:")
                          for l in expected.split("\n"))
        status = 2 if error_shown else 0
        if p.returncode != status:
            self.fail(where, f"`{command}` exited with {p.returncode}, expected {status}; it printed:\n"
                      f"{p.stdout}")
        return p.stdout

    def compare(self, where, what, expected, got):
        if not CHECKER.check_output(expected, got, doctest.ELLIPSIS):
            self.fail(where, f"{what}: the page shows\n{expected}but it prints\n{got}")

    def run_block(self, block, following):
        """Runs a block; returns True when it ran, False when it is shown text."""
        if block.marker and block.marker[0] == "output of":
            command = block.marker[1]
            got = self.shell(block.where(), command, "" if block.lang == "json" else block.text)
            if block.lang == "json":
                compare_json(self, block, command, got)
            else:
                self.compare(block.where(), f"`{command}`", block.text, got)
            return True
        if is_session(block):
            for number, command, expected in session_commands(block):
                where = f"{block.page}:{number}"
                self.compare(where, f"`{command}`", expected, self.shell(where, command, expected))
            return True
        if block.lang == "pycon":
            test = doctest.DocTestParser().get_doctest(block.text, self.globs, block.where(), block.page,
                                                       block.line)
            report = io.StringIO()
            runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS)
            with contextlib.chdir(self.folder):
                result = runner.run(test, out=report.write, clear_globs=False)
            if result.failed:
                self.fail(block.where(), f"doctest failed:\n{report.getvalue()}")
            if result.attempted == 0:
                self.fail(block.where(), "a pycon block without a `>>> ` example")
            return True
        if block.lang == "python":
            shown = following.text if following is not None and following.lang == "text" else ""
            printed = io.StringIO()
            try:
                with contextlib.chdir(self.folder), contextlib.redirect_stdout(printed):
                    exec(compile(block.text, block.where(), "exec"), self.globs)
            except Exception as e:  # noqa: BLE001 (any error of the snippet is the failure)
                self.fail(block.where(), f"the snippet raised {type(e).__name__}: {e}")
                return True
            self.compare(block.where(), "the Python snippet", shown, printed.getvalue())
            return True
        return False

    def run(self, blocks):
        """Runs every block; returns (run, skipped) counts."""
        ran = skipped = 0
        consumed = set()
        for k, block in enumerate(blocks):
            if k in consumed:
                continue
            if block.marker and block.marker[0] == "not run":
                if not block.marker[1]:
                    self.fail(block.where(), "a `not run` marker must say why")
                skipped += 1
                continue
            following = blocks[k + 1] if k + 1 < len(blocks) else None
            if block.lang == "python" and following is not None and following.lang == "text":
                consumed.add(k + 1)
            if self.run_block(block, following):
                ran += 1
            elif block.lang in SHELL_LANGS:
                self.fail(block.where(), "a shell block without `$ ` commands: show their output as a "
                          "session, or mark it <!-- not run: why -->")
            elif looks_like_command(block):
                self.fail(block.where(), f"a ```{block.lang} block with a command in it is neither run "
                          "nor marked <!-- not run: why -->")
        return ran, skipped


ELIDED = "\u2026elided"


def parse_shown_json(text):
    """The shown JSON with `...` elisions: `, ...}` / `{...}` become a member
    ELIDED, `, ...]` / `[...]` a last item ELIDED."""
    text = re.sub(r"(,\s*|\{\s*)\.\.\.(\s*\})", lambda m: m.group(1) + f'"{ELIDED}": true' + m.group(2), text)
    text = re.sub(r"(,\s*|\[\s*)\.\.\.(\s*\])", lambda m: m.group(1) + f'"{ELIDED}"' + m.group(2), text)
    return json.loads(text)


def json_differences(got, shown, path="$"):
    if isinstance(shown, dict):
        if not isinstance(got, dict):
            return [f"{path}: {got!r} is not an object"]
        keys = [k for k in shown if k != ELIDED]
        got_keys = list(got)[:len(keys)] if ELIDED in shown else list(got)
        if got_keys != keys:
            return [f"{path}: keys {list(got)} vs shown {keys}"]
        return [d for k in keys for d in json_differences(got[k], shown[k], f"{path}.{k}")]
    if isinstance(shown, list):
        if not isinstance(got, list):
            return [f"{path}: {got!r} is not a list"]
        items = shown[:-1] if shown and shown[-1] == ELIDED else shown
        if len(got) < len(items) or (len(items) == len(shown) and len(got) != len(shown)):
            return [f"{path}: {len(got)} items vs {len(shown)} shown"]
        return [d for i, s in enumerate(items) for d in json_differences(got[i], s, f"{path}[{i}]")]
    if type(got) is not type(shown) or got != shown:
        return [f"{path}: prints {json.dumps(got)}, the page shows {json.dumps(shown)}"]
    return []


def compare_json(page, block, command, got):
    try:
        shown = parse_shown_json(block.text)
    except json.JSONDecodeError as e:
        page.fail(block.where(), f"the shown JSON does not parse ({e})")
        return
    try:
        printed = json.loads(got)
    except json.JSONDecodeError as e:
        page.fail(block.where(), f"`{command}` printed no JSON ({e}):\n{got}")
        return
    for d in json_differences(printed, shown)[:10]:
        page.fail(block.where(), d)


@pytest.fixture(scope="module")
def env(tmp_path_factory):
    """The environment of the pages' commands: `crspline` and `python3` first on PATH."""
    cli = os.environ.get("CRSPLINE_BIN")
    if not cli:
        raise RuntimeError("set CRSPLINE_BIN to the crspline executable (CTest does this)")
    bin_dir = tmp_path_factory.mktemp("bin")
    (bin_dir / "crspline").symlink_to(pathlib.Path(cli).resolve())
    (bin_dir / "python3").symlink_to(sys.executable)
    out = dict(os.environ)
    out["PATH"] = f"{bin_dir}{os.pathsep}{out.get('PATH', '')}"
    out["LC_ALL"] = "C.UTF-8"
    return out


def run_page(name, text, folder, env):
    page = Page(name, folder, env)
    counts = page.run(read_blocks(name, text))
    return page, counts


@pytest.mark.parametrize("name", sorted(PAGES))
def test_page(name, env, tmp_path):
    page, counts = run_page(name, (ROOT / name).read_text(encoding="utf-8"), tmp_path, env)
    assert not page.failures, f"{len(page.failures)} mismatches in {name}:\n\n" + "\n\n".join(page.failures)
    assert counts == PAGES[name], (f"{name}: ran {counts[0]} blocks and skipped {counts[1]}, expected "
                                   f"{PAGES[name][0]} and {PAGES[name][1]} (a block added, removed or no "
                                   f"longer recognised: update PAGES when that is meant)")


def test_a_changed_digit_fails(env, tmp_path):
    """The comparison can fail: README.md with one digit of a shown output
    changed (in each kind of run block) must give a mismatch there."""
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    blocks = read_blocks("README.md", text)
    runnable = [b for b in blocks if is_session(b) or (b.marker and b.marker[0] == "output of")]
    assert len(runnable) == PAGES["README.md"][0], "README.md's run blocks changed: update this test"
    changed = 0
    for b in runnable:
        # The first digit in the block's shown output (not in a command).
        body_lines = b.text.split("\n")
        for k, line in enumerate(body_lines):
            if is_session(b) and line.startswith("$ "):
                continue
            m = re.search(r"\d", line)
            if m:
                digit = str((int(m.group()) + 1) % 10)
                body_lines[k] = line[:m.start()] + digit + line[m.end():]
                break
        else:
            continue
        mutated = text.replace(b.text, "\n".join(body_lines), 1)
        assert mutated != text
        folder = tmp_path / f"changed{changed}"
        folder.mkdir()
        page, _ = run_page("README.md", mutated, folder, env)
        assert page.failures, \
            f"a changed digit in the block at line {b.line} was not noticed"
        changed += 1
    assert changed == len(runnable), f"found a digit to change in {changed} of {len(runnable)} run blocks"
