"""Views on a hidden tab catch up when shown, not on every edit (issue 8, item 8), and
what they then show equals core. Also: 16 speeds in the assembled window at 1366×768."""
from __future__ import annotations

import numpy as np
import pytest
from PySide6.QtWidgets import QApplication

from core.forces.dynamics import solve_dynamics
from core.forces.masses import masses_for_design
from core.linkage.kinematics import solve

from gui_helpers import main_window


@pytest.fixture
def window(qtbot, tmp_path):
    with main_window(tmp_path) as win:
        win.resize(1366, 768)
        qtbot.waitExposed(win)
        yield win


def test_hidden_force_plots_wait_until_shown(window):
    forces = window.forces.stack()
    assert not forces.isVisible()                       # the Kinematics tab is in front
    window.model.set_spec(time_ratio=1.6)
    window.model.set_angle_index(77)
    assert not forces.is_current()                      # nothing redrawn behind the tab
    assert window.plots.stack().is_current()            # the visible view is
    window.tabs.setCurrentWidget(window.forces)
    QApplication.processEvents()
    assert forces.is_current()
    model = window.model
    dyn = solve_dynamics(model.design, model.motion.crank_angle, model.rpms,
                         masses_for_design(model.design, model.masses))
    shown = window.forces.curve_data("torque")
    for (_, y), want in zip(shown, dyn.crank_torque):
        np.testing.assert_allclose(y, want, rtol=1e-12, atol=1e-9)
    assert window.forces.cursor_value() == pytest.approx(np.degrees(model.motion.crank_angle[77]))


def test_hidden_kinematics_plots_catch_up_too(window):
    window.tabs.setCurrentWidget(window.forces)
    QApplication.processEvents()
    window.model.set_rpms([30, 50, 70])
    assert not window.plots.stack().is_current()
    window.tabs.setCurrentWidget(window.plots)
    QApplication.processEvents()
    assert window.plots.stack().is_current()
    motion = solve(window.model.design, window.model.motion.crank_angle, [30, 50, 70])
    for (_, y), want in zip(window.plots.curve_data("ram_a"), motion.ram_a):
        np.testing.assert_allclose(y, want, rtol=1e-12, atol=1e-12)
    assert window.plots.legend_names() == ["30 r/min", "50 r/min", "70 r/min"]


def test_read_back_of_a_hidden_view_is_never_stale(window):
    """A caller that reads a hidden view (an export, a report) gets the current results."""
    window.model.set_spec(time_ratio=1.6)
    model = window.model
    dyn = solve_dynamics(model.design, model.motion.crank_angle, model.rpms,
                         masses_for_design(model.design, model.masses))
    (_, y), *_ = window.forces.curve_data("power")
    np.testing.assert_allclose(y, dyn.power[0] / 1000.0, rtol=1e-12, atol=1e-12)


# Both plot tabs: the loads form now lives in the inputs pane, not beside the force plots.
@pytest.mark.parametrize("tab", [0, 1])
def test_sixteen_speeds_fit_the_window_at_1366x768(window, tab):
    window.model.set_rpms([20 + 5 * i for i in range(16)])
    window.tabs.setCurrentIndex(tab)
    QApplication.processEvents()
    widget = window.plots if tab == 0 else window.forces
    stack = widget.stack()
    graphics = stack._view
    last = "ram_a" if tab == 0 else "force"
    bottom = widget.plot_item(last).sceneBoundingRect().bottom()
    assert bottom <= graphics.height() + 1                       # nothing pushed out
    group = "main" if tab == 0 else "speeds"
    assert len(stack.legend(group).names()) >= 16
    assert stack.legend(group).head.sceneBoundingRect().right() <= graphics.width() + 1
    # every plot keeps a usable height
    names = ("ram_x", "ram_v", "ram_a") if tab == 0 else ("torque", "power", "energy", "force")
    for name in names:
        assert widget.plot_item(name).vb.sceneBoundingRect().height() > 40, name


def test_the_force_plots_are_drawn_while_idle_before_the_first_visit(window, qtbot):
    """Issue 40 item 5: the Forces tab's first drawing of 16 speeds was half its first
    visit. The window, idle, draws it behind its tab; the visit then redraws nothing, and
    what it shows equals core."""
    window.model.set_rpms([20.0 + 5.0 * i for i in range(16)])
    qtbot.waitUntil(lambda: all(page.is_ready() for page in window._pages.values()), timeout=60_000)
    forces = window.forces.stack()
    assert not forces.isVisible() and forces.is_current()
    refreshed = []
    real = type(forces).refresh
    forces.refresh = lambda: refreshed.append(1) or real(forces)
    window.tabs.setCurrentWidget(window.forces)
    QApplication.processEvents()
    assert refreshed == [] and forces.is_current()
    model = window.model
    dyn = solve_dynamics(model.design, model.motion.crank_angle, model.rpms,
                         masses_for_design(model.design, model.masses))
    shown = window.forces.curve_data("torque")
    assert len(shown) == 16
    for (_, y), want in zip(shown, dyn.crank_torque):
        np.testing.assert_allclose(y, want, rtol=1e-12, atol=1e-9)


def test_the_cam_plots_are_drawn_while_idle_and_the_cursor_follows_at_the_visit(window, qtbot):
    """The Cam tab, idle behind its tab, computes the cam and draws its plots (36 curve
    items for 16 speeds were most of its first visit); the visit redraws nothing, shows
    core's pitch curve, and its cursor is where the crank is now, not where it was when
    the plots were drawn."""
    import math

    from core.cam.follower import pitch
    window.model.set_rpms([20.0 + 5.0 * i for i in range(16)])
    qtbot.waitUntil(lambda: all(page.is_ready() for page in window._pages.values()), timeout=60_000)
    plots = window.cam.plots
    assert not plots.isVisible()
    window.model.set_angle_index(123)                    # the animation moved meanwhile
    drawn = []
    real = type(plots)._draw
    plots._draw = lambda: drawn.append(1) or real(plots)
    window.tabs.setCurrentWidget(window.cam)
    QApplication.processEvents()
    assert drawn == []
    cam = window.cam_model.cam
    x, y = plots.curves["psi"].getData()
    delta = np.radians(x)
    np.testing.assert_allclose(y, np.degrees(pitch(cam.follower, cam.program, delta).motion.psi), atol=1e-9)
    assert len(plots.speed_plot.listDataItems()) == 16
    phase = cam.timing.phase_deg if cam.timing is not None else 0.0
    want = (math.degrees(window.model.motion.crank_angle[123]) - phase) % 360.0
    assert all(c.value() == pytest.approx(want) for c in plots.cursors)


def test_the_cam_is_saved_and_opened_with_its_tab_never_built(window, tmp_path):
    """The Cam tab is built when first shown (issue 24), but the cam is the window's from
    the start: Save writes the cam's inputs and Open brings them back with the tab unbuilt,
    and the tab, once shown, shows the opened cam."""
    import json

    page = window._pages["cam"]
    window._idle_build_started = True            # keep the idle building from building it
    assert not page.is_built()
    window.cam_model.set_fields(arm=150.0, rise_law="poly345")
    assert window.document.save_to(str(tmp_path / "d.json"))
    saved = json.loads((tmp_path / "d.json").read_text())["cam"]
    assert saved["arm_mm"] == 150.0 and saved["rise_law"] == "poly345"
    cam = window.cam_model.cam
    window.document.new()
    assert window.cam_model.cam.follower.arm_mm == 120.0
    assert window.document.open_path(str(tmp_path / "d.json"))
    assert window.cam_model.cam == cam
    assert not page.is_built()
    window.tabs.setCurrentWidget(window.cam)
    QApplication.processEvents()
    assert window.cam.cam_model is window.cam_model
    assert window.cam.form.fields["arm"].edit.text() == "150"


def test_the_first_show_refreshes_the_front_plots_at_their_size(qtbot, tmp_path, monkeypatch):
    """Issue 43 item 5: the Kinematics page is shown before its tab widget lays it out; its
    first refresh ran at a provisional size (the pane 336 px tall instead of 533), put the
    legend beside the plots and back above them at the next resize, before the first paint.
    Now it is laid out first: the legend is placed once, where it stays."""
    from shaperapp.plots.legend import GroupLegend
    sides = []
    real = GroupLegend.set_side
    monkeypatch.setattr(GroupLegend, "set_side", lambda self, side: (sides.append(side), real(self, side)))
    with main_window(tmp_path) as win:
        qtbot.waitExposed(win)
        stack = win.plots.stack()
        assert sides == [] and not stack.legend("main").side()
        port = stack._scroll.viewport()
        assert port.height() >= stack._view.minimumHeight()          # the plots fit, legend above


def test_the_gear_and_cam_models_wait_and_save_open_as_if_made_at_start(qtbot, tmp_path, monkeypatch):
    """The window makes the cam's and the gear pair's models when first asked (issue 43
    item 5), but their places in the design file are there from the start: Save before
    either is made writes the default cam and pair as made models write them; Open
    refuses a file with a bad pair without making the model; models made after a file was
    opened hold that file's cam and pair, and Save writes them back unchanged."""
    import json

    from shaperapp.cam.model import CamModel
    from shaperapp.design.model import DesignModel
    from shaperapp.gear.model import GearModel
    from shaperapp.window.main_window import MainWindow

    made_at_start = DesignModel()
    want = {"cam": CamModel(made_at_start).document(), "gear": GearModel(made_at_start).document()}
    path, wrong = tmp_path / "parts.json", tmp_path / "wrong.json"
    with main_window(tmp_path) as win:
        win._idle_build_started = True                 # no idle build of the tabs meanwhile
        assert not win._part_models["cam"].made() and not win._part_models["gear"].made()
        assert win.document.save_to(str(path))
        document = json.loads(path.read_text(encoding="utf-8"))
        assert {name: document[name] for name in want} == want      # (Save made them)
    document["gear"] = {**document["gear"], "centre_mm": 170.0}
    document["cam"] = {**document["cam"], "arm_mm": 150.0, "rise_law": "poly345"}
    path.write_text(json.dumps(document), encoding="utf-8")
    wrong.write_text(json.dumps({**document, "gear": {**document["gear"], "centre_mm": 100.0}}),
                     encoding="utf-8")                 # no shift fits a′ = 100 mm for z 13/40, m 6
    monkeypatch.setattr(MainWindow, "_show_failure", lambda self, message: None)    # no dialog
    with main_window(tmp_path) as win:
        win._idle_build_started = True
        failures = []
        win.document.failed.connect(failures.append)
        assert not win.document.open_path(str(wrong))
        assert len(failures) == 1 and not win._part_models["gear"].made()
        assert win.document.open_path(str(path))
        assert not win._part_models["cam"].made() and not win._part_models["gear"].made()
        assert win.gear_model.pair.centre_mm == 170.0
        assert win.cam_model.cam.follower.arm_mm == 150.0
        assert win.cam_model.cam.program.rise_law == "poly345"
        assert {name: win.model.saved_parts()[name] for name in want} == {
            name: document[name] for name in want}


@pytest.mark.parametrize("language", ["en", "zh_CN"])
def test_the_loads_form_built_later_leaves_the_inputs_dock_as_it_was(qtbot, tmp_path, language):
    """The Loads form is built when its tab is first shown (issue 43 item 5): the inputs
    dock keeps its width and the form its fields' width then, in both languages (its
    scroll area is narrower than the design form's), and it shows the model's loads."""
    from shaperapp.widgets import i18n

    with main_window(tmp_path) as win:
        win._idle_build_started = True                 # no idle build meanwhile
        i18n.set_language(language)
        win.resize(1366, 768)
        qtbot.waitExposed(win)
        QApplication.processEvents()
        dock, pane = win.docks["inputs"], win.inputs
        before = (dock.width(), pane.width(), pane.widget(0).width())
        assert not pane.loads_page.is_built()
        pane.show_loads()
        QApplication.processEvents()
        assert pane.loads_page.is_built()
        assert (dock.width(), pane.width(), pane.widget(0).width()) == before
        area = win.loads.parentWidget().parentWidget()
        assert area.width() >= win.loads.minimumSizeHint().width()      # never clipped
        assert win.loads.field("cut_force_N").text() == f"{win.model.masses.cut_force_N:g}"


def test_the_loads_forms_labels_take_the_width_of_the_language_shown(qtbot, tmp_path):
    """The Loads form lines its fields up behind one label width: the widest label's in the
    language shown. A label's size hint kept the minimum width set for English, so after a
    switch to Chinese the label column stayed as wide as in English (and the Loads form,
    built while Chinese is shown, now starts narrow: both must agree)."""
    from shaperapp.widgets import i18n

    def label_width(win) -> int:
        return max(label.minimumWidth() for label in win.loads._labels.values())

    with main_window(tmp_path) as win:
        win._idle_build_started = True
        i18n.set_language("zh_CN")
        built_in_chinese = label_width(win)
    with main_window(tmp_path) as win:
        win._idle_build_started = True
        english = label_width(win)
        i18n.set_language("zh_CN")
        QApplication.processEvents()                   # the language change is delivered
        switched = label_width(win)
    assert switched == built_in_chinese < english


def test_closing_the_window_makes_no_cam_model(qtbot, tmp_path):
    """The window's close stops the cam's advice search, if the cam's model was ever made:
    a window closed without it does not make it (and import the cam) only to stop it."""
    with main_window(tmp_path) as win:
        win._idle_build_started = True
    assert not win._part_models["cam"].made()
