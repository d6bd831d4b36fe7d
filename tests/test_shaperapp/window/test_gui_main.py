"""The assembled window: default design, live updates, language switch, start-up."""
import subprocess
import sys

import numpy as np

from core.base.figure_text import figure_text   # one precision per kind (issue 40)
from core.linkage.geometry import synthesize
from core.linkage.kinematics import solve


def test_opens_on_default_design(window):
    assert window.model.design == synthesize(100, 1.4, 300)
    assert window.metrics.value_text("h") == "173.437"      # seed 003: h = 173.44 mm, to 3 decimals as everywhere (issue 40)
    assert window.metrics.row_title("h").endswith(", mm")
    assert "Untitled" in window.windowTitle()


def test_the_status_bar_writes_k_h_and_theta_as_every_table_does(window):
    """The status bar wrote H to 2 decimals (300.00 mm) under a Results pane writing
    300.000: it now writes K, H and θ through the one rule of every table."""
    metrics = window.model.metrics
    assert window.statusBar().currentMessage() == (
        f"K = {metrics.time_ratio:.4f}, H = {metrics.stroke_mm:.3f} mm, θ = {metrics.theta_deg:.3f}°")
    assert window.metrics.value_text("stroke") in window.statusBar().currentMessage()


def test_typing_k_updates_everything(window, qtbot):
    edit = window.form.field("time_ratio")
    edit.selectAll()
    with qtbot.waitSignal(window.model.resultsChanged, timeout=10_000):
        qtbot.keyClicks(edit, "1.6")
    expected = solve(synthesize(100, 1.6, 300), window.model.motion.crank_angle, [40, 60])
    curves = window.plots.curve_data("ram_v")
    assert len(curves) == 2
    for (x, y), want in zip(curves, expected.ram_v):
        assert np.allclose(y, want)
    assert window.metrics.value_text("K") == "1.6000"
    assert window.isWindowModified()


def test_invalid_value_keeps_old_curves(window, qtbot):
    before = [y.copy() for _, y in window.plots.curve_data("ram_a")]
    edit = window.form.field("time_ratio")
    edit.selectAll()
    with qtbot.waitSignal(window.model.errorChanged, timeout=10_000):
        qtbot.keyClicks(edit, "0.9")
    assert window.form.marked_fields() == ["time_ratio"]
    after = [y for _, y in window.plots.curve_data("ram_a")]
    assert all(np.array_equal(a, b) for a, b in zip(before, after))
    assert "Time ratio K" in window.statusBar().currentMessage()


def test_language_switch_changes_visible_labels(window, qtbot):
    assert window.menu_file.title() == "&File"
    window.set_language("zh_CN")
    qtbot.wait(10)
    assert window.menu_file.title() != "&File"
    assert "文件" in window.menu_file.title()
    assert "曲柄" in window.form._labels["crank"].text()
    window.set_language("en")
    qtbot.wait(10)
    assert window.menu_file.title() == "&File"
    assert window.form._labels["crank"].text() == "Crank length L1"


def test_translated_error_message(window, qtbot):
    window.set_language("zh_CN")
    window.model.set_spec(time_ratio=0.5)
    assert "行程速比系数" in window.form.error_text()


# Window state (geometry, docks) is tested in test_gui_layout.py.


def test_app_starts_and_renders(tmp_path):
    shot = tmp_path / "shot.png"
    env = dict(__import__("os").environ, QT_QPA_PLATFORM="offscreen", XDG_CONFIG_HOME=str(tmp_path))
    out = subprocess.run([sys.executable, "-m", "shaperapp.app", "--lang", "en", "--screenshot", str(shot)],
                         capture_output=True, text=True, env=env, timeout=120)
    assert out.returncode == 0, out.stderr
    assert "first window painted" in out.stdout
    assert shot.stat().st_size > 20_000


def test_help_guide_opens_and_follows_the_language(window):
    window.act_guide.trigger()
    guide = window._guide
    assert guide is not None and guide.isVisible()
    assert "User guide" in guide.browser.toPlainText()
    window.set_language("zh_CN")
    assert "使用指南" in guide.browser.toPlainText()


def test_closing_the_window_closes_the_guide(window):
    window.act_guide.trigger()
    window.close()
    assert not window._guide.isVisible()


def test_plot_export_is_offered_only_on_tabs_with_plots(window):
    for i in range(window.tabs.count()):
        window.tabs.setCurrentIndex(i)
        assert window.act_plots_img.isEnabled() == hasattr(window.tabs.widget(i), "export_image")


def test_forces_table_follows_edits_speeds_and_language(qtbot, tmp_path):
    """The forces and flywheel table is filled from forcesChanged (which follows every
    results change): after an edit and a change of speeds it shows core's summary of
    the new design, and after a language switch its row titles are translated."""
    from PySide6.QtWidgets import QApplication

    from core.forces.masses import masses_for_design
    from core.forces.flywheel import summarize
    from gui_helpers import main_window

    with main_window(tmp_path) as window:
        # Every lazy view built first: the window widens a little once they are (their
        # minimum sizes), and the row titles wrap to the table's width.
        for page in window._pages.values():
            page.view()
        QApplication.processEvents()
        model, metrics = window.model, window.metrics
        model.set_spec(time_ratio=1.6)
        model.set_rpms([30.0, 45.0, 90.0])
        QApplication.processEvents()
        summary = summarize(model.design, model.rpms, masses_for_design(model.design, model.masses))
        table = metrics.tables()[3]
        assert table.columnCount() == 3
        for col, s in enumerate(summary.speeds):
            assert metrics.table_text(5, col, forces=True) == figure_text("inertia", s.flywheel_inertia_kg_m2)
            assert metrics.table_text(1, col, forces=True) == figure_text("torque", s.max_torque_N_m)
        english = table.verticalHeaderItem(0).text()
        window.set_language("zh_CN")
        QApplication.processEvents()
        chinese = table.verticalHeaderItem(0).text()
        assert chinese != english and "N·m" in chinese
        window.set_language("en")
        QApplication.processEvents()
        # The same English words; the line they break on may differ: a title wrapped once
        # stays wrapped a scroll bar's width narrower (result_table._wrap_titles says why)
        assert table.verticalHeaderItem(0).text().replace("\n", " ") == english.replace("\n", " ")


def test_summary_is_solved_only_when_shown_and_filled_before_it_is_seen(qtbot, tmp_path):
    """The cycle summary (exact torque peaks, flywheel) is the largest part of an edit; it
    is solved when something shows it. Below the fold of the Results pane the forces table
    keeps its rows and columns; scrolled into view it shows core's numbers at once."""
    from PySide6.QtWidgets import QApplication, QScrollArea

    from core.forces.masses import masses_for_design
    from core.forces.flywheel import summarize
    from gui_helpers import main_window

    with main_window(tmp_path) as window:
        window.resize(1366, 768)
        model, metrics = window.model, window.metrics
        window.tabs.setCurrentIndex(0)
        QApplication.processEvents()
        table = metrics.tables()[3]
        assert table.visibleRegion().isEmpty()                    # below the fold
        model.set_spec(time_ratio=1.55)
        QApplication.processEvents()
        assert not model._dynamics_summary.solved()               # not solved: nothing shows it
        assert table.rowCount() == 7 and table.columnCount() == len(model.rpms)
        area = metrics.parentWidget()
        while not isinstance(area, QScrollArea):
            area = area.parentWidget()
        area.ensureWidgetVisible(table)
        QApplication.processEvents()
        assert not table.visibleRegion().isEmpty()
        summary = summarize(model.design, model.rpms, masses_for_design(model.design, model.masses))
        for col, s in enumerate(summary.speeds):                   # items as painted, no read-back
            assert table.item(5, col).text() == figure_text("inertia", s.flywheel_inertia_kg_m2)
            assert table.item(1, col).text() == figure_text("torque", s.max_torque_N_m)
        model.set_spec(time_ratio=1.5)                             # in view: filled at once
        QApplication.processEvents()
        summary = summarize(model.design, model.rpms, masses_for_design(model.design, model.masses))
        assert table.item(5, 0).text() == figure_text("inertia", summary.speeds[0].flywheel_inertia_kg_m2)
        window.tabs.setCurrentIndex(1)                             # the Forces tab needs it too
        QApplication.processEvents()
        assert model._dynamics_summary.solved()


def test_copying_the_forces_table_below_the_fold_copies_numbers(qtbot, tmp_path):
    """Copy from the forces table while its numbers wait (scrolled away) brings them up
    to date first: the clipboard never gets placeholders."""
    from PySide6.QtWidgets import QApplication

    from core.forces.masses import masses_for_design
    from core.forces.flywheel import summarize
    from gui_helpers import main_window

    with main_window(tmp_path) as window:
        window.resize(1366, 768)
        model, table = window.model, window.metrics.tables()[3]
        model.set_spec(time_ratio=1.45)
        QApplication.processEvents()
        text = table.tsv(selected_only=False)
        summary = summarize(model.design, model.rpms, masses_for_design(model.design, model.masses))
        assert "…" not in text and figure_text("torque", summary.speeds[0].max_torque_N_m) in text


def test_a_summary_that_cannot_be_computed_shows_dashes_and_the_forces_error(qtbot, tmp_path, monkeypatch):
    """The summary is solved late, in a view's update: if it fails there, nothing raises,
    the forces error names it and the table shows "—", never "nan" or old numbers."""
    from PySide6.QtWidgets import QApplication

    import shaperapp.design.results as results
    from gui_helpers import main_window

    with main_window(tmp_path) as window:
        model, metrics = window.model, window.metrics

        def fails(*args, **kwargs):
            raise ArithmeticError("overflow")
        monkeypatch.setattr(results, "summarize", fails)
        model.set_spec(time_ratio=1.45)
        QApplication.processEvents()
        summary = model.dynamics_summary
        assert all(s.max_torque_N_m != s.max_torque_N_m for s in summary.speeds)   # NaN
        assert model.forces_error is not None and "cannot be computed" in str(model.forces_error)
        texts = [metrics.table_text(row, col, forces=True) for row in range(7) for col in range(2)]
        assert set(texts) == {"—"}
        monkeypatch.undo()
        model.set_spec(time_ratio=1.5)                         # a good edit clears it
        QApplication.processEvents()
        assert model.forces_error is None
        assert metrics.table_text(1, 0, forces=True) != "—"
