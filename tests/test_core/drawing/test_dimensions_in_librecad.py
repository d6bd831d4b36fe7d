"""The GB dimension style as a second CAD reader draws it (issue 32, item 6): LibreCAD 2.2
(``librecad dxf2pdf``, a Debian package) ignores DIMSCALE and drew the scheme's dimension
texts at a quarter of the labels' height, and the cam's text struck through by its line.
A dimension and a label of the same height on paper, printed by LibreCAD, measured in the
pixels of the page (the fit to the page scales both alike)."""
from __future__ import annotations

import os
import shutil
import subprocess

import numpy as np
import pytest

from core.drawing import dimensions as dims
from core.drawing.dxf import new_document, save_dxf, text_attribs

pytestmark = [pytest.mark.slow,
              pytest.mark.skipif(shutil.which("librecad") is None or shutil.which("pdftoppm") is None,
                                 reason="librecad or poppler-utils not installed")]
SCALE = 4.0                       # a print at 1:4, as the scheme of a 100 mm crank


def printed(tmp_path) -> np.ndarray:
    """A dimension (L = 400, its line at y = −100) and, to its right, a label as high as
    the dimension text should be, printed by LibreCAD: dark pixels, rows from the top."""
    doc = new_document()
    dims.add_dimstyle(doc, SCALE)
    msp = doc.modelspace()
    dims.linear(msp, (0.0, 0.0), (400.0, 0.0), (200.0, -100.0), 0.0, "L")
    msp.add_text("LABEL", height=dims.DIM_TEXT_MM * SCALE, dxfattribs=text_attribs()).set_placement((600.0, -100.0))
    path = tmp_path / "d.dxf"
    save_dxf(doc, path)
    env = {**os.environ, "QT_QPA_PLATFORM": "offscreen"}
    subprocess.run(["librecad", "dxf2pdf", "-a", "d.dxf"], cwd=tmp_path, env=env, check=True,
                   capture_output=True, timeout=120)
    subprocess.run(["pdftoppm", "-r", "100", "-gray", "-png", "d.pdf", "p"], cwd=tmp_path, check=True)
    from PIL import Image
    image = np.asarray(Image.open(next(tmp_path.glob("p*.png"))).convert("L"))
    return image < 160


def test_dimension_text_is_as_high_as_a_label_and_above_its_line(tmp_path):
    ink = printed(tmp_path)
    rows = ink.sum(axis=1)
    line_row = int(np.argmax(rows))                       # the dimension line: the longest row
    extension = sorted(np.argsort(ink.sum(axis=0))[-2:])   # the two extension lines: the tallest columns
    right = int(extension[1])
    label = ink[:, right + 5:]
    # the dimension's text: between the extension lines, above the dimension line
    middle = ink[:line_row - 1, int(extension[0]) + 5: right - 5]
    text_rows = np.flatnonzero(middle.any(axis=1))
    label_rows = np.flatnonzero(label.any(axis=1))
    dim_height = text_rows[-1] - text_rows[0] + 1
    label_height = label_rows[-1] - label_rows[0] + 1
    assert dim_height == pytest.approx(label_height, rel=0.2), (dim_height, label_height)
    assert text_rows[-1] < line_row - 1                   # above the line, not struck through
