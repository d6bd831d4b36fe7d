"""With idle 0 the cut's switch angles are the limit positions, 0 and π + θ, exactly
(issue 34, item 4): the end was a root of x(φ) = H, a double root that a root finder
places only to √ε (231.4285706111° against 180° + θ = 231.4285714286°, 1.4e-8 rad),
so the dynamics showed no cutting force at the end limit."""
import json
import math

import numpy as np
from hypothesis import assume, given, settings
from hypothesis import strategies as st

# What the commands write, in this process; test_cli.py runs the real command.
from cli_runner import shaper_run_in_process as shaper
from core.cam.laws import Program
from core.cam.timing import timing
from core.linkage.cut import cut_window
from core.linkage.designs import Designs
from core.base.errors import DesignError
from core.linkage.geometry import from_dimensions, synthesize
from core.linkage.kinematics import shape
from core.course_design.positions import positions

EXACT = 1e-12        # rad
FEED = Program(rise_deg=20.0, dwell_deg=0.0, return_deg=20.0)   # fits beside K up to 5
K18 = ["--crank", "80", "--K", "1.8", "--stroke", "400", "--guide", "sagitta"]


def theta_of(k: float) -> float:
    """θ = 180°·(K − 1)/(K + 1), rad: the definition of K, independent of the program."""
    return math.pi * (k - 1.0) / (k + 1.0)


def test_issue_case_cuts_at_the_end_limit():
    run = shaper("dynamics", *K18, "--lever-mass", "30", "--lever-inertia", "2",
                 "--ram-mass", "200", "--cut-force", "9000", "--cut-height", "100", "--idle", "0",
                 "--rpm", "75", "--angles", "231.42857142857142", "--csv", "-")
    assert run.returncode == 0, run.stderr
    header, row = run.stdout.splitlines()[:2]
    values = dict(zip(header.split(","), row.split(",")))
    assert float(values["cut_force_N"]) == 9000.0


def test_issue_case_cam_cut_end_is_the_limit():
    run = shaper("cam", *K18, "--idle", "0", "--arm", "150", "--swing", "15", "--rise", "40",
                 "--dwell", "10", "--return", "40", "--pressure", "40", "--json")
    assert run.returncode == 0, run.stderr
    doc = json.loads(run.stdout)
    assert abs(math.radians(doc["cut_end_deg"]) - (math.pi + theta_of(1.8))) <= EXACT


@st.composite
def designs(draw):
    """Synthesized designs over K in (1, 5) with every guide rule, variant and rod side."""
    crank = draw(st.floats(20.0, 300.0))
    k = draw(st.floats(1.01, 4.9))
    stroke = draw(st.floats(1.2, 4.0)) * 2 * crank * (1 + math.sin(theta_of(k) / 2))
    guide = draw(st.sampled_from(["chord", "sagitta"]))
    rod = {}
    if draw(st.booleans()):
        rod = dict(rod_ratio=draw(st.floats(0.25, 1.5)),
                   rod_side=draw(st.sampled_from(["trailing", "leading"])))
    try:
        return k, synthesize(crank, k, stroke, guide=guide, **rod)
    except DesignError:
        assume(False)


@settings(max_examples=40, deadline=None)
@given(designs())
def test_switch_angles_are_the_limit_positions(case):
    k, design = case
    end = math.pi + theta_of(k)
    on, off = (float(v[0]) for v in cut_window(Designs.of(design), 0.0))
    assert on == 0.0
    assert abs(off - end) <= EXACT
    # The positions table's cut rows and the cam's timing take the same angles.
    rows = positions(design, 1, idle_fraction=0.0)
    names = list(rows.name)
    assert abs(math.radians(rows.crank_deg[names.index("cut_end")]) - end) <= EXACT
    assert abs(math.radians(rows.crank_deg[names.index("cut_start")])) <= EXACT
    assert abs(math.radians(timing(FEED, design, 0.0).clear_from_deg) - end) <= EXACT


@settings(max_examples=30, deadline=None)
@given(st.floats(20.0, 200.0), st.floats(1.05, 1.7), st.floats(2.2, 4.0))
def test_end_is_where_the_ram_stands_still_for_many_designs_at_once(crank, over, length):
    """The vectorized path (many designs, the flywheel's grid): at the end the crank is
    square to the lever (O2A · O4A = 0), the ram's dead point, to 1e-12 rad."""
    frame = over * crank * 1.2
    design = from_dimensions(crank, frame, length * (frame + crank), guide="chord")
    many = Designs.of(design)
    phi = np.linspace(0.0, 2 * math.pi, 3601)
    on, off = cut_window(many, 0.0, (phi, shape(many.column(), phi).ram_joint[0]))
    assert on[0] == 0.0
    at = shape(design, off)
    a = at.crank_pin[:, 0]
    o2 = np.array([0.0, design.frame])
    cosine = np.dot(a - o2, a) / (crank * np.hypot(*a))
    assert abs(cosine) <= EXACT
    assert abs(at.ram1[0]) <= EXACT * design.lever

