"""The building blocks of a report: what ``content`` builds and ``pdf``/``html`` lay out."""
from __future__ import annotations

from dataclasses import dataclass, field, replace
from typing import Callable, ClassVar, Sequence

from PySide6.QtCore import QCoreApplication, QRectF
from PySide6.QtGui import QPainter

Paint = Callable[[QPainter, QRectF, float], None]     # painter, rect (device), device units per mm


@dataclass
class Heading:
    text: str
    level: int = 1


@dataclass
class Paragraph:
    html: str
    keep_with_next: bool = False      # an introduction stays on the page of what it introduces


@dataclass
class KeyValues:
    rows: list[tuple[str, str]]


@dataclass
class Table:
    header: list[str]
    rows: list[list[str]]
    caption: str = ""
    shaded: list[bool] = field(default_factory=list)
    left_columns: int = 1
    plain_header: bool = False        # True: the header is user text (names), never typeset
    key_columns: int = 0              # columns repeated in each block of a split table
                                      # (``column_blocks``); 0: the ``left_columns``


def column_blocks(widths: Sequence[float], lead: int, available: float) -> list[list[int]]:
    """The columns of a table too wide for the page, as blocks that fit: each block the
    ``lead`` (identifying) columns, then an even share of the others in order. Why: a
    table cut at the page's edge loses its last columns (16 crank speeds, issue 32);
    blocks keep every value and say which row each belongs to. A column wider than
    the page on its own still gets a block (nothing is dropped)."""
    lead_w = sum(widths[:lead])
    rest = list(range(lead, len(widths)))
    if lead_w + sum(widths[lead:]) <= available or not rest:
        return [list(range(len(widths)))]
    greedy: list[list[int]] = [[]]
    for c in rest:                             # first as few blocks as fit…
        if greedy[-1] and lead_w + sum(widths[k] for k in greedy[-1]) + widths[c] > available:
            greedy.append([])
        greedy[-1].append(c)
    n, extra = divmod(len(rest), len(greedy))  # …then as many columns in each as can be
    starts = [k * n + min(k, extra) for k in range(len(greedy) + 1)]
    even = [rest[a:b] for a, b in zip(starts, starts[1:])]
    fits = all(lead_w + sum(widths[k] for k in b) <= available for b in even)
    return [list(range(lead)) + b for b in (even if fits else greedy)]


def split_table(table: "Table", blocks: list[list[int]]) -> list["Table"]:
    """``table`` as one table per block of columns (:func:`column_blocks`), the caption
    marked as continued after the first."""
    if len(blocks) == 1:
        return [table]
    more = QCoreApplication.translate("Report", "%1 (continued)")
    return [replace(table, header=[table.header[c] for c in b],
                    rows=[[row[c] for c in b] for row in table.rows],
                    caption=table.caption if k == 0 or not table.caption
                    else more.replace("%1", table.caption))
            for k, b in enumerate(blocks)]


@dataclass
class Figure:
    caption: str
    width_mm: float
    height_mm: float
    paint: Paint
    to_scale: bool = False
    """True: the caption states the drawing's scale, so the figure never shrinks to fit a page."""


def numbered_figures(blocks: list) -> list:
    """``blocks`` with each figure's caption numbered in order, "Figure 3. …" ("图 3  …"):
    a course report cites its figures by number, and a teacher marks a figure without one."""
    label = QCoreApplication.translate("Report", "Figure %1. ")
    out, number = [], 0
    for block in blocks:
        if isinstance(block, Figure):
            number += 1
            block = replace(block, caption=label.replace("%1", str(number)) + block.caption)
        out.append(block)
    return out


@dataclass(frozen=True)
class Cover:
    """What a course design's cover asks for besides the design (user text: printed as
    text, escaped in HTML). Empty fields are printed as blank lines to fill in by hand."""

    student: str = ""
    number: str = ""          # the student's number
    group: str = ""           # the class
    school: str = ""
    supervisor: str = ""

    FIELDS: ClassVar[tuple[str, ...]] = ("student", "number", "group", "school", "supervisor")


@dataclass
class Report:
    title: str
    name: str
    date: str
    language: str
    blocks: list = field(default_factory=list)
    cover: Cover = Cover()


def cover_rows(report: Report) -> list[tuple[str, str]]:
    """The cover block under the title: the design on a row of its own, then two
    label–value cells a row."""
    translate = QCoreApplication.translate
    c = report.cover
    return [(translate("Report", "Design name"), report.name),
            (translate("Report", "Student"), c.student),
            (translate("Report", "Student number"), c.number),
            (translate("Report", "Class"), c.group), (translate("Report", "School"), c.school),
            (translate("Report", "Supervisor"), c.supervisor), (translate("Report", "Date"), report.date)]




def contents(report: Report) -> tuple[str, list[str]]:
    """The contents list's title and its entries, the sections' headings in order: one list
    for the PDF's contents page (with the page each lands on) and the HTML's (with a link
    to each), so that the two cannot list different sections."""
    return (QCoreApplication.translate("Report", "Contents"),
            [block.text for block in report.blocks if isinstance(block, Heading)])
