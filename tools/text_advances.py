"""Measure the sheets' fonts and write ``core/drawing/advances.py``: ``python tools/text_advances.py``.

Why: a sheet lays out every text by :func:`core.drawing.sheet.text_width`, and each
renderer squeezes a text its font draws wider than that (``sheet_paint._drawn_width``,
``outline_text.squeeze``). One advance for every Latin letter left "mm" and "Module m"
condensed beside "0.25" (DejaVu Sans' m is 1.33 cap heights, its i 0.38). This measures
each character's advance, in cap heights as the sheets size a text, in every font that
draws the sheets' texts: the PDF's and SVG's (``fonts.report_font``, English and Chinese,
through Qt's QFontMetricsF at the painter's 100 px) and the DXF's outlines
(``outline_text.outline_font`` at the GB style's width factor; see :func:`outline_advances`
for the few it leaves out), and keeps the largest, so no renderer squeezes. (The DXF's GB
TEXT entities are drawn in the CAD program's own font, which this cannot measure.) The pairs
the font kerns wider ("O-") are stored beside them. Run it again when a font changes;
``tests/test_shaperapp/drawing/test_text_advances.py`` compares the stored table with this
machine's fonts.
CJK characters are not in the table: they are set square (``sheet.WIDE_ADVANCE``).
"""
from __future__ import annotations

import math
import os
import sys
from pathlib import Path

os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

# The characters the sheets write (their captions, tables, numbers and the class sheets), and
# what a user's name in Latin script may hold: ASCII, Latin-1, Greek, and the symbols below.
SYMBOLS = "°′″‴≥≤·×≈…−–—±⌀√→←↑↓∞²³‰≠∠∑∆Ω‘’“”•µ"
CHARACTERS = "".join(sorted(set(
    [chr(c) for c in range(0x20, 0x7F)] + [chr(c) for c in range(0xA0, 0x180)]
    + [chr(c) for c in range(0x391, 0x3AA) if c != 0x3A2] + [chr(c) for c in range(0x3B1, 0x3CA)]
    + list(SYMBOLS))))
TABLE = ROOT / "core" / "drawing" / "advances.py"


def qt_advances(language: str) -> dict[str, float]:
    """Each character's advance in ``report_font(language)`` over its cap height, as
    ``sheet_paint`` sizes and measures a text."""
    from PySide6.QtGui import QFontMetricsF
    from shaperapp.widgets.fonts import report_font
    font = report_font(language)
    font.setPixelSize(100)
    metrics = QFontMetricsF(font)
    cap = metrics.capHeight() or 70.0
    return {ch: metrics.horizontalAdvance(ch) / cap for ch in CHARACTERS}


def qt_kerns(language: str, advances: dict[str, float]) -> dict[str, float]:
    """The pairs of characters ``report_font(language)`` sets further apart than their two
    advances (its kerning tables widen a few: "-J", "O-", "AA"), by how much, in cap heights."""
    from PySide6.QtGui import QFontMetricsF
    from shaperapp.widgets.fonts import report_font
    font = report_font(language)
    font.setPixelSize(100)
    metrics = QFontMetricsF(font)
    cap = metrics.capHeight() or 70.0
    pairs = {a + b: metrics.horizontalAdvance(a + b) / cap - advances[a] - advances[b]
             for a in CHARACTERS for b in CHARACTERS}
    return {pair: kern for pair, kern in pairs.items() if kern > 0.0005}


def outline_advances() -> dict[str, float]:
    """Each character's advance in the DXF's outline font at the GB style's width factor,
    per unit of text height (ezdxf's cap height), but for those it draws as wide as a
    Chinese character: its full-width forms of · ‘ ’ “ ” • and the Latin letters it lacks.
    Those would widen every PDF text with "0.25·m" by half a height; in the outline a run
    of them is squeezed instead, and a run with letters or digits not at all (its Latin at
    0.7 is some 40 % narrower than the PDF's)."""
    from core.drawing.dxf import TEXT_WIDTH
    from core.drawing.outline_text import outline_font
    font = outline_font()
    square = 0.95 * font.get_text_length("曲", 1.0, TEXT_WIDTH)
    return {ch: advance for ch in CHARACTERS
            if (advance := font.get_text_length(ch, 1.0, TEXT_WIDTH)) < square}


def up(value: float) -> float:
    """``value`` rounded up to 0.001: the table never below what it measured."""
    return math.ceil(value * 1000.0 - 1e-6) / 1000.0


def measured() -> tuple[dict[str, float], dict[str, float]]:
    """The largest advance of each character over the renderers and the pairs kerned
    wider, rounded up to 0.001."""
    from PySide6.QtWidgets import QApplication
    from shaperapp.widgets.fonts import prefer_simplified_chinese
    app = QApplication.instance() or QApplication([])
    prefer_simplified_chinese()
    tables = [qt_advances("en"), qt_advances("zh_CN"), outline_advances()]
    kerns = [qt_kerns(language, table) for language, table in zip(("en", "zh_CN"), tables)]
    del app
    advances = {ch: up(max(t.get(ch, 0.0) for t in tables)) for ch in CHARACTERS}
    pairs = sorted(set(kerns[0]) | set(kerns[1]))
    return advances, {pair: up(max(k.get(pair, 0.0) for k in kerns)) for pair in pairs}


def module_text(advances: dict[str, float], kerns: dict[str, float]) -> str:
    from PySide6.QtGui import QFontInfo
    from shaperapp.widgets.fonts import report_font
    family = QFontInfo(report_font("en")).family()
    lines = ['"""Each character\'s advance in text heights (cap heights), the largest of the sheets\'',
             f"renderers' fonts ({family}, the DXF's outline font at width factor 0.7): generated",
             'by ``tools/text_advances.py``, do not edit. ``sheet.text_width`` reads it."""',
             ""]
    for name, table, doc in (("ADVANCES", advances, None),
                             ("KERNS", kerns, "# pairs set wider than their two advances, by how much")):
        items = [f"{key!r}: {value!r}," for key, value in table.items()]
        lines += ([doc] if doc else []) + [f"{name}: dict[str, float] = {{"]
        lines += ["    " + " ".join(items[i:i + 8]) for i in range(0, len(items), 8)] + ["}", ""]
    return "\n".join(lines)


if __name__ == "__main__":
    TABLE.write_text(module_text(*measured()), encoding="utf-8")
    print(f"wrote {TABLE.relative_to(ROOT)} ({len(CHARACTERS)} characters)")
