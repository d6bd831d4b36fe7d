"""An automatic roller is one that can be made: at least 3 mm (a Ø6 mm needle roller) and
within the usual margin of the pitch curve's sharpest convex point, or the cam is refused
with advice that works (30 November: a synthesized cam raised to clear its hub kept a
0.023 mm roller, shown as the design everywhere).

The curvature is measured apart from core.cam: cam_oracle's (its own laws and chain rule,
a 200 001-point grid polished by scipy) and central differences of the roller centre's
path carried onto the cam (cam_reference); the minimality of a raised cam by a scan of every
cam 1 % smaller (both roots of the centre distance, both arrangements), its pressure angles
numeric, its curvature cam_oracle's.
"""
from __future__ import annotations

import json
import math
import re

import numpy as np
import pytest
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

from cli_runner import shaper_in_process
from core.base.errors import DesignError
from core.cam import CamInputs, Program, design_cam
from core.cam.laws import LAWS

import cam_oracle as oracle
import cam_reference as ref
from sweeps import examples
from test_cam_build import _assert_buildable

SMALLEST = 3.0          # mm, docs/cli.md: the smallest automatic roller
EXAMPLE = CamInputs(arm_mm=52.5, program=Program(8.375, 44.0, 0.0, 40.0, "sine", "parabolic"),
                    pressure_deg=36.0)
EXAMPLE_ARGS = ("cam", "--arm", "52.5", "--swing", "8.375", "--pressure", "36", "--rise", "44",
                "--dwell", "0", "--return", "40", "--law", "sine", "--return-law", "parabolic")
NONE = dict(hub_mm=0.0, boss_mm=0.0, clearance_mm=0.0)


def _sheet(p: Program) -> dict:
    return dict(swing=p.swing_deg, rise=p.rise_deg, dwell=p.dwell_deg, back=p.return_deg,
                laws=(p.rise_law, p.return_law))


def _oracle_rho(cam) -> float:
    f = cam.follower
    return oracle.extremes(dict(a=f.distance_mm, l=f.arm_mm, psi0=math.radians(f.initial_deg), k=f.side),
                           _sheet(cam.program))["rho_min_mm"]


def _differenced_rho(cam, step_deg: float = 0.002) -> float:
    """1 / the largest convex curvature of the roller centre's path on the cam, by central
    differences of its points; convex is the sense of the inner dwell's arc about the cam
    centre."""
    f = cam.follower
    delta = np.radians(np.arange(0.0, 360.0, step_deg))
    h = math.radians(step_deg)
    p = ref.pitch_points(f.distance_mm, f.arm_mm, math.radians(f.initial_deg), f.side,
                         lambda d: cam.program.motion(np.mod(d, 2 * math.pi)).psi, delta)
    d1 = (np.roll(p, -1, axis=1) - np.roll(p, 1, axis=1)) / (2 * h)
    d2 = (np.roll(p, -1, axis=1) - 2 * p + np.roll(p, 1, axis=1)) / h ** 2
    kappa = (d1[0] * d2[1] - d1[1] * d2[0]) / np.hypot(*d1) ** 3
    kappa *= np.sign(kappa[-1])                 # 359.998°: on the inner dwell's arc, convex
    return 1.0 / kappa.max()


def _assert_roller_can_be_made(cam, rho: float) -> None:
    assert cam.roller_mm >= SMALLEST
    assert cam.roller_mm <= 0.8 * rho * (1 + 1e-9) and rho - cam.roller_mm >= 3.0 - 1e-9


def test_the_example_takes_a_roller_of_3_mm_on_a_raised_cam():
    cam = design_cam(EXAMPLE)
    rho = _oracle_rho(cam)
    assert _differenced_rho(cam) == pytest.approx(rho, rel=1e-4)
    _assert_roller_can_be_made(cam, rho)
    _assert_buildable(cam)
    assert cam.base_raised_from_mm is not None and cam.base_radius_mm > cam.base_raised_from_mm
    status, out, _ = shaper_in_process(*EXAMPLE_ARGS, "--json")
    doc = json.loads(out)
    assert status == 0 and doc["roller_mm"] == cam.roller_mm and doc["base_radius_mm"] == cam.base_radius_mm


def _largest_convex_curvature(a, l, psi0, k, program: Program, u: np.ndarray) -> float:
    sheet, cam = _sheet(program), dict(a=a, l=l, psi0=psi0, k=k)
    return max(oracle.convex_curvature(cam, sheet, phase, u * (hi - lo) + lo, first).max()
               for phase in (0, 1) for lo, hi, first in oracle.pieces(sheet["laws"][phase]))


def test_with_no_hub_the_cam_is_raised_just_enough_for_the_roller():
    """With no hub or boss, the pitch curve's sharpness alone raises the cam: every cam
    within the allowances with a base radius 1 % smaller is too sharp for a 3 mm roller."""
    inputs = CamInputs(**{**EXAMPLE.__dict__, **NONE})
    cam = design_cam(inputs)
    rho = _oracle_rho(cam)
    _assert_roller_can_be_made(cam, rho)
    assert cam.largest_roller_mm < SMALLEST * 1.01          # no larger than it needs to be
    p, l = inputs.program, inputs.arm_mm
    psi_of = lambda d: p.motion(d).psi  # noqa: E731
    rise = np.radians(np.linspace(0.0, p.rise_deg, 721))
    back = np.radians(p.rise_deg + p.dwell_deg + np.linspace(0.0, p.return_deg, 721))
    u = np.linspace(0.0, 1.0, 2001)
    smaller = 0.99 * cam.base_radius_mm
    allowed = (math.radians(inputs.pressure_deg), math.radians(inputs.return_pressure_deg))
    within = 0
    for k in (-1, 1):
        for a, psi0, up, down in ref.worst_pressure(smaller, l, k, psi_of, rise, back,
                                                    np.radians(np.linspace(0.05, 179.95 - p.swing_deg, 900))):
            if up > allowed[0] or down > allowed[1]:
                continue
            within += 1
            kappa = max(_largest_convex_curvature(a, l, psi0, k, p, u), 1.0 / smaller)
            assert min(0.8 / kappa, 1.0 / kappa - 3.0) < SMALLEST, (a, math.degrees(psi0), k)
    assert within > 10          # the scan met the allowances' region, not nothing


@pytest.mark.slow
@settings(max_examples=examples(40), deadline=None, suppress_health_check=[HealthCheck.too_slow])
@example(rise_law="sine", return_law="parabolic", swing=8.375, rise=44.0, dwell=0.0, back=40.0,
         arm=52.5, allowed=36.0, room=1.0)
@given(rise_law=st.sampled_from(LAWS), return_law=st.sampled_from(LAWS),
       swing=st.floats(5.0, 30.0), rise=st.floats(40.0, 150.0), dwell=st.floats(0.0, 40.0),
       back=st.floats(40.0, 150.0), arm=st.floats(20.0, 400.0), allowed=st.floats(30.0, 50.0),
       room=st.sampled_from([0.0, 1.0]))
def test_any_automatic_roller_can_be_made_or_the_advice_makes_one(rise_law, return_law, swing, rise, dwell,
                                                                  back, arm, allowed, room):
    """(80 draws passed, two ``thorough`` runs of seeds 1 and 2, arms 20-400 mm, the default
    room and none.)"""
    inputs = CamInputs(arm_mm=arm, program=Program(swing, rise, dwell, back, rise_law, return_law),
                       pressure_deg=allowed, **({} if room else NONE))
    try:
        cam = design_cam(inputs)
    except DesignError as exc:
        assert exc.parameter in ("arm", "swing"), exc
        if exc.parameter == "swing":
            return
        longer = float(re.search(r"an arm of (\S+) mm gives one", exc.allowed).group(1))
        assert longer > arm
        cam = design_cam(CamInputs(**{**inputs.__dict__, "arm_mm": longer}))
    _assert_roller_can_be_made(cam, _oracle_rho(cam))
    _assert_buildable(cam)


def _one_line_error(*args) -> str:
    status, out, err = shaper_in_process(*args)
    assert status == 2 and out == "" and len(err.strip().splitlines()) == 1
    return err


# no cam within the allowances on a 21.25 mm arm takes a 3 mm roller and clears the default
# hub and boss
SHORT_ARM = ("cam", "--swing", "26.94", "--pressure", "35.06", "--rise", "97.56", "--dwell", "36.63",
             "--return", "45.13", "--law", "parabolic", "--return-law", "parabolic")


def test_a_cam_no_raise_makes_names_the_arm_that_does_and_that_arm_does():
    err = _one_line_error(*SHORT_ARM, "--arm", "21.25")
    assert "error: --arm: no cam within the allowances takes a roller of 3 mm or more" in err
    longer = re.search(r"an arm of (\S+) mm gives one", err).group(1)
    status, out, _ = shaper_in_process(*SHORT_ARM, "--arm", longer, "--json")
    doc = json.loads(out)
    assert status == 0 and doc["roller_mm"] >= SMALLEST
    assert doc["profile_base_radius_mm"] >= doc["hub_mm"] + doc["clearance_mm"] - 1e-9
    # by how much: 0.1 mm shorter (the step it is named to) gives none
    err = _one_line_error(*SHORT_ARM, "--arm", f"{float(longer) - 0.1:.1f}")
    assert f"an arm of {longer} mm gives one" in err


def test_a_checked_cam_too_sharp_for_3_mm_is_refused_and_the_synthesis_makes_one():
    err = _one_line_error(*EXAMPLE_ARGS, "--base", "15.523", "--distance", "45.183")
    assert "error: --base: the pitch curve's smallest convex radius ρmin = 3.293 mm takes no roller" in err
    assert "leave out the base radius and the centre distance" in err
    status, out, _ = shaper_in_process(*EXAMPLE_ARGS, "--json")
    assert status == 0 and json.loads(out)["roller_mm"] >= SMALLEST


@pytest.mark.parametrize("roller", ["3", "20"])
def test_a_typed_roller_the_smallest_cam_cannot_take_says_what_a_blank_one_gives(roller):
    err = _one_line_error(*EXAMPLE_ARGS, "--roller", roller)
    said = re.search(r"error: --roller: .*; left blank, the roller is (\S+) mm on a base radius raised "
                     r"to (\S+) mm \(got", err)
    status, out, _ = shaper_in_process(*EXAMPLE_ARGS, "--json")
    doc = json.loads(out)
    assert status == 0 and said
    assert f"{doc['roller_mm']:.4g}" == said.group(1) and f"{doc['base_radius_mm']:.4g}" == said.group(2)


def test_a_typed_roller_the_cam_takes_is_kept_however_small():
    # the user's choice: the usual margin and the room are checked, not a least size
    cam = design_cam(CamInputs(**{**EXAMPLE.__dict__, "roller_mm": 0.02}))
    assert cam.roller_mm == 0.02 and cam.roller_mm <= cam.largest_roller_mm
    _assert_buildable(cam)


@pytest.mark.parametrize("program, arm", [
    (Program(15.0, 60.0, 10.0, 60.0), 120.0),                                # the form's default
    (Program(15.0, 60.0, 10.0, 60.0, "cosine", "parabolic"), 120.0),         # the course data sheet
    (Program(15.0, 75.0, 10.0, 75.0), 125.0),                                # the task book's (shaper class)
])
def test_cams_whose_largest_roller_fits_keep_it(program, arm):
    cam = design_cam(CamInputs(arm_mm=arm, program=program, pressure_deg=40.0))
    assert cam.base_raised_from_mm is None and cam.roller_mm == cam.largest_roller_mm > SMALLEST


@settings(max_examples=6, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(rise_law=st.sampled_from(LAWS), return_law=st.sampled_from(LAWS),
       swing=st.floats(5.0, 30.0), rise=st.floats(40.0, 150.0), dwell=st.floats(0.0, 40.0),
       back=st.floats(40.0, 150.0), arm=st.floats(20.0, 400.0), allowed=st.floats(30.0, 50.0),
       scale=st.floats(1.0, 2.0))
def test_the_raise_screen_keeps_every_centre_the_polished_radius_keeps(rise_law, return_law, swing, rise,
                                                                       dwell, back, arm, allowed, scale):
    """The raise screens centres by ρmin on a grid (no polish), asking SCREEN_MARGIN more:
    a grid's largest curvature is at most the true one, so its ρmin is never below the
    polished one, and the margin must cover how far above it it can be."""
    from core.cam.cam import SCREEN_MARGIN
    from core.cam.build import CURVATURE_SAMPLES
    from core.cam.extremes import min_convex_radius, sampled_min_convex_radius
    from core.cam.follower import Follower
    from core.cam.synthesis import synthesize
    inputs = CamInputs(arm_mm=arm, program=Program(swing, rise, dwell, back, rise_law, return_law),
                       pressure_deg=allowed)
    f = synthesize(arm, inputs.program, inputs.allowance)
    g = Follower(arm, f.distance_mm * scale, f.initial_deg, f.side)
    polished = min_convex_radius(g, inputs.program)
    screened = sampled_min_convex_radius(Follower(arm, np.array([g.distance_mm]), np.array([g.initial_deg]), g.side),
                                         inputs.program, np.array([g.base_radius_mm]), CURVATURE_SAMPLES)[0]
    assert polished * (1 - 1e-12) <= screened <= polished * (1 + SCREEN_MARGIN)
