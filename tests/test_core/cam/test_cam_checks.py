"""Issue 23, item 4: every figure of a cam against checks that share nothing with its
derivation (see cam_reference): a contact search on the turned profile, a numerical normal,
the roller's envelope, and the base radius 2 % smaller."""
from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

from core.cam import CamInputs, Program, design_cam
from core.cam.follower import pitch, pressure_angle, profile
from core.cam.laws import LAWS

import cam_reference as ref


def _parts(cam):
    f = cam.follower
    return f.distance_mm, f.arm_mm, math.radians(f.initial_deg), f.side


def _psi_of(program):
    return lambda d: program.motion(d).psi


def _contact_errors(cam, deltas):
    a, l, psi0, k = _parts(cam)
    prog = cam.program

    def profile_of(u):
        return profile(pitch(cam.follower, prog, u), cam.roller_mm)
    law = prog.motion(deltas).psi
    found = np.array([ref.contact_angle(profile_of, a, l, psi0, k, cam.roller_mm, d, g)
                      for d, g in zip(deltas, law)])
    return np.abs(found - law)


SHEET = CamInputs(arm_mm=120.0, program=Program(swing_deg=15.0, rise_deg=60.0, dwell_deg=10.0,
                                                return_deg=60.0, rise_law="cosine",
                                                return_law="parabolic"),
                  pressure_deg=40.0, return_pressure_deg=70.0)


@pytest.fixture(scope="module")
def sheet_cam():
    return design_cam(SHEET)


def test_contact_search_gives_the_law_at_every_angle(sheet_cam):
    deltas = np.radians(np.arange(0.0, 360.0, 5.0) + 0.37)
    assert _contact_errors(sheet_cam, deltas).max() < 1e-6


def test_pressure_angle_equals_the_numerical_normal(sheet_cam):
    a, l, psi0, k = _parts(sheet_cam)
    deltas = np.radians(np.linspace(0.1, 359.9, 997))
    mine = ref.numeric_pressure(a, l, psi0, k, _psi_of(sheet_cam.program), deltas)
    theirs = pressure_angle(sheet_cam.follower, pitch(sheet_cam.follower, sheet_cam.program, deltas))
    assert np.abs(mine - theirs).max() < 1e-6


def test_pitch_curve_is_the_inverted_roller_centre(sheet_cam):
    a, l, psi0, k = _parts(sheet_cam)
    deltas = np.radians(np.linspace(0.0, 360.0, 721))
    got = pitch(sheet_cam.follower, sheet_cam.program, deltas).point
    want = ref.pitch_points(a, l, psi0, k, _psi_of(sheet_cam.program), deltas)
    assert np.abs(got - want).max() < 1e-9 * l


def test_derivatives_of_the_pitch_curve_are_exact(sheet_cam):
    deltas = np.radians(np.linspace(0.3, 359.7, 400))
    h = 1e-5
    f, prog = sheet_cam.follower, sheet_cam.program
    p = pitch(f, prog, deltas)
    d1 = (pitch(f, prog, deltas + h).point - pitch(f, prog, deltas - h).point) / (2 * h)
    d2 = (pitch(f, prog, deltas + h).d1 - pitch(f, prog, deltas - h).d1) / (2 * h)
    assert np.abs(p.d1 - d1).max() < 1e-5
    # the acceleration jumps at the phases' ends and the parabolic return's middle: skip those
    far = np.all(np.abs(deltas[:, None] - np.radians([0, 60, 70, 100, 130])[None]) > 3 * h, axis=1)
    assert far.sum() > 390
    assert np.abs(p.d2 - d2)[:, far].max() < 1e-4


def test_profile_is_the_roller_envelope(sheet_cam):
    """Each profile point is the roller radius from its pitch point along the numerical
    normal, and no pitch point is nearer than the roller radius (no undercut)."""
    a, l, psi0, k = _parts(sheet_cam)
    psi_of = _psi_of(sheet_cam.program)
    r = sheet_cam.roller_mm
    deltas = np.radians(np.linspace(0.05, 359.95, 1441))
    prof = profile(pitch(sheet_cam.follower, sheet_cam.program, deltas), r)
    centre = ref.pitch_points(a, l, psi0, k, psi_of, deltas)
    h = 1e-5
    tangent = (ref.pitch_points(a, l, psi0, k, psi_of, deltas + h)
               - ref.pitch_points(a, l, psi0, k, psi_of, deltas - h))
    offset = prof - centre
    assert np.abs(np.hypot(*offset) - r).max() < 1e-9 * l
    assert np.abs(np.sum(offset * tangent, axis=0) / np.hypot(*tangent)).max() < 1e-6 * r
    # the profile lies inside the pitch curve (towards the cam centre)
    assert np.all(np.hypot(*prof) < np.hypot(*centre))
    dense = ref.pitch_points(a, l, psi0, k, psi_of, np.radians(np.linspace(0, 360, 20001)))
    nearest = np.min(np.hypot(prof[0][:, None] - dense[0][None], prof[1][:, None] - dense[1][None]), axis=1)
    assert nearest.min() > r * (1 - 1e-4)


def test_synthesized_cam_meets_the_allowance_and_reaches_it(sheet_cam):
    a, l, psi0, k = _parts(sheet_cam)
    prog = sheet_cam.program
    rise = np.radians(np.linspace(0.0, prog.rise_deg, 3001))
    back = np.radians(prog.rise_deg + prog.dwell_deg + np.linspace(0.0, prog.return_deg, 3001))
    up = math.degrees(ref.numeric_pressure(a, l, psi0, k, _psi_of(prog), rise).max())
    down = math.degrees(ref.numeric_pressure(a, l, psi0, k, _psi_of(prog), back).max())
    assert up <= SHEET.pressure_deg + 1e-3 and down <= SHEET.return_pressure_deg + 1e-3
    # the smallest cam is on the edge of what is allowed: one phase is at its allowance
    assert max(up - SHEET.pressure_deg, down - SHEET.return_pressure_deg) > -1e-3
    assert sheet_cam.max_pressure_rise_deg == pytest.approx(up, abs=1e-3)
    assert sheet_cam.max_pressure_return_deg == pytest.approx(down, abs=1e-3)


@pytest.mark.parametrize("inputs", [
    SHEET,
    CamInputs(arm_mm=80.0, program=Program(swing_deg=25.0, rise_deg=100.0, dwell_deg=0.0,
                                           return_deg=80.0, rise_law="poly345", return_law="sine"),
              pressure_deg=35.0, return_pressure_deg=60.0, hub_mm=0.0, boss_mm=0.0, clearance_mm=0.0),
])  # (the second, with the default hub and boss, is raised to clear them: see test_cam_build)
def test_base_radius_two_percent_smaller_breaks_the_allowance(inputs):
    cam = design_cam(inputs)
    prog = inputs.program
    l = inputs.arm_mm
    rise = np.radians(np.linspace(0.0, prog.rise_deg, 721))
    back = np.radians(prog.rise_deg + prog.dwell_deg + np.linspace(0.0, prog.return_deg, 721))
    psi0s = np.radians(np.linspace(0.05, 179.95 - prog.swing_deg, 1200))
    for k in (-1, 1):
        for a, psi0, up, down in ref.worst_pressure(0.98 * cam.base_radius_mm, l, k, _psi_of(prog),
                                                    rise, back, psi0s):
            assert (up > math.radians(inputs.pressure_deg)
                    or down > math.radians(inputs.return_pressure_deg)), (a, math.degrees(psi0), k)
    # and the synthesized radius itself is feasible by the same scan's measure
    a, l_, psi0, k = _parts(cam)
    up = ref.numeric_pressure(a, l, psi0, k, _psi_of(prog), rise).max()
    assert math.degrees(up) <= inputs.pressure_deg + 1e-3


@settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.too_slow])
# found by a suite run (30 November): the raised cam's automatic roller was 0.023 mm, and the
# contact search's first bracket, 1e-3 rad of a 52.5 mm arm, moved the centre through the
# whole roller and out of the profile's other side (the cam is now raised for a 3 mm roller)
@example(rise_law="sine", return_law="parabolic", swing=8.375, rise=44.0, dwell=0.0, back=40.0,
         arm=52.5, allowed=36.0)
@given(rise_law=st.sampled_from(LAWS), return_law=st.sampled_from(LAWS),
       swing=st.floats(5.0, 30.0), rise=st.floats(40.0, 150.0), dwell=st.floats(0.0, 40.0),
       back=st.floats(40.0, 150.0), arm=st.floats(50.0, 400.0), allowed=st.floats(30.0, 50.0))
def test_any_law_angles_and_arm_pass_the_contact_search(rise_law, return_law, swing, rise, dwell,
                                                        back, arm, allowed):
    inputs = CamInputs(arm_mm=arm, program=Program(swing, rise, dwell, back, rise_law, return_law),
                       pressure_deg=allowed, return_pressure_deg=70.0)
    try:
        cam = design_cam(inputs)
    except Exception as exc:       # a cam too sharp for a 3 mm roller however raised is refused, by name
        assert getattr(exc, "parameter", None) in ("swing", "arm")
        return
    # every angle at least 0.005° from a phase's edge: the numerical normal's central
    # difference (1e-5 rad) must not straddle the jump in curvature there
    on_dwell = rise + dwell / 2 if dwell >= 0.01 else rise + dwell + 0.2
    deltas = np.radians(np.array([0.2, 0.3 * rise, 0.7 * rise, on_dwell,
                                  rise + dwell + 0.4 * back, rise + dwell + 0.9 * back, 355.0]))
    assert _contact_errors(cam, deltas).max() < 1e-6
    a, l, psi0, k = _parts(cam)
    mine = ref.numeric_pressure(a, l, psi0, k, _psi_of(cam.program), deltas)
    theirs = pressure_angle(cam.follower, pitch(cam.follower, cam.program, deltas))
    assert np.abs(mine - theirs).max() < 1e-6
    assert cam.max_pressure_rise_deg <= allowed + 1e-6
