"""The joint names are set in the application's own face however the process started.

JOINT_FONTS was made when the scheme's module was imported: before the QApplication (a
course, a class, this test run, all import the scheme first) a QFont took the system's
first family, C059, a serif, bold italic; after it (``shaper report``) the application's
sans. The same design's report then printed its joint names in two faces."""
from __future__ import annotations

from PySide6.QtGui import QFontInfo
from PySide6.QtWidgets import QApplication

from gui_helpers import shown
from shaperapp.design.model import DesignModel
from shaperapp.scheme.view import SchemeWidget       # imported before the application, as a course does


def test_the_joint_names_are_in_the_applications_face(qtbot):
    scheme = shown(qtbot, SchemeWidget(DesignModel()), 600, 500)
    face = QFontInfo(QApplication.font()).family()
    for name, label in scheme._mechanism.labels.items():
        assert QFontInfo(label.textItem.font()).family() == face, name
