"""The report's offscreen views are never painted: every figure is exported by rendering
its scene (or the widget) straight into the SVG, so a paint of the view before it was
work thrown away, some 4 % of a course in process (docs/performance.md, "The report's
build (issue 43 item 4), 30 November"). On 18a5ced the views painted a dozen times a
report, in the event processing before each export."""
from __future__ import annotations

from PySide6.QtCore import QEvent, QObject, Qt
from PySide6.QtWidgets import QApplication, QWidget

from core.cam import CamInputs
from core.forces.masses import MassProperties
from core.linkage.spec import Spec
from shaperapp.report.content import Options, build

LOADS = MassProperties(lever_mass_kg=20, lever_inertia_kg_m2=1.1, ram_mass_kg=70, cut_force_N=7000,
                       cut_height_mm=80)


class PaintCounter(QObject):
    """Counts the paint events of widgets in windows not shown on screen (the report's)."""

    def __init__(self) -> None:
        super().__init__()
        self.painted: list[str] = []

    def eventFilter(self, watched, event) -> bool:  # noqa: N802 - Qt's name
        if (event.type() == QEvent.Type.Paint and isinstance(watched, QWidget)
                and watched.window().testAttribute(Qt.WidgetAttribute.WA_DontShowOnScreen)):
            self.painted.append(type(watched).__name__)
        return False


def test_a_report_paints_none_of_its_offscreen_views(qapp):
    counter = PaintCounter()
    QApplication.instance().installEventFilter(counter)
    try:
        report = build(Spec(), [40.0, 60.0], LOADS, "Unpainted", "2026-01-01", "en",
                       Options(cam=(CamInputs(), None)))
    finally:
        QApplication.instance().removeEventFilter(counter)
    assert len([b for b in report.blocks if type(b).__name__ == "Figure"]) >= 5     # the figures were made
    assert counter.painted == []
