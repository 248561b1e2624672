#!/usr/bin/python3
"""Every relative link and image in the repository's Markdown pages (README.md, CHANGELOG.md,
docs/, ...) resolves: the file (or folder) exists in the repository and, for `page.md#anchor`,
the page has that heading. Also refuses links that leave the repository.

Usage: check_links.py SOURCE_DIR
"""
import re
import sys
from pathlib import Path

LINK = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)")
FENCE = re.compile(r"^\s*```")


def outside_fences(text):
    kept, inside = [], False
    for line in text.splitlines():
        if FENCE.match(line):
            inside = not inside
        elif not inside:
            kept.append(line)
    return kept


def prose(text):
    """The page without code blocks and inline code, where links are not links."""
    return "\n".join(re.sub(r"`[^`]*`", "", line) for line in outside_fences(text))


def anchors(page):
    """GitHub's heading anchors of a Markdown page."""
    found = set()
    for line in outside_fences(page.read_text()):
        heading = re.match(r"^#{1,6}\s+(.*?)\s*#*\s*$", line)
        if heading:
            slug = re.sub(r"[^\w\- ]", "", heading.group(1).lower()).replace(" ", "-")
            found.add(slug)
    return found


def main():
    root = Path(sys.argv[1]).resolve()
    pages = [root / "README.md", root / "CHANGELOG.md"]
    for page in sorted(root.rglob("*.md")):
        top = page.relative_to(root).parts[0]
        # Build folders and the outputs of runs are not the repository's pages.
        if page in pages or top in {".git", "runs", "renders", "reproduce"} or top.startswith("build"):
            continue
        pages.append(page)
    problems, checked = [], 0
    for page in pages:
        if not page.exists():
            problems.append(f"{page.relative_to(root)}: missing")
            continue
        for target in LINK.findall(prose(page.read_text())):
            if re.match(r"^[a-z]+:", target) or target.startswith("//"):
                continue  # http(s), mailto: not checked offline
            checked += 1
            path, _, anchor = target.partition("#")
            resolved = (page.parent / path).resolve() if path else page
            where = f"{page.relative_to(root)}: ({target})"
            if root not in resolved.parents and resolved != root:
                problems.append(f"{where} leaves the repository")
            elif not resolved.exists():
                problems.append(f"{where} does not exist")
            elif anchor and resolved.suffix == ".md" and anchor not in anchors(resolved):
                problems.append(f"{where}: no heading with anchor #{anchor}")
    for problem in problems:
        print(problem)
    print(f"{checked} relative links checked in {len(pages)} pages, {len(problems)} broken")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
