"""A PDF page exactly the paper's size, not rounded to whole points.

QPageSize keeps a size in whole points, so QPdfWriter's A3 came out 1191 × 842 pt
(420.16 × 297.04 mm) and A4 595 × 842 pt (209.90 × 297.04 mm). :func:`exact_page`
rewrites the boxes of the finished PDF; the sheets and the report share it.
"""
from __future__ import annotations

import re

_BOXES = re.compile(rb"/(MediaBox|TrimBox) (\[0 0 ([\d.]+) ([\d.]+)\])")


def exact_page(pdf: bytes, width_mm: float, height_mm: float) -> bytes:
    """``pdf`` (from QPdfWriter, every page one size) with each MediaBox and TrimBox the paper's exact
    size. Why: QPageSize keeps a size in whole points, so A3 came out 1191 × 842 pt
    (420.16 × 297.04 mm). Qt draws from the top edge down (its y flip is the rounded
    height), so the exact box keeps that top and starts the bottom the difference higher.
    Each box is rewritten in place at its old length (padded with spaces, which PDF allows),
    so the file's byte offsets stay valid; a box that would not fit is left as it was."""
    w_pt, h_pt = width_mm * 72.0 / 25.4, height_mm * 72.0 / 25.4

    def exact(match: re.Match) -> bytes:
        old, top = match.group(2), float(match.group(4))
        new = f"[0 {top - h_pt:.4f} {w_pt:.4f} {top:g}".encode("ascii")
        if len(new) + 1 > len(old):
            return match.group(0)
        return b"/" + match.group(1) + b" " + new + b" " * (len(old) - len(new) - 1) + b"]"
    return _BOXES.sub(exact, pdf)
