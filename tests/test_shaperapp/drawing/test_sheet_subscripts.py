"""Subscripts on the sheets in both languages (issue 32, item 6): the translated strings'
index notation leaves no underscore on a Chinese sheet either, and the painter sets a
subscript right after its letter however long the text before it."""
import numpy as np
import pytest
from PySide6.QtGui import QColor, QImage, QPainter

from core.cam import CamInputs, Program, design_cam
from core.drawing.cam_sheet import cam_sheet
from core.drawing.forces import forces_sheet
from core.drawing.motion import motion_sheet
from core.drawing.sheet import PAPERS, Sheet, Text, marked, paper
from core.forces.masses import MassProperties, masses_for_design
from core.linkage.geometry import synthesize
from shaperapp.drawing.cam_labels import cam_labels
from shaperapp.drawing.forces_labels import forces_labels
from shaperapp.drawing.labels import motion_labels
from shaperapp.drawing.render import paint_sheet
from shaperapp.widgets.i18n import set_language

BLOCK = synthesize(100.0, 1.4, 300.0)
LOADS = MassProperties(lever_mass_kg=20.0, lever_inertia_kg_m2=1.1, ram_mass_kg=70.0,
                       cut_force_N=7000.0, cut_height_mm=80.0)


@pytest.fixture
def chinese(qapp):
    assert set_language("zh_CN")
    yield
    set_language("en")


def test_chinese_sheets_have_no_underscore_and_their_indices_below(chinese):
    cam = design_cam(CamInputs(120.0, Program(15.0, 60.0, 10.0, 60.0)), BLOCK)
    sheets = {"motion": motion_sheet(BLOCK, 40.0, paper("A1"), labels=motion_labels()).sheet,
              "forces": forces_sheet(BLOCK, 40.0, masses_for_design(BLOCK, LOADS), paper("A1"),
                                     labels=forces_labels()).sheet,
              "cam": cam_sheet(cam, 40.0, paper("A1"), labels=cam_labels()).sheet}
    for name, sheet in sheets.items():
        texts = [t for t in sheet.items if isinstance(t, Text)]
        assert any("\u4e00" <= ch <= "\u9fff" for t in texts for ch in t.text), name   # translated
        assert [t.text for t in texts if "_" in t.text] == [], name
    forces = [t for t in sheets["forces"].items if isinstance(t, Text)]
    pairs = {(t.text[:a][-2:], t.text[a:b]) for t in forces for a, b in t.subscripts}
    assert {(" M", "m"), ("ΔW", "max"), (" J", "F"), (" J", "e"), ("，μ", "F"), ("μ", "l")} <= pairs


def ink_columns(text: Text, px_per_mm: float = 20.0) -> np.ndarray:
    """Which columns of a rendering of ``text`` alone have ink."""
    sheet = Sheet(PAPERS["A3"], (text,))
    image = QImage(round(220 * px_per_mm), round(20 * px_per_mm), QImage.Format.Format_Grayscale8)
    image.fill(QColor("white"))
    painter = QPainter(image)
    painter.scale(px_per_mm, px_per_mm)
    painter.translate(0.0, -(PAPERS["A3"].height - 20.0))
    paint_sheet(sheet, painter)
    painter.end()
    raw = np.frombuffer(image.constBits(), np.uint8).reshape(image.height(), image.bytesPerLine())
    return (raw[:, :image.width()] < 160).any(axis=0)


@pytest.mark.parametrize("caption", ["Flywheel to add J_F − J_e", "Mean reduced inertia J_e",
                                     "Energy fluctuation ΔW_max"])
def test_a_subscript_follows_its_letter_after_a_long_text(qapp, caption):
    """The widest blank between inked columns is no wider than in the same text set without
    subscripts (a word space): the font is narrower than the sheet's width estimate, and
    the subscript stood a few millimetres away from its letter."""
    plain, spans = marked(caption)
    height = 5.0

    def widest_blank(text: Text) -> float:
        inked = np.flatnonzero(ink_columns(text))
        return float((np.diff(inked) - 1).max()) / 20.0
    with_subscripts = widest_blank(Text(plain, (10.0, 8.0), height, "lb", subscripts=spans))
    without = widest_blank(Text(plain, (10.0, 8.0), height, "lb"))
    assert with_subscripts <= without + 0.1 * height, (with_subscripts, without)
    # aligned by the drawn width: right-aligned, it still ends at its position
    right = np.flatnonzero(ink_columns(Text(plain, (200.0, 8.0), height, "rb", subscripts=spans)))
    assert abs(right[-1] / 20.0 - 200.0) <= 0.1 * height
