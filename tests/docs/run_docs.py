#!/usr/bin/python3
"""Runs the commands of the README and the tutorial pages as a reader would, and checks the
outputs the pages quote.

Usage: run_docs.py SWARMAGG SOURCE_DIR [PAGE ...]
(pages default: README.md, docs/worlds.md, docs/tutorial/*.md)

Each page runs in its own temporary folder holding `build/swarmagg` (the binary under test),
`build/python` (the Python package beside it, when built) and links to the repository's
worlds/, examples/, controllers/ and scripts/, so the pages' commands run as written from a
clone's root. Fenced blocks are read in page order:

- ```sh blocks run with bash (-e: every command must succeed); ```python blocks run with
  /usr/bin/python3. Other blocks (yaml, text, cpp, ...) are shown, not run.
- An HTML comment `<!-- docs-test: DIRECTIVE -->` before a block changes what happens to it:
    skip: REASON          the block is not run (e.g. it installs packages or needs Slurm);
    replace 'A' 'B'       run the block with the text A replaced by B (shorter durations);
    file PATH             write the block's text to PATH instead of running it;
    expect                the block is output: each of its lines must appear, in order, among
                          the lines the previous run block printed ('...' in a line matches
                          any text; a line of '...' alone matches nothing in particular).
- In a ```sh block, `python3` must be named /usr/bin/python3 (Debian's, with numpy/h5py).
- A page whose first comment is `<!-- docs-test: page run by TEST -->` is left to that test
  (the Python tutorial needs the module on PYTHONPATH; its own pytest runs it).
"""
import os
import re
import resource
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

PAGE_OWNER = re.compile(r"<!-- docs-test: page run by (\S+) -->")

DIRECTIVE = re.compile(r"<!--\s*docs-test:\s*(.*?)\s*-->")
FENCE = re.compile(r"^(\s*)```\s*([A-Za-z0-9_+-]*)\s*$")
REPLACE = re.compile(r"""^replace\s+'([^']*)'\s+'([^']*)'$""")
LINKED = ["worlds", "examples", "controllers", "scripts"]


class Block:
    def __init__(self, page, line, language, text, directives):
        self.page, self.line, self.language = page, line, language
        self.text, self.directives = text, directives

    def where(self):
        return f"{self.page}:{self.line}"


def read_blocks(page, source):
    """The fenced blocks of a page with the directives written before each."""
    blocks, pending = [], []
    lines = source.read_text().splitlines()
    k = 0
    while k < len(lines):
        for directive in DIRECTIVE.findall(lines[k]):
            pending.append(directive)
        fence = FENCE.match(lines[k])
        if fence:
            start, body = k + 1, []
            k += 1
            while k < len(lines) and lines[k].strip() != "```":
                body.append(lines[k][len(fence.group(1)):])
                k += 1
            blocks.append(Block(page, start, fence.group(2), "\n".join(body) + "\n", pending))
            pending = []
        k += 1
    return blocks


def line_pattern(expected):
    parts = [re.escape(part) for part in expected.split("...")]
    return re.compile("^" + ".*".join(parts) + "$")


def check_expected(block, printed):
    """Every expected line appears among the printed ones, in order."""
    actual = [line.rstrip() for line in printed.splitlines()]
    position = 0
    for expected in block.text.splitlines():
        expected = expected.rstrip()
        if not expected or expected == "...":
            continue
        pattern = line_pattern(expected)
        while position < len(actual) and not pattern.match(actual[position]):
            position += 1
        if position == len(actual):
            return f"{block.where()}: the page quotes\n    {expected}\nbut the output was:\n{printed}"
        position += 1
    return None


def prepare(folder, swarmagg, source_dir):
    (folder / "build").mkdir()
    os.symlink(os.path.abspath(swarmagg), folder / "build" / "swarmagg")
    # The Python package is assembled beside the binary (build/python), for the pages' scripts
    # that `import swarmagg` with PYTHONPATH=build/python.
    package = Path(os.path.abspath(swarmagg)).parent / "python"
    if package.is_dir():
        os.symlink(package, folder / "build" / "python")
    for name in LINKED:
        os.symlink(source_dir / name, folder / name)


def run_block(block, folder):
    text = block.text
    for directive in block.directives:
        replace = REPLACE.match(directive)
        if replace:
            if replace.group(1) not in text:
                raise AssertionError(f"{block.where()}: replace: '{replace.group(1)}' is not in the block")
            text = text.replace(replace.group(1), replace.group(2))
    if block.language == "sh":
        if re.search(r"(^|[\s;|&(])python3\b", text):
            raise AssertionError(f"{block.where()}: name the interpreter /usr/bin/python3")
        command = ["bash", "-e", "-o", "pipefail", "-c", text]
    else:
        script = folder / f".block-{block.line}.py"
        script.write_text(text)
        command = ["/usr/bin/python3", str(script)]
    done = subprocess.run(command, cwd=folder, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          text=True, timeout=300)
    if done.returncode != 0:
        raise AssertionError(f"{block.where()}: exit {done.returncode}:\n{text}\n--- output:\n{done.stdout}")
    return done.stdout


def run_page(page, source_dir, swarmagg):
    blocks = read_blocks(page, source_dir / page)
    folder = Path(tempfile.mkdtemp(prefix="swarmagg-docs-"))
    ran = 0
    try:
        prepare(folder, swarmagg, source_dir)
        printed = None
        for block in blocks:
            kinds = [d.split()[0].rstrip(":") for d in block.directives if d.split()]
            if "skip" in kinds:
                continue
            if "file" in kinds:
                target = folder / next(d for d in block.directives if d.startswith("file")).split(None, 1)[1]
                target.parent.mkdir(parents=True, exist_ok=True)
                target.write_text(block.text)
                continue
            if "expect" in kinds:
                if printed is None:
                    raise AssertionError(f"{block.where()}: expect without a run block before it")
                problem = check_expected(block, printed)
                if problem:
                    raise AssertionError(problem)
                continue
            if block.language in ("sh", "python"):
                printed = run_block(block, folder)
                ran += 1
    finally:
        shutil.rmtree(folder, ignore_errors=True)
    return ran


def main():
    swarmagg, source_dir = sys.argv[1], Path(sys.argv[2]).resolve()
    pages = sys.argv[3:] or ["README.md", "docs/worlds.md"] + sorted(
        str(p.relative_to(source_dir)) for p in (source_dir / "docs" / "tutorial").glob("*.md"))
    failures = 0
    for page in pages:
        owner = PAGE_OWNER.search((source_dir / page).read_text())
        if owner:
            print(f"--   {page}: run by {owner.group(1)}")
            continue
        try:
            ran = run_page(page, source_dir, swarmagg)
            print(f"ok   {page}: {ran} blocks ran")
        except (AssertionError, subprocess.TimeoutExpired) as problem:
            print(f"FAIL {page}: {problem}")
            failures += 1
    used = resource.getrusage(resource.RUSAGE_CHILDREN)
    print(f"CPU of the commands: {used.ru_utime + used.ru_stime:.1f} s")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
