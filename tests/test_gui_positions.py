"""The Positions tab: rows equal core's table, a row moves the animation, Copy pastes as cells."""
import pytest
from PySide6.QtCore import Qt
from PySide6.QtGui import QGuiApplication

from core.dynamics import masses_for_design
from core.positions import SPECIAL_NAMES, display_values, number_text, position_table, positions
from shaperapp.positions_view import PositionsView

from gui_helpers import shown


@pytest.fixture
def view(qtbot, model):
    return shown(qtbot, PositionsView(model), 900, 600)


def cell(view, row, column_name):
    tips = [view.table_model.headerData(c, Qt.Orientation.Horizontal, Qt.ItemDataRole.ToolTipRole)
            for c in range(view.table_model.columnCount())]
    return view.table_model.index(row, tips.index(column_name)).data()


def test_rows_are_core_table_numbers(view, model):
    design = model.design
    masses = masses_for_design(design, model.masses)
    table = position_table(design, positions(design, 12, (), masses.idle_fraction), model.rpms, masses)
    shown = display_values(table.data)
    assert view.table_model.rowCount() == 12 + len(SPECIAL_NAMES)
    for row in (0, 3, 13, 16):
        for name in ("ram_v_m_s", "crank_torque_N_m", "O4_y_N"):
            assert cell(view, row, name) == number_text(shown[row, table.columns.index(name)])
    assert view.table_model.index(16, 1).data() == "max cutting speed"
    view.speed_box.setCurrentIndex(1)
    k = 18
    assert cell(view, 3, "ram_v_m_s") == number_text(shown[k + 3, table.columns.index("ram_v_m_s")])


def test_selecting_a_row_moves_the_animation(view, model, qtbot):
    with qtbot.waitSignal(model.angleChanged):
        view.view.selectRow(3)                       # position 4, φ = 90°
    assert model.crank_deg == pytest.approx(90.0)
    view.view.selectRow(15)                          # cut end, off the 1° grid
    exact = view.crank_deg(15)
    assert abs(model.crank_deg - exact) <= model.step_deg / 2 + 1e-9


def test_count_and_design_changes_rebuild(view, model, qtbot):
    view.set_count(24)
    assert view.table_model.rowCount() == 24 + 6
    assert cell(view, 1, "crank_deg") == "15.000"
    model.set_spec(variant="rod")
    # one rebuild for the edit's two signals (results, then forces), when events run
    qtbot.waitUntil(lambda: "rod_deg" in view.table_model._tips)
    assert cell(view, 0, "rod_deg") is not None


def test_one_edit_rebuilds_the_table_once(view, model, qtbot, monkeypatch):
    calls = []
    show = view._show
    monkeypatch.setattr(view, "_show", lambda: (calls.append(1), show()))
    model.set_spec(time_ratio=1.5)
    qtbot.waitUntil(lambda: calls != [])
    qtbot.wait(50)
    assert calls == [1]
    assert cell(view, 1, "crank_deg") is not None


def test_copy_is_tab_separated_with_header(view, qtbot):
    view.view.selectRow(1)
    view.copy()
    text = QGuiApplication.clipboard().text()
    lines = text.strip("\r\n").split("\r\n")
    assert len(lines) == 2
    header, row = (line.split("\t") for line in lines)
    assert len(header) == len(row) == view.table_model.columnCount()
    assert row[0] == "2" and "φ (°)" in header
    view.view.clearSelection()
    view.copy()
    assert len(QGuiApplication.clipboard().text().strip().split("\r\n")) == 1 + 18
