"""The motion laws (against finite differences and the textbook's peak coefficients) and the
feed's timing against the linkage's cut (against core.linkage.cut's own rule)."""
from __future__ import annotations

import math

import numpy as np
import pytest

from core.cam import CamInputs, Program, design_cam
from core.cam.laws import LAWS, law
from core.cam.timing import timing
from core.linkage.cut import cutting
from core.base.errors import DesignError
from core.linkage.spec import Spec

# The textbook's coefficients: max ds/du and max |d²s/du²| of each normalized rise.
PEAKS = {"parabolic": (2.0, 4.0), "cosine": (math.pi / 2, math.pi ** 2 / 2),
         "sine": (2.0, 2 * math.pi), "poly345": (1.875, 10 / math.sqrt(3))}


@pytest.mark.parametrize("name", LAWS)
def test_law_ends_derivatives_and_peaks(name):
    u = np.linspace(0.0, 1.0, 200001)
    s, s1, s2 = law(name, u)
    assert s[0] == pytest.approx(0.0, abs=1e-15) and s[-1] == pytest.approx(1.0, abs=1e-15)
    assert s1[0] == pytest.approx(0.0, abs=1e-15) and s1[-1] == pytest.approx(0.0, abs=1e-12)
    h = u[1] - u[0]
    inner = np.abs(u[1:-1] - 0.5) > 2 * h          # the parabolic law's acceleration jumps at ½
    assert np.abs(((s[2:] - s[:-2]) / (2 * h) - s1[1:-1])[inner]).max() < 1e-8
    assert np.abs(((s1[2:] - s1[:-2]) / (2 * h) - s2[1:-1])[inner]).max() < 1e-6
    assert s1.max() == pytest.approx(PEAKS[name][0], rel=1e-8)
    assert np.abs(s2).max() == pytest.approx(PEAKS[name][1], rel=1e-6)


def test_program_motion_over_the_cycle():
    prog = Program(swing_deg=20.0, rise_deg=90.0, dwell_deg=30.0, return_deg=120.0,
                   rise_law="poly345", return_law="cosine")
    d = np.radians(np.linspace(0.0, 360.0, 36001))
    m = prog.motion(d)
    assert m.psi.max() == pytest.approx(math.radians(20.0), rel=1e-12)
    assert np.all(m.psi[(d > math.radians(240.0))] == 0.0)
    out = (d >= math.radians(90.0)) & (d < math.radians(120.0))
    assert np.allclose(m.psi[out], math.radians(20.0))
    h = d[1] - d[0]
    fd = (m.psi[2:] - m.psi[:-2]) / (2 * h)
    # away from the phases' ends, where the acceleration may jump
    ends = np.radians([0.0, 90.0, 120.0, 240.0, 360.0])
    inner = np.all(np.abs(d[1:-1, None] - ends[None]) > 2 * h, axis=1)
    assert np.abs(fd - m.psi1[1:-1])[inner].max() < 1e-7
    # the cosine return: its peak speed is π/2 · ψmax / Φ'
    assert -m.psi1.min() == pytest.approx(math.pi / 2 * math.radians(20.0) / math.radians(120.0), rel=1e-6)


@pytest.mark.parametrize("kwargs, name", [
    (dict(rise_deg=200.0, dwell_deg=100.0, return_deg=100.0), "dwell"),
    (dict(rise_deg=0.0), "rise"),
    (dict(return_deg=-5.0), "return"),
    (dict(swing_deg=95.0), "swing"),
    (dict(rise_law="linear"), "rise_law"),
])
def test_program_refuses_bad_angles_by_name(kwargs, name):
    with pytest.raises(DesignError) as info:
        Program(**kwargs)
    assert info.value.parameter == name


@pytest.mark.parametrize("kwargs, name", [
    (dict(pressure_deg=90.0), "pressure"), (dict(return_pressure_deg=0.0), "return_pressure"),
    (dict(arm_mm=-1.0), "arm"), (dict(base_mm=50.0), "distance"),
])
def test_inputs_refuse_bad_values_by_name(kwargs, name):
    with pytest.raises(DesignError) as info:
        CamInputs(**kwargs)
    assert info.value.parameter == name


def test_roller_that_undercuts_is_refused():
    cam = design_cam(CamInputs())
    with pytest.raises(DesignError) as info:
        design_cam(CamInputs(roller_mm=cam.min_curvature_radius_mm * 1.01))
    assert info.value.parameter == "roller" and "undercuts" in info.value.allowed


def test_feed_lies_outside_the_cut():
    design = Spec().design()
    prog = Program(swing_deg=15.0, rise_deg=50.0, dwell_deg=10.0, return_deg=50.0)
    when = timing(prog, design, 0.05)
    phi = np.radians(np.linspace(0.0, 360.0, 72001))
    m = prog.motion(when.cam_angle(phi))
    moving_or_out = (m.psi > 0) | (m.psi1 != 0)
    assert moving_or_out.any()
    assert not np.any(moving_or_out & cutting(design, phi, 0.05))
    # centred: as much clearance before the rise as after the return
    before = (when.phase_deg - when.clear_from_deg) % 360.0
    after = when.clear_span_deg - before - prog.feed_deg
    assert before == pytest.approx(after, abs=1e-9) and before > 0


def test_feed_too_long_or_phase_in_the_cut_is_refused():
    design = Spec().design()
    with pytest.raises(DesignError) as info:
        timing(Program(rise_deg=120.0, dwell_deg=20.0, return_deg=120.0), design, 0.05)
    assert info.value.parameter == "rise"
    prog = Program(rise_deg=40.0, dwell_deg=0.0, return_deg=40.0)
    with pytest.raises(DesignError) as info:
        timing(prog, design, 0.05, phase_deg=90.0)       # the middle of the working stroke
    assert info.value.parameter == "phase"
    when = timing(prog, design, 0.05)
    assert timing(prog, design, 0.05, phase_deg=when.phase_deg).phase_deg == pytest.approx(when.phase_deg)
