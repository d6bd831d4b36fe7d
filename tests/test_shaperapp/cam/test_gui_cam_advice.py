"""The Cam tab's refusal of a typed roller, followed as the form shows it: a checked cam's
roller bound typed into the roller field, a checked cam that takes no roller left to the
synthesis by clearing the two fields; and the same refusals in Chinese, clause by clause
(a statement and its advice after "；"), with no English left but units and symbols."""
from __future__ import annotations

import re

import pytest

from core.base.errors import DesignError
from core.cam import CamInputs, Program, design_cam
from shaperapp.widgets import i18n
from shaperapp.widgets.messages import describe

from test_gui_cam_build import tab, type_into  # noqa: F401  (the tab fixture)

SYMBOLS = {"mm", "r0", "R1", "a", "l", "r", "ρmin", "ψmax"}     # ψmax: the swing field's name


def test_a_checked_cams_roller_bound_typed_into_the_form_is_taken(qtbot, tab):
    # the form's default sheet (arm 120 mm, 15°, 60°/10°/60°) checked on r0 = 20, a = 110
    type_into(qtbot, tab, "base", "20")
    type_into(qtbot, tab, "distance", "110")
    type_into(qtbot, tab, "roller", "6")
    before = tab.cam_model.cam
    assert tab.form.marked_fields() == ["roller"]
    shown_text = tab.form.error_label.text()
    stated = re.search(r"must be at most (\S+) mm, so that the profile's smallest radius", shown_text).group(1)
    type_into(qtbot, tab, "roller", stated)
    assert tab.form.marked_fields() == []
    cam = tab.cam_model.cam
    assert cam is not before and cam.roller_mm == float(stated) and cam.base_radius_mm == 20.0


def test_a_checked_cam_taking_no_roller_is_left_to_the_synthesis_as_the_form_says(qtbot, tab):
    type_into(qtbot, tab, "roller", "5")
    type_into(qtbot, tab, "base", "15")
    type_into(qtbot, tab, "distance", "110")
    assert tab.form.marked_fields() in (["base"], ["distance"])     # the field just typed
    shown_text = tab.form.error_label.text()
    r0 = re.search(r"leave the base radius and the centre distance blank, and the synthesis gives r0 = (\S+) mm "
                   r"for this roller", shown_text).group(1)
    type_into(qtbot, tab, "base", "")
    type_into(qtbot, tab, "distance", "")
    assert tab.form.marked_fields() == [], tab.form.error_label.text()
    cam = tab.cam_model.cam
    assert f"{cam.base_radius_mm:.4g}" == r0 and cam.roller_mm == 5.0


EXAMPLE = CamInputs(arm_mm=52.5, program=Program(8.375, 44.0, 0.0, 40.0, "sine", "parabolic"), pressure_deg=36.0)
SHORT = CamInputs(arm_mm=15.0, program=Program(26.94, 97.56, 36.63, 45.13, "parabolic", "parabolic"),
                  pressure_deg=35.06)


@pytest.mark.parametrize("inputs", [
    CamInputs(arm_mm=120.0, base_mm=20.0, distance_mm=110.0, roller_mm=6.0),        # too large for the hub
    CamInputs(arm_mm=120.0, base_mm=15.0, distance_mm=110.0, roller_mm=5.0),        # none; the synthesis's r0
    CamInputs(**{**EXAMPLE.__dict__, "base_mm": 15.523, "distance_mm": 45.183}),   # ρmin < 6 mm; r0 and roller
    CamInputs(**{**EXAMPLE.__dict__, "roller_mm": 3.0}),                            # left blank, the roller is …
    CamInputs(**{**SHORT.__dict__, "roller_mm": 2.0}),                              # an arm of … gives one
    CamInputs(arm_mm=120.0, pressure_deg=5.0),                                      # an allowance of …
    CamInputs(arm_mm=120.0, program=Program(30.0, 40.0, 10.0, 40.0), pressure_deg=10.0,
              return_pressure_deg=5.0),                                             # … on both
    CamInputs(arm_mm=120.0, base_mm=229.0, distance_mm=110.0),                      # crosses: below …
    CamInputs(arm_mm=120.0, base_mm=15.0, distance_mm=110.0),                       # the hub: a base radius of …
    CamInputs(arm_mm=78.41, base_mm=34.65, distance_mm=58.83),                      # the boss: a centre distance of …
    CamInputs(arm_mm=120.0, boss_mm=90.0),                                          # the swing: a swing of …
    CamInputs(arm_mm=120.0, boss_mm=130.0),                                         # … an arm of … (no swing …)
    CamInputs(arm_mm=65.0, program=Program(13.0, 130.0, 8.0, 60.0, "sine", "cosine"), pressure_deg=27.5,
              hub_mm=100.0, boss_mm=35.0, clearance_mm=5.0),                        # the hub: a swing of …
    CamInputs(arm_mm=97.26, program=Program(58.35, 57.11, 23.17, 38.46, "cosine", "cosine"), pressure_deg=38.85,
              roller_mm=12.75),                                                     # no arm: a swing of …
    CamInputs(arm_mm=29.73, program=Program(45.68, 72.76, 0.33, 124.18, "poly345", "parabolic"),
              pressure_deg=33.11, roller_mm=15.28),                                 # … the roller blank, a swing
    CamInputs(arm_mm=30.92, program=Program(52.0, 143.36, 26.57, 86.89, "sine", "poly345"), pressure_deg=32.11,
              roller_mm=11.49, hub_mm=5.56, boss_mm=34.09),                         # … the roller blank, an arm
    CamInputs(arm_mm=128.76, program=Program(56.21, 167.2, 6.52, 104.0, "parabolic", "sine"), pressure_deg=20.83,
              hub_mm=1.76, boss_mm=150.52, clearance_mm=1.94),                      # no allowance: a swing
    CamInputs(arm_mm=219.34, program=Program(59.9, 162.01, 14.36, 41.43, "sine", "poly345"), pressure_deg=19.37,
              hub_mm=55.49, boss_mm=273.79, clearance_mm=7.9),                      # … the fields left
], ids=["hub", "no-roller", "sharp-checked", "blank", "arm", "allowance", "both-allowances", "crosses",
        "room-hub", "room-boss", "synthesized-boss", "synthesized-boss-arm", "synthesized-hub",
        "typed-no-arm-swing", "typed-no-arm-blank-swing", "typed-no-arm-blank-arm",
        "allowance-no-allowance-swing", "allowance-fields-left"])
def test_every_roller_refusal_reads_in_chinese(qapp, inputs):
    with pytest.raises(DesignError) as refused:
        design_cam(inputs)
    assert_reads_in_chinese(refused.value)


def assert_reads_in_chinese(error: DesignError) -> None:
    """The form's text of ``error`` in Chinese has no English left but units and symbols,
    and every number of core's text."""
    i18n.set_language("zh_CN")
    try:
        text = describe(error)
    finally:
        i18n.set_language("en")
    words = set(re.findall(r"[A-Za-zρψ][A-Za-z0-9ρψ]*", text))
    assert words <= SYMBOLS, (words - SYMBOLS, text)
    assert set(re.findall(r"\d+(?:\.\d+)?", error.allowed)) <= set(re.findall(r"\d+(?:\.\d+)?", text))


@pytest.mark.parametrize("language", ["en", "zh_CN"])
def test_a_checked_cam_in_its_hub_is_mended_by_the_base_radius_the_form_shows(qtbot, tab, language):
    """The form's default sheet checked on r0 = 15, a = 110 dips into the hub; the form names the
    base radius that gives a cam (1de6048: by how much it falls short, no value), and typed as
    shown it is taken."""
    i18n.set_language(language)
    try:
        type_into(qtbot, tab, "base", "15")
        type_into(qtbot, tab, "distance", "110")
        assert tab.form.marked_fields() in (["base"], ["distance"])
        shown_text = tab.form.error_label.text()
        pattern = r"a base radius of (\S+) mm gives one" if language == "en" else r"基圆半径取 (\S+) mm 时可以"
        r0 = re.search(pattern, shown_text).group(1)
        type_into(qtbot, tab, "base", r0)
        assert tab.form.marked_fields() == [], tab.form.error_label.text()
        assert tab.cam_model.cam.base_radius_mm == float(r0)
    finally:
        i18n.set_language("en")


@pytest.mark.parametrize("language", ["en", "zh_CN"])
def test_a_synthesized_cam_past_the_pivot_boss_is_mended_by_the_swing_the_form_shows(qtbot, tab, language):
    """The form's default sheet with a 90 mm pivot boss: no cam within the allowances clears
    it; the form marks the swing and names the swing that gives a cam (21a3424: by how much
    the smallest cam reaches past, no value), and typed as shown it is taken."""
    i18n.set_language(language)
    try:
        type_into(qtbot, tab, "boss", "90")
        assert tab.form.marked_fields() in (["swing"], ["boss"])       # core's field, or the one just typed
        shown_text = tab.form.error_label.text()
        pattern = r"a swing of (\S+)° gives one" if language == "en" else r"最大摆角取 (\S+)° 时可以"
        swing = re.search(pattern, shown_text).group(1)
        type_into(qtbot, tab, "swing", swing)
        assert tab.form.marked_fields() == [], tab.form.error_label.text()
        assert tab.cam_model.cam.program.swing_deg == float(swing) and tab.cam_model.cam.inputs.boss_mm == 90.0
    finally:
        i18n.set_language("en")
