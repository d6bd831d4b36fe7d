"""A damaged or hand-edited settings file never stops the window from opening.

QSettings hands back whatever type the file holds (a size, a point, a list of
numbers, a byte array of noise). Every value the app reads is tried with each
hostile kind; the window must open, keep working and show a sane recent-files menu.
"""
import pytest
from PySide6.QtCore import QByteArray, QPoint, QSettings, QSize
from PySide6.QtWidgets import QApplication

from gui_helpers import main_window
from shaperapp.design.document import MAX_RECENT

KEYS = ("language", "geometry", "windowState", "lastDir", "libraryPath", "recentFiles")
HOSTILE = {
    "size": QSize(3, 4),           # iterating it looped forever (recentFiles)
    "point": QPoint(1, 2),
    "numbers": [1, 2.5, None],
    "noise": QByteArray(b"\x01\xd9\xd0\xcb\x00\x03" + b"\xff" * 40),
    "empty": "",
    "huge list": ["/x/" + str(i) for i in range(100_000)],
    "nul": "a\0b",
    "long": "/" + "x" * 100_000,
}


@pytest.mark.parametrize("kind", HOSTILE)
@pytest.mark.parametrize("key", KEYS)
def test_window_opens_with_a_hostile_setting(qtbot, tmp_path, key, kind):
    settings = QSettings(str(tmp_path / "s.ini"), QSettings.Format.IniFormat)
    settings.setValue(key, HOSTILE[kind])
    settings.sync()
    del settings
    with main_window(tmp_path) as win:
        QApplication.processEvents()
        assert win.isVisible()
        recent = win.document.recent_files()
        assert len(recent) <= MAX_RECENT and all(isinstance(p, str) and "\0" not in p for p in recent)
        assert len(win.menus.recent.actions()) == len(recent)
        win.model.set_spec(time_ratio=1.5)            # still computes and shows
        assert win.model.error is None and win.model.design.time_ratio == pytest.approx(1.5)


def test_recent_files_keep_only_plain_paths(qtbot, tmp_path):
    settings = QSettings(str(tmp_path / "s.ini"), QSettings.Format.IniFormat)
    settings.setValue("recentFiles", ["/a.json", 7, "", "b\0c", "/" + "x" * 5000, "/d.json"])
    settings.sync()
    del settings
    with main_window(tmp_path) as win:
        assert win.document.recent_files() == ["/a.json", "/d.json"]
