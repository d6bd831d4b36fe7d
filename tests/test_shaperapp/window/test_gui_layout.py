"""The window fits a laptop, shows every result, and its panes can be moved and come back
(issue 8, item 1).

Fit tests run the real window in a subprocess on an offscreen screen of the size under
test (the screen is fixed when Qt starts): ``tests/layout_probe.py`` reports the frame,
the minimum size and, for every result table, which rows are clipped or unreachable.
"""
from __future__ import annotations

import pytest
from PySide6.QtCore import QByteArray, QSettings, Qt
from PySide6.QtGui import QGuiApplication
from PySide6.QtWidgets import QApplication, QDockWidget

from shaperapp.design.model import DesignModel
from shaperapp.widgets import i18n
from shaperapp.window.main_window import MainWindow
from shaperapp.window.state import STATE_VERSION
from layout_checks import SharedProbes, overlap, probe, probes

pytestmark = pytest.mark.slow   # left out of the quick run: pytest -m "not slow"

SIXTEEN = ",".join(str(20 + 5 * i) for i in range(16))
SPEED_ROWS, FORCE_ROWS = 9, 7


def stacks(lang: str, variant: str = "block") -> tuple[str, ...]:
    """One probe for the plot stacks of ``variant``; for the block variant (the default, so
    the tables are those of the default window) the tables' fit too."""
    return ("--lang", lang, "--variant", variant, "--stacks", "--speeds", "40,60", "--speeds", SIXTEEN)


def explore_compare(lang: str) -> tuple[str, ...]:
    return ("--lang", lang, "--explore", "--compare")


LIBRARY = ("--speeds", "40,60", "--library")
LAPTOPS = [(1366, 768), (1280, 720)]
LANGUAGES = ["en", "zh_CN"]
# every probe a test of this module reads through shared_probe, by screen
PLAN = {**{screen: [job for lang in LANGUAGES for job in (stacks(lang), stacks(lang, "rod"), explore_compare(lang))]
           + [LIBRARY] for screen in LAPTOPS},
        (1920, 1080): [LIBRARY]}


@pytest.fixture(scope="module")
def shared_probe(tmp_path_factory):
    """Each probe of PLAN run once, a screen's probes in one process (layout_checks.SharedProbes)."""
    return SharedProbes(lambda: tmp_path_factory.mktemp("probe"), PLAN)


def inside(outer: list[int], inner: list[int]) -> bool:
    ox, oy, ow, oh = outer
    x, y, w, h = inner
    return ox <= x and oy <= y and x + w <= ox + ow and y + h <= oy + oh


@pytest.mark.parametrize("lang", LANGUAGES)
@pytest.mark.parametrize("width,height", LAPTOPS)
def test_window_and_every_result_table_fit(shared_probe, width, height, lang):
    report = shared_probe(width, height, *stacks(lang))
    assert report["screen"] == [0, 0, width, height]
    for case in report["cases"]:
        assert inside(report["screen"], case["frame"]), case["frame"]
        assert case["minimum"][0] <= 1280 and case["minimum"][1] <= 720, case["minimum"]
        assert case["results_visible"]
        dims, cycle, speeds, forces = case["tables"]
        assert (dims["rows"], cycle["rows"], speeds["rows"], forces["rows"]) == (8, 5, SPEED_ROWS, FORCE_ROWS)
        assert speeds["columns"] == forces["columns"] == case["speeds"]
        for table in case["tables"]:
            assert table["hidden_rows"] == [], table["titles"]            # no row clipped in its table
            assert table["unreachable_rows"] == [], table["titles"]       # the pane scrolls to each
            assert table["last_column_reachable"], table["titles"]
            if table["needs_h_scroll"]:
                assert table["h_scroll_visible"], table["titles"]       # scrolls visibly
        if case["speeds"] == 2:             # two speeds fit: long row titles wrap instead
            assert not any(t["needs_h_scroll"] for t in case["tables"]), [t["titles"] for t in case["tables"]]
        if case["speeds"] == 16:            # 16 speeds never fit a side pane: they scroll
            assert speeds["needs_h_scroll"] and speeds["h_scroll_visible"]
        if lang == "zh_CN":
            assert any("，mm" in t for t in dims["titles"])                # translated titles
        else:
            assert "Frame O2O4 L2, mm" in dims["titles"]


@pytest.mark.parametrize("lang", LANGUAGES)
@pytest.mark.parametrize("width,height", LAPTOPS)
def test_compare_plots_readable_on_a_laptop(shared_probe, width, height, lang):
    """Stacked four high, the Compare tab's plots got 45 px each at 1366×768: their axis
    titles ran into each other and the legend covered the curves."""
    report = shared_probe(width, height, *explore_compare(lang))["compare"]
    assert report["legend_rows"] == 2
    assert report["table_rows_shown"] >= min(2, report["table_rows"]), report["table_rows_shown"]   # 1 before
    for key, plot in report["plots"].items():
        x, y, w, h = plot["box"]
        assert h >= 70 and w >= 150, (key, plot["box"])     # 36-45 px before
        assert plot["title_text"].strip(), key
        assert not overlap(report["legend"], plot["box"]), key
        assert not overlap(report["legend"], plot["title"]), key
    plots = list(report["plots"].values())
    for i, a in enumerate(plots):
        for b in plots[i + 1:]:
            assert not overlap(a["box"], b["box"])
            assert not overlap(a["title"], b["title"]), (a, b)        # titles ran into each other


def spread(boxes: list[list[float]]) -> bool:
    """No two boxes overlap."""
    return not any(overlap(a, b) for i, a in enumerate(boxes) for b in boxes[i + 1:])


@pytest.mark.parametrize("variant", ["block", "rod"])
@pytest.mark.parametrize("lang", LANGUAGES)
@pytest.mark.parametrize("width,height", LAPTOPS)
def test_every_stacked_plot_has_ticks_and_its_own_title(shared_probe, width, height, lang, variant):
    """With 16 speeds the Forces plots got 60 px each: 0-2 tick labels (the joint-force
    plot none) and y titles running into each other ("Input powerEnergy"); with 2 speeds
    still 2 ticks (the Chinese rod variant's joint forces a single "5"). Now every plot
    keeps three labels and a title within its own height, and the stack scrolls."""
    report = shared_probe(width, height, *stacks(lang, variant))
    for case in report["cases"]:
        for name, stack in case["stacks"].items():
            where = (case["speeds"], name)
            assert stack["view_height"] >= stack["needed_height"] - 1, where    # scrolls, not squeezed
            plots = stack["plots"]
            assert len(plots) >= 3, where
            for plot in plots:
                x, y, w, h = plot["box"]
                assert len(plot["ticks"]) >= 3, (where, plot["key"], h, plot["ticks"])
                assert spread(plot["ticks"]), (where, plot["key"])
                assert plot["title"] is not None and plot["title_text"].strip(), (where, plot["key"])
                tx, ty, tw, th = plot["title"]
                assert y - 1 <= ty and ty + th <= y + h + 1, (where, plot["key"], plot["title"], plot["box"])
                # the title never covers a tick label: "(N·m)" ran over the minus of −4000
                # with 16 speeds, the two-line Chinese titles over every label
                assert not [t for t in plot["ticks"] if overlap(plot["title"], t)], (where, plot["key"])
            x_ticks = [p["x_ticks"] for p in plots if p["x_ticks"] is not None]
            assert len(x_ticks) == 1 and len(x_ticks[0]) >= 3 and spread(x_ticks[0]), where
            assert spread([p["title"] for p in plots]), where              # titles apart
            assert spread([p["box"] for p in plots]), where


@pytest.mark.parametrize("lang", LANGUAGES)
@pytest.mark.parametrize("width,height", LAPTOPS)
def test_explore_map_fills_its_tab(shared_probe, width, height, lang):
    """The map was about 150 px tall over an empty band, its top tick "3.0" cut in half
    and its colour bar untitled (issue 20 item 4)."""
    report = shared_probe(width, height, *explore_compare(lang))["explore"]
    assert report["map_height"] >= 0.4 * report["tab_height"], report
    assert report["colorbar_title"].strip()
    # the Chinese title ran over the colour bar's tick labels (issue 34 item 8)
    assert not [t for t in report["ticks"]["colorbar"] if overlap(report["colorbar_title_box"], t)]
    x, y, w, h = report["view"]
    for name, ticks in report["ticks"].items():
        assert len(ticks) >= 3, (name, ticks)
        for tx, ty, tw, th in ticks:
            assert x <= tx and y <= ty and tx + tw <= x + w and ty + th <= y + h, (name, (tx, ty, tw, th), report["view"])


def test_saved_geometry_only_if_it_fits_the_screen(tmp_path):
    settings = str(tmp_path / "s.ini")          # one file: the second window reads what the first saved
    big, again = probes(tmp_path, 1920, 1080, [("--settings", settings, "--resize", "1700x1000"),
                                               ("--settings", settings, "--speeds", "40,60")])
    assert big["resized"] == [1700, 1000]
    assert again["cases"][0]["size"] == [1700, 1000]             # restored
    assert again["cases"][0]["results_area"] == "LeftDockWidgetArea"   # the large screen's layout
    laptop = probe(tmp_path, 1366, 768, "--speeds", "40,60")
    case = laptop["cases"][0]
    assert inside(laptop["screen"], case["frame"])                # not restored: it would not fit
    # nor the panes' layout saved with it (issue 20 item 5): the laptop's default
    assert case["results_area"] == "RightDockWidgetArea", case["results_area"]
    assert case["results_tabbed_with"] == ["polygonsDock"], case["results_tabbed_with"]


# ---- in-process: docks, state, toolbar ------------------------------------------------
@pytest.fixture
def window(qtbot, tmp_path):
    settings = QSettings(str(tmp_path / "s.ini"), QSettings.Format.IniFormat)
    win = MainWindow(DesignModel(), settings)
    win.show()
    qtbot.waitExposed(win)
    QApplication.processEvents()
    yield win
    win.model.set_clean(win.model.path)
    win.close()
    win.deleteLater()
    i18n.set_language("en")


def test_every_pane_is_a_dock_with_a_view_menu_entry(window):
    names = {"inputs": window.inputs, "results": window.metrics, "mechanism": window.scheme,
             "polygons": window.polygon_view, "library": window.library}
    view_actions = window.menus.panes.actions()
    for name, pane in names.items():
        dock = window.docks[name]
        assert isinstance(dock, QDockWidget) and dock.objectName() == f"{name}Dock"
        shown = window.docks.pane(name)
        assert shown is pane or shown.widget() is pane       # the results pane scrolls
        assert dock.toggleViewAction() in view_actions
    # inputs pane: the design form and the loads form
    assert window.inputs.indexOf(window.form.parentWidget().parentWidget()) == 0
    # (the loads form's scroll area in the page that builds it when first shown)
    assert window.loads.parentWidget().parentWidget().parentWidget() is window.inputs.loads_page
    assert window.inputs.indexOf(window.inputs.loads_page) == 1
    assert window.act_reset_layout in window.menus.view.actions()
    # the central tabs no longer hold the loads form or the polygons
    assert window.tabs.indexOf(window.forces) == 1 and window.tabs.indexOf(window.polygon_view) == -1


def test_hide_and_show_a_pane_from_the_view_menu(window):
    action = window.docks["results"].toggleViewAction()
    action.trigger()
    assert not window.docks["results"].isVisible()
    action.trigger()
    assert window.docks["results"].isVisible()


def test_reset_layout_brings_every_pane_back(window):
    window.docks["inputs"].hide()
    window.docks["mechanism"].setFloating(True)
    window.removeDockWidget(window.docks["results"])
    window.act_reset_layout.trigger()
    QApplication.processEvents()
    for name, dock in window.docks.docks.items():
        assert not dock.isFloating()
        assert dock.isVisible() == (name != "library"), name
        assert window.dockWidgetArea(dock) != Qt.DockWidgetArea.NoDockWidgetArea
    assert window.dockWidgetArea(window.docks["inputs"]) == Qt.DockWidgetArea.LeftDockWidgetArea
    assert window.dockWidgetArea(window.docks["mechanism"]) == Qt.DockWidgetArea.RightDockWidgetArea


def test_dock_state_round_trip(window, qtbot):
    window.docks["polygons"].raise_()                      # tabbed with the results (laptop layout)
    window.docks["library"].show()
    window.docks["inputs"].hide()
    window.removeDockWidget(window.docks["mechanism"])
    window.addDockWidget(Qt.DockWidgetArea.LeftDockWidgetArea, window.docks["mechanism"])
    window.docks["mechanism"].show()
    QApplication.processEvents()
    window.close()
    window.settings.sync()
    again = MainWindow(DesignModel(), window.settings)
    again.show()
    qtbot.waitExposed(again)
    QApplication.processEvents()
    try:
        assert not again.docks["inputs"].isVisible()
        assert again.docks["library"].isVisible()
        assert again.polygon_view.isVisible() and not again.metrics.isVisible()
        assert again.dockWidgetArea(again.docks["mechanism"]) == Qt.DockWidgetArea.LeftDockWidgetArea
        # (the size comes back only where it fits the screen: test_saved_geometry_only_if_it_fits)
    finally:
        again.close()
        again.deleteLater()


def test_a_state_of_another_version_is_ignored(qtbot, tmp_path):
    settings = QSettings(str(tmp_path / "old.ini"), QSettings.Format.IniFormat)
    first = MainWindow(DesignModel(), settings)
    first.docks["inputs"].hide()
    first.docks["library"].show()
    old = first.saveState(STATE_VERSION - 1)                 # as an older layout saved it
    first.deleteLater()
    settings.setValue("windowState", old)
    settings.setValue("geometry", QByteArray(b"garbage"))
    win = MainWindow(DesignModel(), settings)
    win.show()
    qtbot.waitExposed(win)
    try:
        assert win.docks["inputs"].isVisible() and not win.docks["library"].isVisible()
    finally:
        win.close()
        win.deleteLater()


def test_toolbar_has_the_main_actions_with_icons_and_tips(window, qtbot):
    bar = window.menus.toolbar
    shown = bar.actions()
    for action in (window.act_new, window.act_open, window.act_save, window.act_undo, window.act_redo,
                   window.act_report, window.act_play, window.act_back, window.act_step, window.act_fit,
                   window.act_fit_plots):
        assert action in shown
        assert not action.icon().isNull()
        assert action.toolTip()
    assert "Ctrl+S" in window.act_save.toolTip()
    window.set_language("zh_CN")
    qtbot.wait(10)
    assert "保存" in window.act_save.toolTip()
    assert bar.windowTitle() != "Main toolbar"


def test_toolbar_actions_work(window, qtbot):
    model = window.model
    model.set_spec(time_ratio=1.6)
    window.act_undo.trigger()
    assert model.spec.time_ratio == pytest.approx(1.4)
    window.act_redo.trigger()
    assert model.spec.time_ratio == pytest.approx(1.6)
    window.act_play.trigger()
    assert window.animation.is_playing()
    qtbot.waitUntil(lambda: model.angle_index > 0, timeout=10_000)
    window.act_play.trigger()
    assert not window.animation.is_playing()
    stack = window.plots.stack()
    plot = window.plots.plot_item("ram_v")
    plot.vb.setXRange(100, 120, padding=0)
    window.act_fit_plots.trigger()
    low, high = plot.vb.viewRange()[0]
    assert low <= 0.5 and high >= 359.0
    window.tabs.setCurrentWidget(window.positions)
    assert not window.act_fit_plots.isEnabled()
    assert stack.is_current()


def test_loads_tab_warns_of_an_invalid_load(window):
    assert window.inputs.tabIcon(1).isNull()
    window.model.set_masses(ram_mass_kg=-1.0)
    assert window.model.forces_error is not None
    assert not window.inputs.tabIcon(1).isNull()
    assert window.inputs.tabIcon(0).isNull()



def test_a_load_edit_sets_a_tab_icon_only_when_a_warning_comes_or_goes(window, monkeypatch):
    """Every load edit announces its error state; setting a tab's icon re-lays out the tab
    bar, the dock and the window (issue 40 item 5: a fifth of a Loads edit), so a valid
    edit after a valid one sets none."""
    calls = []
    original = window.inputs.setTabIcon
    monkeypatch.setattr(window.inputs, "setTabIcon", lambda *a: calls.append(a[0]) or original(*a))
    window.model.set_masses(cut_force_N=7100.0)
    assert calls == []
    window.model.set_masses(ram_mass_kg=-1.0)
    assert calls == [0, 1] and not window.inputs.tabIcon(1).isNull()
    window.model.set_masses(ram_mass_kg=50.0)
    assert calls == [0, 1, 0, 1] and window.inputs.tabIcon(1).isNull()

# ---- hidden panes wait (issue 8, item 8) -------------------------------------------------
def test_a_hidden_results_pane_waits_until_shown(window):
    window.docks["results"].hide()
    k_table = window.metrics.tables()[1]
    shown = k_table.text(0, 0)
    window.model.set_spec(time_ratio=1.6)
    assert k_table.text(0, 0) == shown                     # nothing redrawn behind a closed dock
    window.docks["results"].show()
    QApplication.processEvents()
    assert k_table.text(0, 0) == "1.6000"


def test_hidden_scheme_and_polygons_do_no_work_per_edit(window, monkeypatch):
    import shaperapp.vectors.view as polygon_view
    window.polygon_view            # built now (else by the idle builder, within the count)
    QApplication.processEvents()
    calls = {"scheme": 0, "polygons": 0}
    rebuild = window.scheme._mechanism.rebuild
    compute = polygon_view.polygons

    def counted_rebuild(*a, **k):
        calls["scheme"] += 1
        return rebuild(*a, **k)

    def counted_polygons(*a, **k):
        calls["polygons"] += 1
        return compute(*a, **k)

    monkeypatch.setattr(window.scheme._mechanism, "rebuild", counted_rebuild)
    monkeypatch.setattr(polygon_view, "polygons", counted_polygons)
    window.docks["mechanism"].hide()
    window.docks["polygons"].hide()
    QApplication.processEvents()
    for k in (1.5, 1.6, 1.7):
        window.model.set_spec(time_ratio=k)
        window.model.set_angle_index(10)
        QApplication.processEvents()
    assert calls == {"scheme": 0, "polygons": 0}
    window.docks["mechanism"].show()
    window.docks["polygons"].show()
    window.docks["polygons"].raise_()
    QApplication.processEvents()
    assert calls["scheme"] == 1 and calls["polygons"] >= 1
    joints = window.scheme.drawn_joints()
    assert joints["A"] == pytest.approx(tuple(window.model.motion.shape.crank_pin[:, 10]))


def test_result_tables_copy_with_titles(window):
    table = window.metrics.tables()[2]                      # per crank speed
    table.setCurrentCell(0, 1)
    table.copy()
    text = QGuiApplication.clipboard().text()
    lines = text.strip("\r\n").split("\r\n")
    assert lines[0] == "\t60 r/min"
    assert lines[1] == f"Cycle time, s\t{window.model.metrics.speeds[1].cycle_time_s:.4f}"
    table.clearSelection()
    table.copy()
    lines = QGuiApplication.clipboard().text().strip("\r\n").split("\r\n")
    assert len(lines) == 1 + SPEED_ROWS and lines[0] == "\t40 r/min\t60 r/min"


@pytest.mark.parametrize("width,height,beside", [(1366, 768, True), (1280, 720, True), (1920, 1080, False)])
def test_library_pane_fits_the_screen(shared_probe, width, height, beside):
    """Docked under the plots, the library made a 1366×768 window 810 px tall (its status
    bar and animation bar off the screen) and left its list no row; then it floated over
    the window there, where a user expects a pane to dock. On a short screen it is now a
    tab beside the Results and the vector diagrams; where there is room it stays docked
    under the plots; either way it is docked, the window stays on the screen and the list
    has room for rows."""
    report = shared_probe(width, height, *LIBRARY)
    library = report["library"]
    assert library["floating"] is False, library
    if beside:
        assert library["area"] == "RightDockWidgetArea", library
        assert sorted(library["tabbed_with"]) == ["polygonsDock", "resultsDock"], library
    else:
        assert library["area"] == "BottomDockWidgetArea" and not library["tabbed_with"], library
    assert inside(report["screen"], library["frame"]), library
    assert inside(report["screen"], library["dock"]), library
    assert library["rows_room"] >= 5, library
