"""The scheme's force arrows draw core's joint forces (the chosen crank speed) to one scale.

The expected forces are solved here again with core.forces.dynamics from the model's
design, crank angles, speeds and loads; the arrows are read back from the
drawn path (``SchemeWidget.drawn_forces``).
"""
from __future__ import annotations

import re
import sys
from dataclasses import replace

import numpy as np
import pytest
from PySide6.QtCore import QEvent
from PySide6.QtWidgets import QApplication, QCheckBox

from core.forces.dynamics import solve_dynamics
from gui_helpers import shown
from shaperapp.design.model import DesignModel
from shaperapp.scheme.view import SchemeWidget

SHARE = 0.35          # the issue: the largest force of the cycle ≈ 0.35·L3 long




def use_rod(model: DesignModel) -> None:
    model.set_spec(variant="rod", rod_ratio=0.3)
    assert model.error is None and model.design.rod is not None


def core_dynamics(model: DesignModel):
    masses = model.masses
    if model.design.rod is None:
        masses = replace(masses, rod_mass_kg=0.0)
    return solve_dynamics(model.design, model.motion.crank_angle, model.rpms, masses)


def expected_forces(model: DesignModel | None, dyn, index: int, speed: int = 0) -> dict[str, np.ndarray]:
    """Force on the named body at ``index``, speed ``speed`` (default the first), N
    (see docs/forces.md)."""
    i, s = index, speed
    out = {"O2": np.array([dyn.o2_x[s, i], dyn.o2_y[s, i]]),
           "A": np.array([dyn.a_x[s, i], dyn.a_y[s, i]]),
           "O4": np.array([dyn.o4_x[s, i], dyn.o4_y[s, i]]),
           "B": -np.array([dyn.b_x[s, i], dyn.b_y[s, i]]),      # rod/tip block on the lever
           "guide": np.array([0.0, dyn.guide_normal[s, i]]),
           "cut": np.array([-dyn.cut_force[s, i], 0.0])}
    if dyn.c_x is not None:
        out["C"] = np.array([dyn.c_x[s, i], dyn.c_y[s, i]])
    return out


def application_points(scheme: SchemeWidget, model: DesignModel, dyn, index: int) -> dict:
    sh, design = model.motion.shape, model.design
    c = sh.ram_joint[:, index]
    x, y = scheme.tool_path()                       # its last vertex is the tool point now
    return {"O2": np.array([0.0, design.frame]), "A": sh.crank_pin[:, index],
            "O4": np.zeros(2), "B": sh.lever_tip[:, index], "C": c,
            "guide": np.array([c[0] + dyn.guide_offset_mm[0, index], design.guide]),
            "cut": np.array([x[-1], y[-1]])}


def arrows(scheme: SchemeWidget) -> dict[str, tuple[np.ndarray, np.ndarray]]:
    return {name: (np.array(start), np.array(tip)) for name, (start, tip) in scheme.drawn_forces().items()}


def ram_x_extent(scheme: SchemeWidget) -> tuple[float, float]:
    return scheme.ram_extent()


def unit(v: np.ndarray) -> np.ndarray:
    return v / np.hypot(*v)


def show(scheme: SchemeWidget) -> None:
    scheme.set_forces_visible(True)
    assert scheme.forces_visible()


_CYCLES: dict[str, dict] = {}


def drawn_cycle(qtbot, variant: str) -> dict:
    """The arrows a shown scheme (900 × 650 px, the ``scheme`` fixture's) draws at every
    crank angle of the default design (``variant`` "block") or its rod variant, made once
    per variant and process and read by the three tests that walk the whole cycle: each
    frame's label placement was most of their time (about 20 ms a frame, 361 frames a walk).
    Plain data only: ``frames`` (index → name → (start, tip), mm), ``caption`` (at the last
    angle), ``views`` (left, right, top, bottom, mm: after showing the forces, then after
    ``fit()``), ``refitted`` (every third angle's arrows after ``fit()``), ``dyn`` (core's
    dynamics), ``angle_count``, ``lever`` (mm), ``rpm``."""
    if variant not in _CYCLES:
        model = DesignModel()
        scheme = shown(qtbot, SchemeWidget(model), 900, 650)     # as the fixtures build them
        if variant == "rod":
            use_rod(model)
        show(scheme)
        views = []
        scheme.drawn_forces()                        # the scheme caught up with the model
        views.append(scheme._view.viewRect())
        frames = []
        for index in range(model.angle_count):
            model.set_angle_index(index)
            frames.append(arrows(scheme))
        caption = scheme.force_caption()
        scheme.fit()
        scheme.drawn_forces()
        views.append(scheme._view.viewRect())
        refitted = {}                # read back through the new view: equal up to round-off
        for index in range(0, model.angle_count, 3):
            model.set_angle_index(index)
            refitted[index] = arrows(scheme)
        _CYCLES[variant] = dict(
            frames=frames, refitted=refitted, caption=caption, dyn=core_dynamics(model),
            views=[(v.left(), v.right(), v.top(), v.bottom()) for v in views],
            angle_count=model.angle_count, lever=model.design.lever, rpm=model.rpms[0])
    return _CYCLES[variant]


# ---- toggling ---------------------------------------------------------------
def test_hidden_by_default(scheme, model):
    box = scheme.findChild(QCheckBox, "forcesBox")
    assert not scheme.forces_visible()
    assert not box.isChecked() and not scheme.forces_action.isChecked()
    assert scheme.drawn_forces() == {}
    assert scheme.force_labels() == {} and scheme.force_caption() == ""
    model.set_angle_index(100)
    assert scheme.drawn_forces() == {}
    assert scheme.dimensions_visible()            # the other toggle is untouched


def test_toggled_by_checkbox_action_and_method(scheme):
    box = scheme.findChild(QCheckBox, "forcesBox")
    assert box.text() == scheme.forces_action.text() != ""
    box.setChecked(True)
    assert scheme.forces_action.isChecked() and scheme.forces_visible()
    assert scheme.drawn_forces() and scheme.force_caption()
    scheme.forces_action.setChecked(False)
    assert not box.isChecked() and scheme.drawn_forces() == {}
    assert scheme.force_labels() == {} and scheme.force_caption() == ""
    scheme.set_forces_visible(True)
    assert box.isChecked() and scheme.forces_action.isChecked() and scheme.drawn_forces()
    assert scheme.dimensions_visible()
    scheme.set_dimensions_visible(False)
    assert scheme.forces_visible()                # independent toggles


# ---- what is drawn equals core -------------------------------------------------
@pytest.mark.parametrize("variant", ["block", "rod"])
@pytest.mark.parametrize("degrees", [10, 100, 170, 200, 270, 330])
def test_arrows_point_along_core_forces_at_their_points(scheme, model, variant, degrees):
    if variant == "rod":
        use_rod(model)
    show(scheme)
    model.set_angle_deg(degrees)
    index = model.angle_index
    dyn = core_dynamics(model)
    forces = expected_forces(model, dyn, index)
    points = application_points(scheme, model, dyn, index)
    drawn = arrows(scheme)
    u = model.design.lever / 40.0
    lo, hi = ram_x_extent(scheme)
    for name, force in forces.items():
        magnitude = np.hypot(*force)
        if name == "guide":
            point = points["guide"]
            expect = magnitude > 0.0 and np.isfinite(point[0]) and lo <= point[0] <= hi
        else:
            expect = magnitude > 1e-6 * max(np.hypot(*f) for f in forces.values())
        assert (name in drawn) == expect, name
        if not expect:
            continue
        start, tip = drawn[name]
        np.testing.assert_allclose(unit(tip - start), unit(force), atol=1e-9, err_msg=name)
        # The point of application is on the arrow's line, just outside it (at most a pin's
        # radius from the nearer end), never crossed by it.
        p = points[name]
        d = unit(tip - start)
        across = d[0] * (p - start)[1] - d[1] * (p - start)[0]
        assert abs(across) < 1e-6, name
        along = float(np.dot(p - start, d))
        length = float(np.hypot(*(tip - start)))
        assert along <= 1e-9 or along >= length - 1e-9, name
        gap = min(abs(along), abs(along - length))
        assert gap <= 0.5 * u + 1e-9, name
    # The guide force and the cutting force sit exactly at their points; the cut arrow
    # ends at the tool point.
    if "guide" in drawn:
        np.testing.assert_allclose(drawn["guide"][0], points["guide"], atol=1e-9)
    if "cut" in drawn:
        np.testing.assert_allclose(drawn["cut"][1], points["cut"], atol=1e-9)
    assert ("C" in drawn) == (variant == "rod")


@pytest.mark.parametrize("variant", ["block", "rod"])
def test_one_length_scale_and_its_caption(qtbot, variant):
    cycle = drawn_cycle(qtbot, variant)
    dyn = cycle["dyn"]
    ratios, longest = [], 0.0
    for index in range(cycle["angle_count"]):
        forces = expected_forces(None, dyn, index)
        for name, (start, tip) in cycle["frames"][index].items():
            length = float(np.hypot(*(tip - start)))
            ratios.append(length / np.hypot(*forces[name]))
            longest = max(longest, length)
    mm_per_N = float(np.median(ratios))
    np.testing.assert_allclose(ratios, mm_per_N, rtol=1e-9)   # lengths ∝ magnitudes, everywhere
    assert longest == pytest.approx(SHARE * cycle["lever"], rel=0.05)
    largest = max(np.hypot(*f) for i in range(cycle["angle_count"])
                  for f in expected_forces(None, dyn, i).values())
    assert longest == pytest.approx(largest * mm_per_N, rel=1e-9)
    caption = cycle["caption"]
    assert f"{cycle['rpm']:g} r/min" in caption
    found = re.search(r"([\d.]+) mm ≙ ([\d.]+) (kN|N)", caption)
    assert found, caption
    ref_N = float(found.group(2)) * (1000.0 if found.group(3) == "kN" else 1.0)
    assert float(found.group(1)) / ref_N == pytest.approx(mm_per_N, rel=1e-9)


def test_length_ratio_of_two_arrows_equals_force_ratio(scheme, model):
    show(scheme)
    model.set_angle_deg(100)
    forces = expected_forces(model, core_dynamics(model), model.angle_index)
    drawn = arrows(scheme)
    length = {name: np.hypot(*(tip - start)) for name, (start, tip) in drawn.items()}
    assert {"A", "O4", "B", "cut"} <= set(drawn)
    assert length["A"] / length["O4"] == pytest.approx(
        np.hypot(*forces["A"]) / np.hypot(*forces["O4"]), rel=1e-9)
    assert length["B"] / length["cut"] == pytest.approx(
        np.hypot(*forces["B"]) / np.hypot(*forces["cut"]), rel=1e-9)


def test_magnitude_labels_in_kN(scheme, model):
    show(scheme)
    for degrees in (100, 270):
        model.set_angle_deg(degrees)
        forces = expected_forces(model, core_dynamics(model), model.angle_index)
        labels = scheme.force_labels()
        assert labels and set(labels) <= set(scheme.drawn_forces())
        for name, text in labels.items():
            assert text == f"{np.hypot(*forces[name]) / 1000.0:.1f} kN"


def test_arrows_move_with_the_angle(scheme, model):
    show(scheme)
    model.set_angle_index(40)
    before = arrows(scheme)
    model.set_angle_index(250)
    after = arrows(scheme)
    a = model.motion.shape.crank_pin[:, 250]
    assert np.hypot(*(after["A"][0] - a)) <= 0.5 * model.design.lever / 40.0
    assert np.hypot(*(after["A"][0] - before["A"][0])) > 0.5 * model.design.crank
    moved = [name for name in set(before) & set(after)
             if not np.allclose(np.hstack(before[name]), np.hstack(after[name]))]
    assert set(moved) >= {"O2", "A", "O4", "B"}


def test_cut_arrow_only_in_the_cutting_zone(qtbot):
    cycle = drawn_cycle(qtbot, "block")
    cut = cycle["dyn"].cut_force[0]
    assert 0 < np.count_nonzero(cut) < cut.size
    for index in range(cycle["angle_count"]):
        assert ("cut" in cycle["frames"][index]) == (cut[index] > 0.0), index


def test_rod_variant_adds_the_rod_force_on_the_ram(scheme, model):
    show(scheme)
    model.set_angle_deg(100)
    assert "C" not in scheme.drawn_forces()
    use_rod(model)
    model.set_angle_deg(100)
    drawn = arrows(scheme)
    force = expected_forces(model, core_dynamics(model), model.angle_index)["C"]
    start, tip = drawn["C"]
    np.testing.assert_allclose(unit(tip - start), unit(force), atol=1e-9)


@pytest.mark.parametrize("side", ["trailing", "leading"])
def test_rod_forces_are_drawn_beside_the_rod_not_along_it(scheme, model, side):
    model.set_spec(variant="rod", rod_ratio=0.3, rod_side=side)
    assert model.error is None
    show(scheme)
    sh = model.motion.shape
    for index in range(0, model.angle_count, 10):
        model.set_angle_index(index)
        drawn = arrows(scheme)
        b, c = sh.lever_tip[:, index], sh.ram_joint[:, index]
        for name, point, other in (("B", b, c), ("C", c, b)):
            if name in drawn:
                middle = (drawn[name][0] + drawn[name][1]) / 2.0
                assert np.dot(middle - point, other - point) < 0.0, (name, index)


# ---- follows the model ------------------------------------------------------------
def test_new_loads_redraw_the_arrows(scheme, model):
    show(scheme)
    model.set_angle_deg(100)
    old = arrows(scheme)["B"]
    old_caption = scheme.force_caption()
    model.set_masses(cut_force_N=20000.0)
    assert model.forces_error is None
    drawn = arrows(scheme)
    forces = expected_forces(model, core_dynamics(model), model.angle_index)
    assert not np.allclose(np.hstack(drawn["B"]), np.hstack(old))
    assert scheme.force_caption() != old_caption            # a new largest force, a new scale
    for name in ("A", "B", "O4", "cut"):
        start, tip = drawn[name]
        np.testing.assert_allclose(unit(tip - start), unit(forces[name]), atol=1e-9)


def test_changes_while_hidden_are_drawn_when_shown(scheme, model):
    show(scheme)
    scheme.set_forces_visible(False)
    use_rod(model)
    model.set_masses(cut_force_N=3000.0, ram_mass_kg=40.0)
    model.set_rpms([75.0, 30.0])
    model.set_angle_deg(120)
    assert scheme.drawn_forces() == {}
    show(scheme)
    assert "75 r/min" in scheme.force_caption()
    forces = expected_forces(model, core_dynamics(model), model.angle_index)
    drawn = arrows(scheme)
    assert {"O2", "A", "O4", "B", "C"} <= set(drawn)
    for name, (start, tip) in drawn.items():
        np.testing.assert_allclose(unit(tip - start), unit(forces[name]), atol=1e-9)


def test_guide_arrow_left_out_where_core_gives_no_line_of_action(scheme, model):
    """Block variant without ram weight: the guide carries a pure couple (offset NaN)."""
    model.set_masses(ram_mass_kg=0.0)
    dyn = core_dynamics(model)
    assert np.all(dyn.guide_normal[0] == 0.0) and np.all(np.isnan(dyn.guide_offset_mm[0]))
    show(scheme)
    for index in range(0, model.angle_count, 5):
        model.set_angle_index(index)
        assert "guide" not in scheme.drawn_forces()


def test_guide_arrow_drawn_on_the_guide_line(scheme, model):
    use_rod(model)
    show(scheme)
    dyn = core_dynamics(model)
    drawn_at = []
    for index in range(0, model.angle_count, 3):
        model.set_angle_index(index)
        drawn = arrows(scheme)
        if "guide" in drawn:
            start, tip = drawn["guide"]
            c = model.motion.shape.ram_joint[:, index]
            np.testing.assert_allclose(start, (c[0] + dyn.guide_offset_mm[0, index],
                                               model.design.guide), atol=1e-9)
            assert tip[0] == pytest.approx(start[0], abs=1e-9)
            assert np.sign(tip[1] - start[1]) == np.sign(dyn.guide_normal[0, index])
            drawn_at.append(index)
    assert drawn_at


def test_no_loads_no_arrows(scheme, model):
    model.set_masses(lever_mass_kg=0.0, lever_inertia_kg_m2=0.0, ram_mass_kg=0.0,
                     cut_force_N=0.0, gravity=False)
    assert model.forces_error is None
    show(scheme)
    assert scheme.drawn_forces() == {}
    assert "zero" in scheme.force_caption()


# ---- Qt housekeeping -------------------------------------------------------------
def test_items_are_created_once_with_forces(scheme, model):
    view = scheme.plot_widget().getPlotItem().getViewBox()
    before = [id(item) for item in view.addedItems]
    show(scheme)
    use_rod(model)
    model.set_angle_index(200)
    model.set_masses(cut_force_N=5000.0)
    scheme.set_forces_visible(False)
    assert [id(item) for item in view.addedItems] == before


def test_a_frame_with_forces_emits_no_python_signals(scheme, model):
    show(scheme)
    model.set_angle_index(1)
    before = sys.getrefcount(True)
    for index in range(2, 60):
        model.set_angle_index(index)
    assert sys.getrefcount(True) >= before - 58
    assert scheme.drawn_forces()


def test_language_change_keeps_force_texts(scheme):
    show(scheme)
    QApplication.sendEvent(scheme, QEvent(QEvent.LanguageChange))
    assert scheme.findChild(QCheckBox, "forcesBox").text()
    assert scheme.forces_action.text()
    assert scheme.force_caption() and scheme.force_labels()


def test_export_with_forces(scheme, tmp_path):
    show(scheme)
    png = tmp_path / "forces.png"
    scheme.export_image(str(png))
    assert png.stat().st_size > 0


def test_arrows_follow_the_chosen_speed(scheme, model):
    """The arrows were the first speed's only: now the speed chosen beside Show forces."""
    from PySide6.QtWidgets import QComboBox
    box = scheme.findChild(QComboBox, "forceSpeedBox")
    assert not box.isEnabled()                              # nothing to choose while hidden
    show(scheme)
    assert box.isEnabled() and [box.itemText(i) for i in range(box.count())] == ["40 r/min", "60 r/min"]
    model.set_angle_deg(100)
    dyn = core_dynamics(model)
    box.setCurrentIndex(1)
    assert scheme.force_speed() == 1 and "60 r/min" in scheme.force_caption()
    drawn = arrows(scheme)
    index = model.angle_index
    fast = expected_forces(model, dyn, index, speed=1)
    slow = expected_forces(model, dyn, index, speed=0)
    ratios = [np.hypot(*(tip - start)) / np.hypot(*fast[name]) for name, (start, tip) in drawn.items()]
    np.testing.assert_allclose(ratios, ratios[0], rtol=1e-9)  # lengths ∝ the 60 r/min forces
    assert any(abs(np.hypot(*fast[n]) / np.hypot(*slow[n]) - 1.0) > 1e-3 for n in drawn)  # and they differ
    for name, (start, tip) in drawn.items():
        np.testing.assert_allclose(unit(tip - start), unit(fast[name]), atol=1e-9)
    model.set_rpms([60.0, 80.0])                            # 60 r/min stays chosen where it moved
    scheme._catch_up()
    assert box.currentText() == "60 r/min" and scheme.force_speed() == 0
    assert "60 r/min" in scheme.force_caption()
    model.set_rpms([30.0])                                  # gone: back to the first
    scheme._catch_up()
    assert scheme.force_speed() == 0 and "30 r/min" in scheme.force_caption()


@pytest.mark.parametrize("variant", ["block", "rod"])
def test_fit_shows_every_arrow_over_the_whole_cycle(qtbot, variant):
    """The cutting force ahead of the tool reached past the fitted view (cut at its edge).
    The views: once the forces are shown (a fitted view widens to the arrows) and after
    ``fit()``, each with the arrows drawn in it."""
    cycle = drawn_cycle(qtbot, variant)
    passes = (cycle["frames"], cycle["refitted"])
    for fitted_again, (left, right, top, bottom), frames in zip((False, True), cycle["views"], passes):
        for index in range(0, cycle["angle_count"], 3):
            for name, (start, tip) in frames[index].items():
                for x, y in (start, tip):
                    assert left <= x <= right and top <= y <= bottom, \
                        (fitted_again, index, name, (x, y))


def test_showing_forces_keeps_a_view_the_user_zoomed(scheme, model):
    scheme._view.scaleBy((0.3, 0.3))
    zoomed = scheme._view.viewRect()
    show(scheme)
    assert scheme._view.viewRect() == zoomed
