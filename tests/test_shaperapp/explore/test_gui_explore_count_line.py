"""The count of valid designs on one line at 1280 × 720 (issue 34, every view readable on
a laptop): the status label had a third of its row, and in Chinese
"1600 个设计中有 664 个有效。" broke after "664"."""
from __future__ import annotations

import pytest
from PySide6.QtCore import QRect, Qt

from gui_helpers import main_window


def lines(label) -> int:
    """How many lines the label's text takes at the label's present width."""
    metrics = label.fontMetrics()
    box = metrics.boundingRect(QRect(0, 0, label.contentsRect().width(), 10_000),
                               int(Qt.TextFlag.TextWordWrap), label.text())
    return round(box.height() / metrics.lineSpacing())


@pytest.mark.parametrize("lang", ["zh_CN", "en"])
def test_the_count_of_valid_designs_takes_one_line(qtbot, tmp_path, lang):
    with main_window(tmp_path) as win:
        win.resize(1268, 672)
        qtbot.waitExposed(win)
        win.set_language(lang)
        explore = win.explore
        win.tabs.setCurrentWidget(explore)
        qtbot.waitUntil(lambda: explore.result is not None and explore.runner.job is None,
                        timeout=20_000)
        qtbot.wait(20)
        result = explore.result
        assert result.valid.size == 1600
        status = explore.status
        assert str(int(result.valid.sum())) in status.text()
        assert lines(status) == 1, (status.text(), status.contentsRect().width())
        assert explore.hover.width() >= 200          # the read-out beside it keeps room
