"""The building blocks of a report: what ``content`` builds and ``pdf``/``html`` lay out."""
from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Callable, ClassVar

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


@dataclass
class Figure:
    caption: str
    width_mm: float
    height_mm: float
    paint: Paint


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
    return [(translate("Report", "Design"), report.name),
            (translate("Report", "Student"), c.student),
            (translate("Report", "Student number"), c.number),
            (translate("Report", "Class"), c.group), (translate("Report", "School"), c.school),
            (translate("Report", "Supervisor"), c.supervisor), (translate("Report", "Date"), report.date)]


# The formulas' notation in the (translated) source text, typeset by ``typeset``:
# a^k_A3A2 → a with k above and A3A2 below, v_A3 → v with A3 below, O4/L1/ω3 → O, L, ω with
# the digit below, (1/2π) → a slanted fraction.
_NOTATION = re.compile(r"(?<![A-Za-z0-9])(?P<base>[A-Za-zΔ]{1,2})\^(?P<sup>[a-z])_(?P<sub>[A-Za-z0-9]+)"
                       r"|(?<![A-Za-z0-9])(?P<base2>[A-Za-zΔ]{1,2})_(?P<sub2>[A-Za-z0-9]+)"
                       r"|(?<![A-Za-z_])(?P<name>[OLωα])(?P<digit>\d)"
                       r"|\((?P<num>\d)/(?P<den>\d?π)\)")


def typeset(text: str) -> str:
    """Rich text of a formula paragraph: sub- and superscripts and fractions in HTML
    (QTextDocument prints them in the PDF), from the plain notation of the source."""
    def one(m: re.Match) -> str:
        if m["base"]:
            return f"{m['base']}<sup>{m['sup']}</sup><sub>{m['sub']}</sub>"
        if m["base2"]:
            return f"{m['base2']}<sub>{m['sub2']}</sub>"
        if m["name"]:
            return f"{m['name']}<sub>{m['digit']}</sub>"
        return f"(<sup>{m['num']}</sup>⁄<sub>{m['den']}</sub>)"
    return _NOTATION.sub(one, text)
