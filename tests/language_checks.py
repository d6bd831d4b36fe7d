"""Checks that Chinese output is Chinese: no untranslated English word, no radical or
control character where a printed ideograph belongs (issue 32, items 4 and 5).

``english_words`` finds the words a Chinese reader would see as English: runs of Latin
letters with a lower-case tail ("allowed", "Design", "is"), and all-capital runs of three
or more letters ("NOTE"), except the few in ``ALLOWED`` (units, symbols, file types) and
the ones a test adds (a file name, a user's title). Symbols such as K, H, L1, O4, vB3,
aB3B2, J_F or ψmax are not words: a capital with digits, a letter pair whose second is a
capital, or a lower-case tail the allow-list names (max).
"""
from __future__ import annotations

import re
import shutil
import subprocess
import unicodedata

# Units, symbols and file types a Chinese text writes in Latin letters; kept short on purpose.
ALLOWED = frozenset({
    "mm", "kg", "min", "max", "rad", "kW",          # units: mm, kg·m², r/min, rad/s², kW
    "PDF", "SVG", "DXF", "CSV", "PNG", "JSON", "HTML",
    "GB", "UTF",                                   # GB/T 4457.4, UTF-8 (names of standards)
    "dx", "dy",                                    # an offset's components (dx, dy)
})
# Symbols with an index, as a text layer reads them back: the index, typeset lower, runs
# into its letter (M_m → "Mm", ΔW_max → "Wmax", J_e → "Je", a^k → "ak").
NOTATION = frozenset({"Mm", "Wmax", "Je", "Pm", "Tm", "vslide", "ak",
                      "pb", "xmin", "db", "da", "df", "sa",       # the gear pair's (issue 35):
                      "ra", "rb", "rf", "ha", "zmin", "inv"})     # r_a, h*_a, z_min, inv α
_WORD = re.compile(r"(?<![A-Za-z])(?:[A-Za-z][a-z]+|[A-Z]{3,})(?![A-Za-z])")
_CONTROL_OK = "\n\r\t\f"


def english_words(text: str, allowed: frozenset[str] | set[str] = frozenset()) -> list[str]:
    """The English words in ``text``, in order, without ``ALLOWED``, ``NOTATION`` and ``allowed``."""
    keep = ALLOWED | NOTATION | set(allowed)
    return [w for w in _WORD.findall(text) if w not in keep]


def words_of(*texts: str) -> set[str]:
    """Every Latin word of ``texts`` (file names, a user's title): allowed where they are shown."""
    return {w for t in texts for w in _WORD.findall(t)}


def radicals(text: str) -> list[str]:
    """Kangxi and supplementary radicals and CJK strokes (U+2E80–2FDF, U+31C0–31EF): what a
    text layer holds where the font shares the ideograph's glyph and the writer took the
    lowest code point."""
    return [c for c in text if 0x2E80 <= ord(c) <= 0x2FDF or 0x31C0 <= ord(c) <= 0x31EF]


def control_characters(text: str) -> list[str]:
    """Control characters other than line and page breaks: glyphs without a code point."""
    return [c for c in text if unicodedata.category(c) == "Cc" and c not in _CONTROL_OK]


def han(text: str) -> list[str]:
    """The CJK unified ideographs of ``text``, in order."""
    return [c for c in text if 0x4E00 <= ord(c) <= 0x9FFF or 0x3400 <= ord(c) <= 0x4DBF]


def pdf_text(path) -> str:
    """The PDF's text layer as pdftotext reads it, not normalized (the test checks it raw)."""
    return subprocess.run(["pdftotext", str(path), "-"], capture_output=True, text=True,
                          check=True).stdout


def pdf_words(path) -> list[str]:
    """The PDF's pages and words with their boxes (pt) as ``pdftotext -bbox`` reads them, in
    order, without the document's dates: two files of one content give the same list."""
    boxes = subprocess.run(["pdftotext", "-bbox", str(path), "-"], capture_output=True, text=True,
                           check=True).stdout
    return re.findall(r"<page [^>]*>|<word [^>]*>[^<]*</word>", boxes)


def has_pdftotext() -> bool:
    return shutil.which("pdftotext") is not None


def assert_chinese_text(text: str, allowed: set[str] | frozenset[str] = frozenset(), what: str = "") -> None:
    """``text`` is real Chinese text: no radical, no control character, no English word."""
    assert radicals(text) == [], (what, "radicals", "".join(sorted(set(radicals(text)))))
    assert control_characters(text) == [], (what, "control characters", control_characters(text)[:10])
    assert english_words(text, allowed) == [], (what, "English", english_words(text, allowed))


def check_file_menu_entry(window, qtbot, action, english: str) -> None:
    """``action`` stands in the window's File menu and reads ``english`` in English and
    Chinese (some ideograph) after a switch to Chinese."""
    assert action in window.menu_file.actions()
    window.set_language("en")
    assert action.text() == english
    window.set_language("zh_CN")
    qtbot.waitUntil(lambda: action.text() != english, timeout=10_000)
    assert han(action.text())
