"""Checks every drawing sheet must pass: each drawing keeps to its own area, the areas do
not overlap, nothing lies outside the border, no two texts overlap, and no text holds a
Unicode subscript digit, which the CAD fonts of a DXF lack (indices are subscript runs)."""
import re

from core.drawing.sheet import Text, item_box, outside_border, overlapping_texts

UNICODE_SUBSCRIPTS = re.compile("[\u2080-\u209c]")


def inside(box, area, tol=1e-6) -> bool:
    return (box[0] >= area[0] - tol and box[1] >= area[1] - tol
            and box[2] <= area[2] + tol and box[3] <= area[3] + tol)


def assert_laid_out(sheet, areas) -> None:
    """``areas``: name → (area box, its items) of a sheet built by core.drawing."""
    assert outside_border(sheet) == [] and overlapping_texts(sheet) == []
    assert [t.text for t in sheet.items if isinstance(t, Text) and UNICODE_SUBSCRIPTS.search(t.text)] == []
    named = list(areas.items())
    for name, (area, items) in named:
        strays = [it for it in items if not inside(item_box(it), area)]
        assert strays == [], (name, strays[:3])
    for i, (a_name, (a, _)) in enumerate(named):
        for b_name, (b, _) in named[i + 1:]:
            assert not (a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]), (a_name, b_name)


def assert_pdf_sheet(path, size_mm) -> str:
    """A written sheet's PDF: its page is the paper (within 0.5 mm), a Chinese one embeds a
    CJK font (when pdffonts is installed); returns its text, NFKC-normalized (the CJK font
    maps some characters to radicals), or '' without pdftotext."""
    import re
    import shutil
    import subprocess
    import unicodedata
    info = subprocess.run(["pdfinfo", str(path)], capture_output=True, text=True).stdout
    w, h = (float(v) * 25.4 / 72 for v in re.search(r"([\d.]+) x ([\d.]+) pts", info).groups())
    assert abs(w - size_mm[0]) < 0.5 and abs(h - size_mm[1]) < 0.5
    if shutil.which("pdffonts"):
        fonts = subprocess.run(["pdffonts", str(path)], capture_output=True, text=True).stdout
        rows = [line for line in fonts.splitlines()[2:] if line.strip()]
        assert any("CJK" in r or "Hei" in r or "Han" in r for r in rows), fonts
    if shutil.which("pdftotext") is None:
        return ""
    text = subprocess.run(["pdftotext", str(path), "-"], capture_output=True, text=True).stdout
    return unicodedata.normalize("NFKC", text)
