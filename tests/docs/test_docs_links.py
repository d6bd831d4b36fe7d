"""Every relative link of README.md and docs/*.md leads somewhere: to a file that exists
and, where it names an anchor, to a heading of that file (GitHub's anchor rule), so moving
a section from one page to another cannot leave a dead link behind."""
import re
from pathlib import Path

import pytest
from locations import ROOT

ROOT = ROOT
PAGES = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]
LINK = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)\)")


def prose(text: str) -> list[str]:
    """The lines outside fenced code blocks, with inline code removed."""
    lines, fenced = [], False
    for line in text.splitlines():
        if line.lstrip().startswith("```"):
            fenced = not fenced
            continue
        if not fenced:
            lines.append(re.sub(r"`[^`]*`", "", line))
    return lines


def slug(heading: str) -> str:
    """GitHub's anchor of a heading: link text kept, lowercase, punctuation removed, spaces to '-'."""
    text = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", heading.strip())
    text = re.sub(r"[^\w\- ]", "", text.lower())
    return text.replace(" ", "-")


def anchors(path: Path) -> set[str]:
    """Every heading's anchor in ``path``; a repeated heading gets -1, -2 … as on GitHub."""
    seen: dict[str, int] = {}
    found = set()
    fenced = False
    for line in path.read_text(encoding="utf-8").splitlines():
        if line.lstrip().startswith("```"):
            fenced = not fenced
            continue
        match = None if fenced else re.match(r"#{1,6}\s+(.*?)\s*#*\s*$", line)
        if match:
            base = slug(match.group(1))
            count = seen.get(base, 0)
            seen[base] = count + 1
            found.add(base if count == 0 else f"{base}-{count}")
    return found


def broken_links(page: Path) -> list[str]:
    """The relative links of ``page`` that lead to no file or to no heading."""
    broken = []
    for line in prose(page.read_text(encoding="utf-8")):
        for target in LINK.findall(line):
            if re.match(r"[a-z][a-z0-9+.-]*:", target):      # http:, https:, mailto:
                continue
            file_part, _, anchor = target.partition("#")
            path = (page.parent / file_part).resolve() if file_part else page
            if not path.exists():
                broken.append(f"{target}: no such file")
            elif anchor and (path.suffix != ".md" or anchor not in anchors(path)):
                broken.append(f"{target}: no such heading in {path.name}")
    return broken


def test_slug_follows_githubs_rule():
    assert slug("Schema, versions and reliability") == "schema-versions-and-reliability"
    assert slug("The `shaper` command") == "the-shaper-command"
    assert slug("Forces and flywheel") == "forces-and-flywheel"
    assert slug("library compare") == "library-compare"


def test_a_dead_link_is_found(tmp_path):
    (tmp_path / "docs").mkdir()
    (tmp_path / "docs" / "a.md").write_text("# A page\n\n## Exact extrema\n", encoding="utf-8")
    page = tmp_path / "README.md"
    page.write_text("[ok](docs/a.md#exact-extrema) [file](docs/b.md) [heading](docs/a.md#validation)\n"
                    "[here](#nowhere) ![picture](docs/shot.png)\n```\n[code](not/checked.md)\n```\n",
                    encoding="utf-8")
    assert broken_links(page) == ["docs/b.md: no such file", "docs/a.md#validation: no such heading in a.md",
                                  "#nowhere: no such heading in README.md", "docs/shot.png: no such file"]


def test_the_pages_have_links():
    assert sum(len(LINK.findall("\n".join(prose(p.read_text(encoding="utf-8"))))) for p in PAGES) > 20


@pytest.mark.parametrize("page", PAGES, ids=[p.name for p in PAGES])
def test_every_relative_link_resolves(page):
    assert broken_links(page) == []
