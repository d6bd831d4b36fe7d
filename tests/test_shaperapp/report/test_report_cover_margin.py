"""The report cover's title keeps the margin the cover's other texts keep from its frame
(CELL_PAD_MM, 2 mm): the English title ran to about 1 mm from the frame at 17 pt.

Checked on pixels of the printed first page (pdftoppm at 300 dpi): the frame is found as
the columns inked over the whole height of the title's row, the title as the other ink in
that row."""
from __future__ import annotations

import shutil
import subprocess

import numpy as np
import pytest
from PySide6.QtGui import QImage

from cli_runner import shaper_in_process
from figure_checks import pixels

pytestmark = pytest.mark.skipif(shutil.which("pdftoppm") is None, reason="pdftoppm not installed")
DPI = 300
PX_MM = DPI / 25.4


def title_row(page: np.ndarray) -> tuple[np.ndarray, int, int]:
    """The ink of the cover's title row (between the frame's top line and the first rule
    under it), the last column of the frame's left line and the first of its right one."""
    ink = (page < 160).any(axis=2)
    long_rows = np.flatnonzero(ink.sum(axis=1) > 0.5 * ink.shape[1])     # the frame's and the rules' lines
    lines = np.split(long_rows, np.flatnonzero(np.diff(long_rows) > 1) + 1)
    band = ink[lines[0][-1] + 2:lines[1][0] - 1]                           # under the top line, over the rule
    frame = np.flatnonzero(band.all(axis=0))                               # inked over the whole row
    runs = np.split(frame, np.flatnonzero(np.diff(frame) > 1) + 1)        # the left and the right line
    return band, int(runs[0][-1]), int(runs[-1][0])


@pytest.mark.parametrize("language", ["en", "zh"])
def test_the_covers_title_keeps_2_mm_from_its_frame(tmp_path, language):
    out = tmp_path / "r.pdf"
    status, _, err = shaper_in_process("report", "--crank", "100", "--K", "1.4", "--stroke", "300",
                                       "--lang", language, "-o", out)
    assert status == 0, err
    subprocess.run(["pdftoppm", "-r", str(DPI), "-f", "1", "-l", "1", "-png", str(out), str(tmp_path / "p")],
                   check=True)
    page = pixels(QImage(str(next(tmp_path.glob("p-*.png")))))
    band, left, right = title_row(page)
    columns = np.flatnonzero(band[:, left + 1:right].any(axis=0))     # the title's ink between the lines
    assert len(columns), "no title"
    gaps = columns[0] / PX_MM, (right - left - 2 - columns[-1]) / PX_MM   # mm from the frame's lines
    assert min(gaps) >= 1.9, gaps
