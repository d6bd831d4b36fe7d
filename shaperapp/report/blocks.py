"""The building blocks of a report: what ``content`` builds and ``pdf``/``html`` lay out."""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable

from PySide6.QtCore import QRectF
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


@dataclass
class Figure:
    caption: str
    width_mm: float
    height_mm: float
    paint: Paint


@dataclass
class Report:
    title: str
    name: str
    date: str
    language: str
    blocks: list = field(default_factory=list)
