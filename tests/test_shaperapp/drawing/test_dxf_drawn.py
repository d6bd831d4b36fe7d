"""Every DXF drawn as a CAD program draws it, and compared with what the user saw.

Reading a DXF's entities back (the other tests) cannot see a drawing that CAD
shows wrongly: a linetype CAD cannot draw, an entity on the wrong side of the
paper, a panel whose entities were never written. Here ezdxf's own renderer
(its drawing add-on, the engine behind its viewer) draws the file into pixels:

- a sheet's DXF lies on the paper, and its linework is the linework of the
  sheet's SVG, pixel for pixel within half a millimetre, both ways;
- every drawing area of the sheet has ink in the DXF where the SVG has it
  (the texts included: CAD's font differs, so only their presence is compared);
- the scheme for CAD has ink at every joint and along every link where
  ``core`` puts them at the drawn crank angle.
"""
from __future__ import annotations

import ezdxf
import numpy as np
import pytest
from ezdxf.addons.drawing import Frontend, RenderContext
from ezdxf.addons.drawing.config import BackgroundPolicy, ColorPolicy, Configuration
from ezdxf.addons.drawing.pyqt import PyQtBackend
from PySide6.QtCore import QByteArray, QRectF
from PySide6.QtGui import QColor, QImage, QPainter
from PySide6.QtSvg import QSvgRenderer
from PySide6.QtWidgets import QGraphicsScene

from core.drawing.motion import motion_sheet
from core.drawing.scheme import scheme_document
from core.drawing.sheet import Sheet, Text, paper
from core.drawing.sheet_dxf import save_sheet_dxf
from core.forces.masses import MassProperties
from core.linkage.geometry import synthesize
from core.linkage.kinematics import shape
from core.drawing.forces import forces_sheet
from core.cam import CamInputs, Program, design_cam
from core.drawing.cam_sheet import cam_sheet
from core.drawing.dxf import save_dxf
from shaperapp.drawing.render import svg_bytes

PX_PER_MM = 4.0
TOLERANCE_PX = 2                       # half a millimetre on the paper
BLOCK = synthesize(100.0, 1.4, 300.0)
ROD = synthesize(100.0, 1.46, 312.0, rod_ratio=0.3)
LOADS = MassProperties(lever_mass_kg=20.0, lever_inertia_kg_m2=1.1, ram_mass_kg=70.0,
                       cut_force_N=7000.0, cut_height_mm=80.0)


def _ink(image: QImage) -> np.ndarray:
    """Dark pixels of ``image``, rows from the top."""
    grey = image.convertToFormat(QImage.Format.Format_Grayscale8)
    raw = np.frombuffer(grey.constBits(), np.uint8).reshape(grey.height(), grey.bytesPerLine())
    return raw[:, :grey.width()] < 224


def _canvas(width_mm: float, height_mm: float) -> QImage:
    image = QImage(round(width_mm * PX_PER_MM), round(height_mm * PX_PER_MM), QImage.Format.Format_RGB32)
    image.fill(QColor("white"))
    return image


def draw_dxf(path, window: QRectF) -> tuple[np.ndarray, QRectF]:
    """The DXF's model space drawn by ezdxf in black on white, ``window`` (DXF mm, y up)
    filling the image; and the extent of everything drawn, in DXF mm."""
    doc = ezdxf.readfile(path)
    scene = QGraphicsScene()
    config = Configuration(color_policy=ColorPolicy.BLACK, background_policy=BackgroundPolicy.WHITE)
    Frontend(RenderContext(doc), PyQtBackend(scene), config=config).draw_layout(
        doc.modelspace(), finalize=True)
    image = _canvas(window.width(), window.height())
    painter = QPainter(image)
    painter.setRenderHint(QPainter.RenderHint.Antialiasing)
    scene.render(painter, QRectF(image.rect()), window)
    painter.end()
    return _ink(image)[::-1], scene.itemsBoundingRect()     # the scene has DXF's y up


def draw_svg(data: bytes, width_mm: float, height_mm: float) -> np.ndarray:
    image = _canvas(width_mm, height_mm)
    painter = QPainter(image)
    QSvgRenderer(QByteArray(data)).render(painter)
    painter.end()
    return _ink(image)


def _near(mask: np.ndarray, k: int = TOLERANCE_PX) -> np.ndarray:
    grown = mask.copy()
    padded = np.pad(mask, k)
    h, w = mask.shape
    for dy in range(2 * k + 1):
        for dx in range(2 * k + 1):
            grown |= padded[dy:dy + h, dx:dx + w]
    return grown


def _pixels(box, height_mm: float) -> tuple[slice, slice]:
    """Rows and columns of a paper box (x0, y0, x1, y1 in mm, y up)."""
    x0, y0, x1, y1 = box
    return (slice(int((height_mm - y1) * PX_PER_MM), int(np.ceil((height_mm - y0) * PX_PER_MM))),
            slice(int(x0 * PX_PER_MM), int(np.ceil(x1 * PX_PER_MM))))


# Each sheet is built by the test that draws it, not at import: pytest-xdist imports this
# module in every worker to collect it, and five sheets built there cost each worker about
# 5 s of CPU whether or not it runs these tests.
SHEETS = {
    "motion block A3": lambda: motion_sheet(BLOCK, 40.0, paper("A3")),
    "motion rod A2": lambda: motion_sheet(ROD, 60.0, paper("A2"), count=16),
    "forces block A3": lambda: forces_sheet(BLOCK, 40.0, LOADS, paper("A3")),
    "forces rod A2": lambda: forces_sheet(ROD, 60.0, LOADS, paper("A2")),
    "cam A2": lambda: cam_sheet(design_cam(CamInputs(120.0, Program(15.0, 60.0, 10.0, 60.0)), BLOCK), 40.0,
                                paper("A2")),
}


@pytest.mark.parametrize("name", sorted(SHEETS))
def test_sheet_dxf_drawn_by_cad_is_the_sheet_the_user_saw(name, tmp_path, qapp):
    built = SHEETS[name]()
    sheet: Sheet = built.sheet
    width, height = sheet.paper.width, sheet.paper.height
    lines_only = Sheet(sheet.paper, tuple(it for it in sheet.items if not isinstance(it, Text)))

    save_sheet_dxf(sheet, tmp_path / "sheet.dxf")
    drawn, extent = draw_dxf(tmp_path / "sheet.dxf", QRectF(0, 0, width, height))
    # on the paper: nothing beyond its edge, bar half the edge line's own width
    assert extent.left() >= -0.5 and extent.top() >= -0.5
    assert extent.right() <= width + 0.5 and extent.bottom() <= height + 0.5

    save_sheet_dxf(lines_only, tmp_path / "lines.dxf")
    dxf_lines, _ = draw_dxf(tmp_path / "lines.dxf", QRectF(0, 0, width, height))
    svg_lines = draw_svg(svg_bytes(lines_only), width, height)
    # the linework agrees both ways: nothing CAD draws that the SVG lacks, nothing lost
    assert (dxf_lines & _near(svg_lines)).sum() >= 0.98 * dxf_lines.sum()
    assert (svg_lines & _near(dxf_lines)).sum() >= 0.98 * svg_lines.sum()

    shown = draw_svg(svg_bytes(sheet), width, height)
    for area, (box, _) in built.areas.items():
        rows, cols = _pixels(box, height)
        on_screen, in_cad = shown[rows, cols].sum(), drawn[rows, cols].sum()
        assert on_screen > 0, area
        # CAD's narrower GB font draws less ink per text, never a missing drawing
        assert in_cad >= 0.6 * on_screen, (area, in_cad, on_screen)


@pytest.mark.parametrize("design, angle", [(BLOCK, 0.0), (BLOCK, 117.0), (ROD, 250.0)])
def test_scheme_dxf_drawn_by_cad_shows_every_joint_where_core_puts_it(design, angle, tmp_path, qapp):
    save_dxf(scheme_document(design, angle), tmp_path / "scheme.dxf")
    sh = shape(design, np.radians([angle]))
    joints = {"O4": (0.0, 0.0), "O2": (0.0, design.frame),
              "A": tuple(sh.crank_pin[:, 0]), "B": tuple(sh.lever_tip[:, 0]),
              "C": tuple(sh.ram_joint[:, 0])}
    xs = [p[0] for p in joints.values()]
    ys = [p[1] for p in joints.values()]
    window = QRectF(min(xs) - 50, min(ys) - 50, max(xs) - min(xs) + 100, max(ys) - min(ys) + 100)
    drawn, _ = draw_dxf(tmp_path / "scheme.dxf", window)
    near = _near(drawn, 3)

    def inked(x: float, y: float) -> bool:
        row = int((window.bottom() - y) * PX_PER_MM)
        col = int((x - window.left()) * PX_PER_MM)
        return bool(near[row, col])

    missing = [name for name, (x, y) in joints.items() if not inked(x, y)]
    links = [("O2", "A"), ("O4", "B")] + ([("B", "C")] if design.rod is not None else [])
    for a, b in links:                    # ink all along each link, not only at its ends
        for t in np.linspace(0.2, 0.8, 7):
            x = joints[a][0] + t * (joints[b][0] - joints[a][0])
            y = joints[a][1] + t * (joints[b][1] - joints[a][1])
            if not inked(x, y):
                missing.append(f"{a}{b} at {t:.1f}")
    assert missing == []
    # and not by inking everything: most of the window stays paper
    assert drawn.mean() < 0.1
