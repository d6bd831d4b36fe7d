"""File › Export drawing sheet… offers the gear meshing sheet (issue 35, item 5): disabled
with a tooltip saying why when the design has no gear pair, else enabled, on A2 by default,
drawing the design's pair (its centres a′ apart in the DXF's model coordinates). On
55087ce the dialog had no gear entry."""
import ezdxf
import pytest
from PySide6.QtCore import Qt

from core.gear import GearPairInputs, design_pair
from core.gear.file import gear_to_dict
from core.linkage.spec import Spec
from shaperapp.drawing.dialog import DrawingSheetDialog

pytestmark = pytest.mark.slow       # each dialog draws its motion sheet preview first (about 3 s)
GEAR = GearPairInputs(z1=13, z2=40, module_mm=6.0, centre_mm=162.0)


def gear_index(dialog: DrawingSheetDialog) -> int:
    index = dialog.content.findData("gear")
    assert index >= 0
    return index


def test_without_a_valid_gear_the_entry_is_disabled_and_says_why(model, qtbot):
    for parts, why in ((None, "no gear pair"), ({"gear": {"z1": 13, "z2": 40}}, "module_mm")):
        model.load_state(Spec(), [40.0], 1.0, parts=parts)
        dialog = DrawingSheetDialog(model, "en")
        qtbot.addWidget(dialog)
        index = gear_index(dialog)
        assert not dialog.content.model().item(index).isEnabled()
        assert why in dialog.content.itemData(index, Qt.ItemDataRole.ToolTipRole)


def test_with_a_gear_the_sheet_is_the_pair_on_a2(model, qtbot, tmp_path):
    model.load_state(Spec(), [40.0], 1.0, parts={"gear": gear_to_dict(GEAR)})
    dialog = DrawingSheetDialog(model, "en")
    qtbot.addWidget(dialog)
    index = gear_index(dialog)
    assert dialog.content.model().item(index).isEnabled()
    assert dialog.content.itemData(index, Qt.ItemDataRole.ToolTipRole) is None
    dialog.content.setCurrentIndex(index)
    assert dialog.paper.currentText() == "A2"
    assert not dialog.count.isEnabled() and not dialog.angles[0].isEnabled()
    dialog.update_preview()
    assert dialog.message.text() == "" and not dialog.preview.pixmap().isNull()
    out = tmp_path / "gear.dxf"
    dialog.export(str(out))
    pair = design_pair(GEAR)
    circles = ezdxf.readfile(out).modelspace().query("CIRCLE")
    tips = {(round(c.dxf.center.x, 6), round(c.dxf.center.y, 6)) for c in circles
            if abs(c.dxf.radius - pair.gear1.ra) < 1e-9}
    assert tips == {(0.0, 0.0)}                       # O1 at the origin (the DXF is in the model's mm)
    reference2 = [c for c in circles if abs(c.dxf.radius - pair.gear2.r) < 1e-9]
    for c in reference2:
        assert c.dxf.center.x == pytest.approx(pair.centre_mm, abs=1e-9)
    dialog.content.setCurrentIndex(dialog.content.findData("motion"))
    assert dialog.paper.currentText() == "A1"          # back to the motion sheet's paper


def test_the_gear_sheet_says_when_the_gear_tab_has_an_error(model, qtbot):
    """As the cam sheet says it: while the Gear tab refuses what is typed (z1 = 4), the sheet
    draws the design's last valid pair, and the dialog says so; before, it said nothing
    (hunt s13-hunt2)."""
    from types import SimpleNamespace
    from core.base.errors import DesignError
    model.load_state(Spec(), [40.0], 1.0, parts={"gear": gear_to_dict(GEAR)})
    source = SimpleNamespace(error=None)
    dialog = DrawingSheetDialog(model, "en", gear=source)
    qtbot.addWidget(dialog)
    dialog.content.setCurrentIndex(gear_index(dialog))
    dialog.update_preview()
    assert dialog.message.text() == ""
    source.error = DesignError("z1", 4, "must be at least 5")
    dialog.update_preview()
    assert "last valid gear pair" in dialog.message.text()
    dialog.content.setCurrentIndex(dialog.content.findData("motion"))
    dialog.update_preview()
    assert dialog.message.text() == ""
