#!/usr/bin/env python3
"""Checks the relative links of Markdown files: every linked file exists inside the repository,
and every #anchor is an <a id="..."> or a heading of the linked file (GitHub's heading anchors).
Links to web addresses are not checked (nothing is fetched), nor links inside code.

Without files, it also checks the sections that every tracked text file names by quoting them,
as code and study comments do (docs/results.md "A memory"; also with a comma, or wrapped over
comment lines): the quoted words must stand in that Markdown file.

Usage: check_links.py ROOT [FILE.md ...]
  Without files, every *.md file git tracks under ROOT. Prints one line per broken link or
  quoted section (file:line: target: why) and a summary; exits 1 if one is broken, 2 on bad
  input."""
import functools
import pathlib
import re
import subprocess
import sys

# The "](target)" of [text](target) and ![alt](target), with an optional "title": the text may
# have begun on an earlier line.
LINK = re.compile(r"\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)")
EXPLICIT_ANCHOR = re.compile(r"<a\s+(?:id|name)=\"([^\"]+)\"")
HEADING = re.compile(r"^(#{1,6})\s+(.*?)\s*#*\s*$")
FENCE = re.compile(r"^\s*(```|~~~)")
CODE_SPAN = re.compile(r"`[^`]*`")
WEB_ADDRESS = re.compile(r"^[a-z][a-z0-9+.-]*:", re.IGNORECASE)  # https:, mailto:, ...
# A section named by quoting it: `docs/results.md "A memory"` or `docs/results.md, "A memory"`
# (`README "Studies"` for README.md), the words perhaps wrapped over comment lines (`# ` or `// `
# before each).
COMMENT_BREAK = r"\n[ \t]*(?:#+|//+)"
QUOTED_SECTION = re.compile(r"\b(README|[\w./-]+\.md),?(?:[ \t]|" + COMMENT_BREAK + r"|\n)+"
                            r"\(?\"([A-Z](?:[^\"\n]|" + COMMENT_BREAK + r")*)\"")


def github_anchor(heading):
    """GitHub's anchor of a heading: markup and punctuation dropped, lower case, spaces -> '-'."""
    text = re.sub(r"<[^>]+>", "", heading)
    text = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", text)
    text = re.sub(r"[^\w\- ]", "", text.strip().lower())
    return text.replace(" ", "-")


def prose_lines(path):
    """(line number, text) of the lines outside fenced code blocks."""
    inside_fence = False
    for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), start=1):
        if FENCE.match(line):
            inside_fence = not inside_fence
        elif not inside_fence:
            yield number, line


@functools.lru_cache(maxsize=None)
def anchors_of(path):
    """The anchors of a Markdown file; a repeated heading's later anchors end in -1, -2, ..."""
    anchors, repeats = set(), {}
    for _, line in prose_lines(path):
        anchors.update(EXPLICIT_ANCHOR.findall(line))
        heading = HEADING.match(line)
        if heading:
            anchor = github_anchor(heading.group(2))
            count = repeats.get(anchor, 0)
            repeats[anchor] = count + 1
            anchors.add(anchor if count == 0 else f"{anchor}-{count}")
    return frozenset(anchors)


def broken_links(path, root):
    """(line number, target, why) of each broken link of `path`."""
    for number, line in prose_lines(path):
        for target in LINK.findall(CODE_SPAN.sub("", line)):
            if WEB_ADDRESS.match(target):
                continue
            file_part, _, anchor = target.partition("#")
            linked = (path.parent / file_part).resolve() if file_part else path
            if not linked.is_relative_to(root):
                yield number, target, "outside the repository"
            elif not linked.exists():
                yield number, target, "no such file"
            elif anchor and linked.suffix == ".md" and anchor not in anchors_of(linked):
                yield number, target, "no such anchor"


def folded(text):
    return " ".join(text.split())


@functools.lru_cache(maxsize=None)
def folded_text_of(markdown):
    return folded(markdown.read_text(encoding="utf-8"))


def broken_quoted_sections(path, root):
    """(line number, reference, why) of each quoted section of `path` its Markdown file lacks."""
    try:
        text = path.read_text(encoding="utf-8")
    except (UnicodeDecodeError, IsADirectoryError):
        return
    for match in QUOTED_SECTION.finditer(text):
        markdown = root / ("README.md" if match.group(1) == "README" else match.group(1))
        if not markdown.is_file():
            continue  # a path relative to somewhere else, or no file: not a section reference
        words = folded(re.sub(COMMENT_BREAK, " ", match.group(2)))
        if words not in folded_text_of(markdown):
            line = text.count("\n", 0, match.start()) + 1
            yield line, f'{match.group(1)} "{words}"', "no such text"


def tracked_files(root, pattern):
    listed = subprocess.run(["git", "-C", str(root), "ls-files", pattern], capture_output=True,
                            text=True)
    if listed.returncode != 0:
        print(f"check_links.py: {root}: not a git checkout (name the Markdown files instead)",
              file=sys.stderr)
        sys.exit(2)
    return [root / name for name in listed.stdout.split()]


def markdown_files(root, names):
    if names:
        return [pathlib.Path(name).resolve() for name in names]
    return tracked_files(root, "*.md")


def main(argv):
    if len(argv) < 2:
        print("usage: check_links.py ROOT [FILE.md ...]", file=sys.stderr)
        return 2
    root = pathlib.Path(argv[1]).resolve()
    if not root.is_dir():
        print(f"check_links.py: {argv[1]}: no such folder", file=sys.stderr)
        return 2
    files = markdown_files(root, argv[2:])
    for path in files:
        if not path.is_file():
            print(f"check_links.py: {path}: no such file", file=sys.stderr)
            return 2
    broken = 0
    for path in files:
        for number, target, why in broken_links(path, root):
            shown = path.relative_to(root) if path.is_relative_to(root) else path
            print(f"{shown}:{number}: {target}: {why}")
            broken += 1
    summary = f"check_links: {len(files)} files, {broken} broken links"
    if not argv[2:]:
        sources, broken_sections = tracked_files(root, "*"), 0
        for path in sources:
            for number, reference, why in broken_quoted_sections(path, root):
                print(f"{path.relative_to(root)}:{number}: {reference}: {why}")
                broken_sections += 1
        summary += f"; {len(sources)} files, {broken_sections} broken quoted sections"
        broken += broken_sections
    print(summary)
    return 1 if broken else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
