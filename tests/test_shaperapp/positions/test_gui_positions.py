"""The Positions tab: rows equal core's table and print as ``shaper table`` prints them, a row
moves the animation, Copy pastes as cells."""
import re

import pytest
from PySide6.QtCore import Qt
from PySide6.QtGui import QGuiApplication

from core.forces.masses import masses_for_design
from core.course_design.positions import SPECIAL_NAMES, display_values, position_table, positions
from core.files.dynamics_io import FLAG_COLUMNS
from core.files.io import save_design
from shaperapp.design.document import saved_parts
from shaperapp.positions.view import PositionsView

from cli_runner import shaper_in_process

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
            column = shown[:18, table.columns.index(name)]
            text = cell(view, row, name)
            last = 10.0 ** -len(text.partition(".")[2])          # the last decimal shown
            assert float(text) == pytest.approx(column[row], abs=last / 2 + 1e-12)
            assert last <= 1e-4 * abs(column).max()               # 5 significant digits of the largest
    assert view.table_model.headerData(16, Qt.Orientation.Vertical) == "max cutting speed"
    view.speed_box.setCurrentIndex(1)
    k = 18
    value = float(cell(view, 3, "ram_v_m_s"))
    assert value == pytest.approx(shown[k + 3, table.columns.index("ram_v_m_s")], abs=5e-5)


def test_selecting_a_row_moves_the_animation(view, model, qtbot):
    with qtbot.waitSignal(model.angleChanged, timeout=10_000):
        view.view.selectRow(3)                       # position 4, φ = 90°
    assert model.crank_deg == pytest.approx(90.0)
    view.view.selectRow(15)                          # cut end, off the 1° grid
    exact = view.crank_deg(15)
    assert abs(model.crank_deg - exact) <= model.step_deg / 2 + 1e-9


def test_count_and_design_changes_rebuild(view, model, qtbot):
    view.set_count(24)
    assert view.table_model.rowCount() == 24 + 6
    assert cell(view, 1, "crank_deg") == "15.00"
    model.set_spec(variant="rod")
    # one rebuild for the edit's two signals (results, then forces), when events run
    qtbot.waitUntil(lambda: "rod_deg" in view.table_model._tips, timeout=10_000)
    assert cell(view, 0, "rod_deg") is not None


def test_one_edit_rebuilds_the_table_once(view, model, qtbot, monkeypatch):
    calls = []
    show = view._show
    monkeypatch.setattr(view, "_show", lambda: (calls.append(1), show()))
    model.set_spec(time_ratio=1.5)
    qtbot.waitUntil(lambda: calls != [], timeout=10_000)
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
    assert len(header) == len(row) == view.table_model.columnCount() + 1      # the row titles first
    assert header[0] == "Position" and row[0] == "2" and "φ (°)" in header
    view.view.clearSelection()
    view.copy()
    assert len(QGuiApplication.clipboard().text().strip().split("\r\n")) == 1 + 18


def test_rows_keep_their_identity_and_numbers_read_one_way(qtbot, model):
    """At the laptop's tab size (560 px) the No. and Position columns scrolled away
    sideways, Position was the widest column and empty in the 12 numbered rows, and
    φ = 0 printed "0" beside "30.000" (issue 20 item 3)."""
    view = shown(qtbot, PositionsView(model), 560, 460)
    table, header = view.view, view.view.verticalHeader()
    table.horizontalScrollBar().setValue(table.horizontalScrollBar().maximum())
    qtbot.wait(10)
    assert header.isVisible() and header.width() > 0             # the row titles stay
    titles = [view.table_model.headerData(r, Qt.Orientation.Vertical) for r in range(18)]
    assert titles[:12] == [str(n) for n in range(1, 13)] and all(titles[12:])
    columns = view.table_model.columnCount()
    cells = [[view.table_model.index(r, c).data() for r in range(18)] for c in range(columns)]
    assert all(any(text for text in column) for column in cells)  # no empty column
    for column in cells:
        decimals = {len(text.partition(".")[2]) for text in column if text}
        assert len(decimals) == 1, column                        # one number of decimals
    assert cell(view, 0, "crank_deg") == "0.00" and cell(view, 1, "crank_deg") == "30.00"
    # about a quarter of the 560 px went to the identifying columns, not half
    assert header.width() <= 0.35 * table.width()


@pytest.mark.parametrize("language, yes, no", [("en", "yes", "no"), ("zh_CN", "是", "否")])
def test_the_tilt_flag_reads_yes_or_no(qtbot, model, language, yes, no):
    """``guide_tilted`` is a yes/no (1 or 0 in the CSV): the tab showed 1.0000 and 0.0000.
    Each row says yes exactly where core's dynamics has the ram tilt, and there the guide's
    offset is blank (the two end forces shown instead)."""
    from core.forces.dynamics import solve_dynamics
    from shaperapp.widgets.i18n import set_language
    set_language(language)
    try:
        model.set_masses(guide_length_mm=300.0)
        view = shown(qtbot, PositionsView(model), 900, 600)
        design = model.design
        masses = masses_for_design(design, model.masses)
        angles = positions(design, 12, (), masses.idle_fraction).crank_angle
        tilted = solve_dynamics(design, angles, model.rpms[:1], masses).guide_tilted[0]
        texts = [cell(view, row, "guide_tilted") for row in range(view.table_model.rowCount())]
        assert texts == [yes if t else no for t in tilted] and yes in texts and no in texts
        assert all((cell(view, row, "guide_offset_mm") == "") == bool(t) for row, t in enumerate(tilted))
    finally:
        set_language("en")


def cli_columns(out: str) -> dict[tuple[float, str], list[str]]:
    """``shaper table``'s text as {(rpm, column): its texts, row by row}, cut at the
    columns' right-justified edges (a blank cell stays '')."""
    columns: dict[tuple[float, str], list[str]] = {}
    for block in out.strip().split("\n\n"):
        lines = [line for line in block.splitlines() if not line.startswith("cut_start and")]
        rpm = float(lines[0].split(" r/min")[0])
        header = lines[1]
        ends = [m.end() for m in re.finditer(r"\S+", header)]
        names = header.split()
        # crank_deg, never blank, follows the left-justified names; the rest by their edges
        columns[(rpm, names[2])] = [line[:ends[2]].split()[-1] for line in lines[2:]]
        for c, name in enumerate(names[3:], start=3):
            columns[(rpm, name)] = [line[ends[c - 1]:ends[c]].strip() for line in lines[2:]]
    return columns


def test_the_tab_prints_what_shaper_table_prints(view, model, tmp_path):
    """Every cell of the Positions tab, at each speed, reads as ``shaper table`` prints that
    figure for the same design and loads (17.79 mm on screen beside the CLI's 17.788 before)."""
    path = tmp_path / "d.shaper.json"
    save_design(path, model.valid_spec, model.rpms, model.step_deg, extra=saved_parts(model))
    status, out, _ = shaper_in_process("table", "--design", path)
    assert status == 0
    printed = cli_columns(out)
    names = [view.table_model.headerData(c, Qt.Orientation.Horizontal, Qt.ItemDataRole.ToolTipRole)
             for c in range(view.table_model.columnCount())]
    assert "crank_torque_N_m" in names and "O4_y_N" in names
    compared = 0
    for speed, rpm in enumerate(model.rpms):
        view.speed_box.setCurrentIndex(speed)
        for c, name in enumerate(names):
            if name in FLAG_COLUMNS:
                continue                                    # yes / no on screen, 1 / 0 printed
            shown = [view.table_model.index(r, c).data() for r in range(view.table_model.rowCount())]
            assert shown == printed[(float(rpm), name)], (rpm, name)
            compared += 1
    assert compared >= 2 * 20
