"""scripts/check_links.py: the project's Markdown files link only to files and anchors that exist,
and its comments quote only sections that exist; on files made here, each kind of broken link or
quoted section is found and each kind of good one passes."""

import subprocess
import sys

from conftest import SOURCE_DIR

SCRIPT = SOURCE_DIR / "scripts" / "check_links.py"


def run(*args):
    return subprocess.run([sys.executable, str(SCRIPT), *map(str, args)], capture_output=True,
                          text=True)


def test_the_projects_markdown_files_have_no_broken_link():
    result = run(SOURCE_DIR)
    assert result.returncode == 0, result.stdout + result.stderr
    assert "README.md" in subprocess.run(["git", "-C", str(SOURCE_DIR), "ls-files", "*.md"],
                                         capture_output=True, text=True, check=True).stdout


def write_docs(tmp_path):
    (tmp_path / "docs").mkdir()
    (tmp_path / "docs" / "figure.png").write_bytes(b"")
    (tmp_path / "docs" / "results.md").write_text(
        "# Results: the best recipe (5 seeds)\n"
        "<a id=\"result-memory\"></a>**A memory.**\n"
        "## Notes\n## Notes\n"
        "Back to [the top](../README.md#the-two-commands).\n")
    (tmp_path / "README.md").write_text(
        "# Title\n## The two commands\n"
        "Good: [a](docs/results.md#results-the-best-recipe-5-seeds), [b](docs/results.md"
        "#result-memory), [c](docs/results.md#notes-1), ![d](docs/figure.png), [e](#title),\n"
        "[f](https://example.org/nowhere), `[g](docs/in_code.md)`.\n"
        "```\n[h](docs/in_a_fence.md)\n```\n"
        "Broken: [i](docs/missing.md), [j](docs/results.md#nope), [k](#notes-2),\n"
        "[l](../outside.md), [m](docs/results.md#notes-2), [a wrapped\n"
        "link](#nowhere).\n")
    return tmp_path


def test_every_kind_of_broken_link_is_found_and_good_links_pass(tmp_path):
    root = write_docs(tmp_path)
    (tmp_path.parent / "outside.md").write_text("# Outside\n")
    result = run(root, root / "README.md", root / "docs" / "results.md")
    assert result.returncode == 1
    assert result.stdout.splitlines() == [
        "README.md:8: docs/missing.md: no such file",
        "README.md:8: docs/results.md#nope: no such anchor",
        "README.md:8: #notes-2: no such anchor",
        "README.md:9: ../outside.md: outside the repository",
        "README.md:9: docs/results.md#notes-2: no such anchor",
        "README.md:10: #nowhere: no such anchor",
        "check_links: 2 files, 6 broken links",
    ]


def test_bad_input_is_one_line_and_status_2(tmp_path):
    result = run(tmp_path / "no_folder")
    assert result.returncode == 2
    assert result.stderr.strip() == f"check_links.py: {tmp_path / 'no_folder'}: no such folder"
    result = run(tmp_path, tmp_path / "absent.md")
    assert result.returncode == 2
    assert "absent.md: no such file" in result.stderr


def test_quoted_sections_of_tracked_files_are_checked_across_comment_lines(tmp_path):
    (tmp_path / "docs").mkdir()
    (tmp_path / "eval").mkdir()
    (tmp_path / "README.md").write_text("# Title\n## Studies on a cluster\n")
    (tmp_path / "docs" / "findings.md").write_text("**A memory: hardly a time-out.**\n")
    (tmp_path / "eval" / "policy.h").write_text(
        "// See docs/findings.md \"A memory: hardly\n"
        "// a time-out\" and README \"Studies on a cluster\".\n"
        "// Broken: (docs/findings.md, \"A memory that forgets\").\n")
    (tmp_path / "study.yaml").write_text("# docs/findings.md \"Nothing\n# here\"\nkey: 1\n")
    (tmp_path / "data.bin").write_bytes(bytes([0xff, 0xfe, 0x00]))
    subprocess.run(["git", "init", "-q", str(tmp_path)], check=True)
    subprocess.run(["git", "-C", str(tmp_path), "add", "."], check=True)
    result = run(tmp_path)
    assert result.returncode == 1
    assert result.stdout.splitlines() == [
        'eval/policy.h:3: docs/findings.md "A memory that forgets": no such text',
        'study.yaml:1: docs/findings.md "Nothing here": no such text',
        "check_links: 2 files, 0 broken links; 5 files, 2 broken quoted sections",
    ]
