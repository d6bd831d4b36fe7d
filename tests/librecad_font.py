"""A stand-in for LibreCAD's wqy-unicode.lff, for the tests that print a DXF with LibreCAD.

LibreCAD's own builds for Windows and macOS ship wqy-unicode.lff (Fedora and openSUSE make
it with LibreCAD's ``ttf2lff`` from WenQuanYi Micro Hei); Debian's librecad-data 2.2.0 does
not. The tests make one the way ttf2lff does, each glyph's outline as polylines in a LibreCAD
font (LFF: ``[4e00] 一`` and one ``x,y;x,y;…`` line per contour, capitals 9 units high), from
Noto Sans CJK SC and for the characters a test prints only, and put it where LibreCAD 2.2
looks for a user's fonts: ``$HOME/.librecad/fonts``.
"""
from __future__ import annotations

import os
import string
from pathlib import Path

import numpy as np

NOTO_CJK = "/usr/share/fonts/opentype/noto/NotoSansCJK-Regular.ttc"
SC = 2                   # the face of Noto Sans CJK SC in the collection
FONT_NAME = "wqy-unicode"


def _contours(recording, steps: int = 6) -> list[list[tuple[float, float]]]:
    """The closed contours of a glyph (fontTools' RecordingPen value), curves as ``steps``
    chords each."""
    contours, current, start = [], [], (0.0, 0.0)
    t = np.linspace(0.0, 1.0, steps + 1)[1:, None]
    for op, args in recording:
        if op == "moveTo":
            current, start = [args[0]], args[0]
        elif op == "lineTo":
            current.append(args[0])
        elif op == "qCurveTo":          # off-curve points with implied on-curve midpoints
            prev, ctrl = current[-1], args[:-1]
            for i, c in enumerate(ctrl):
                end = args[-1] if i == len(ctrl) - 1 else tuple((np.add(c, ctrl[i + 1]) / 2).tolist())
                p = np.asarray((prev, c, end), float)
                current += list(map(tuple, (1 - t) ** 2 * p[0] + 2 * (1 - t) * t * p[1] + t ** 2 * p[2]))
                prev = end
        elif op == "curveTo":
            p = np.asarray((current[-1], *args), float)
            current += list(map(tuple, (1 - t) ** 3 * p[0] + 3 * (1 - t) ** 2 * t * p[1]
                                + 3 * (1 - t) * t ** 2 * p[2] + t ** 3 * p[3]))
        elif op in ("closePath", "endPath") and current:
            contours.append(current + [start])
            current = []
    return contours


def install_font(home: Path, characters: str) -> Path:
    """Write the stand-in wqy-unicode.lff with ``characters`` (and ASCII) under ``home``'s
    LibreCAD font folder; its path."""
    from fontTools.pens.recordingPen import RecordingPen
    from fontTools.ttLib import TTCollection
    font = TTCollection(NOTO_CJK).fonts[SC]
    cmap, glyphs = font.getBestCmap(), font.getGlyphSet()
    scale = 9.0 / font["OS/2"].sCapHeight
    lines = ["# Format:            LibreCAD Font 1", f"# Name:              {FONT_NAME} (test)",
             "# Encoding:          UTF-8", "# LetterSpacing:     1", "# WordSpacing:       6.75",
             "# LineSpacingFactor: 1", ""]
    for ch in sorted(set(characters) | set(string.printable.strip())):
        if ord(ch) not in cmap:
            continue
        pen = RecordingPen()
        glyphs[cmap[ord(ch)]].draw(pen)
        lines.append(f"[{ord(ch):04x}] {ch}")
        lines += [";".join(f"{x * scale:.2f},{y * scale:.2f}" for x, y in c) for c in _contours(pen.value)]
        lines.append("")
    folder = home / ".librecad" / "fonts"
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / f"{FONT_NAME}.lff"
    path.write_text("\n".join(lines), encoding="utf-8")
    return path


def have_noto_cjk() -> bool:
    return os.path.exists(NOTO_CJK)
