"""The report draws the lever's force polygon the kinetostatic sheet draws (issue 40, item 3):
at each of the two positions, after the ram group's, the lever's (G4, F_I4, R_A, R_O4,
R_4B of core.forces.polygons.lever_force_polygon) under its own title (its caption), in English
and Chinese."""
from __future__ import annotations

import pytest
from PySide6.QtCore import QRectF
from PySide6.QtGui import QImage

from core.forces.masses import MassProperties
from core.forces.polygons import lever_force_polygon
from core.linkage.spec import Spec
from shaperapp.report.blocks import Figure
from shaperapp.report.content import Options, build
from shaperapp.widgets import i18n

from paint_recorder import PaintRecorder

LOADS = MassProperties(lever_mass_kg=20, lever_inertia_kg_m2=1.1, ram_mass_kg=70, cut_force_N=7000,
                       cut_height_mm=80)
TITLES = {"en": "Force polygon of the lever", "zh_CN": "导杆的力多边形"}
PX = 150 / 25.4


@pytest.mark.parametrize("language", ["en", "zh_CN"])
def test_the_report_draws_the_levers_force_polygon_at_both_positions(qapp, language):
    i18n.set_language(language)
    try:
        report = build(Spec(), [40.0], LOADS, "Lever", "2026-01-01", language, Options(diagram_deg=(90.0, 250.0)))
        figures = [b for b in report.blocks if isinstance(b, Figure)]
        found = []
        for figure in figures:
            image = QImage(round(figure.width_mm * PX), round(figure.height_mm * PX), QImage.Format.Format_ARGB32)
            image.setDotsPerMeterX(round(PX * 1000))
            image.setDotsPerMeterY(round(PX * 1000))
            painter = PaintRecorder(image)
            figure.paint(painter, QRectF(0, 0, image.width(), image.height()), PX)
            painter.end()
            if TITLES[language] in figure.caption:          # its title is its numbered caption
                found.append((figure.caption, len(painter.lines)))
    finally:
        i18n.set_language("en")
    design = Spec().design()
    expected = [len(lever_force_polygon(design, angle, 40.0, LOADS).vectors) for angle in (90.0, 250.0)]
    assert [n for _, n in found] == expected
    assert "90.00°" in found[0][0] and "250.00°" in found[1][0]
