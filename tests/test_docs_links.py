"""Links between the project's Markdown pages resolve: every relative link of
README.md, CHANGELOG.md and docs/*.md names a file that exists and, when it
has a #fragment, a heading of that file (GitHub's anchor rules: lower case,
punctuation dropped, spaces to hyphens). The reference pages stay short
enough to read (issue 28: performance and accuracy state what holds now)."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
PAGES = [ROOT / "README.md", ROOT / "CHANGELOG.md", *sorted((ROOT / "docs").glob("*.md"))]
LINK = re.compile(r"(?<!!)\[[^\]]*\]\(([^)\s]+)\)")
FENCE = re.compile(r"^```.*?^```", re.M | re.S)


def anchor(heading: str) -> str:
    text = re.sub(r"[`*]", "", heading.strip().lower())
    text = re.sub(r"[^\w\- ]", "", text)
    return text.replace(" ", "-")


def anchors(page: Path) -> set[str]:
    text = FENCE.sub("", page.read_text(encoding="utf-8"))
    return {anchor(m.group(1)) for m in re.finditer(r"^#{1,6}\s+(.*)$", text, re.M)}


def links(page: Path):
    text = FENCE.sub("", page.read_text(encoding="utf-8"))
    for match in LINK.finditer(text):
        target = match.group(1)
        if re.match(r"[a-z]+:", target):
            continue
        yield target


@pytest.mark.parametrize("page", [p for p in PAGES if p.exists()], ids=lambda p: p.name)
def test_relative_links_resolve(page):
    broken = []
    for target in links(page):
        path, _, fragment = target.partition("#")
        resolved = (page.parent / path).resolve() if path else page
        if not resolved.exists():
            broken.append(target)
        elif fragment and resolved.suffix == ".md" and fragment not in anchors(resolved):
            broken.append(target)
    assert not broken, f"{page.name}: broken links {broken}"


def test_anchor_follows_github_rules():
    assert anchor("Runge–Kutta on stick–slip") == "rungekutta-on-stickslip"
    assert anchor("Measuring on your deck: `asterlite converge`") == (
        "measuring-on-your-deck-asterlite-converge"
    )


@pytest.mark.parametrize("name", ["performance.md", "accuracy.md"])
def test_reference_pages_stay_short(name):
    lines = (ROOT / "docs" / name).read_text(encoding="utf-8").count("\n")
    assert lines < 300, f"docs/{name} has {lines} lines: history belongs in CHANGELOG.md"


def test_changelog_entries_are_dated():
    text = (ROOT / "CHANGELOG.md").read_text(encoding="utf-8")
    dates = re.findall(r"^## (\d{4}-\d{2}-\d{2})$", text, re.M)
    assert dates and dates == sorted(dates, reverse=True)
