"""Optimize proposes only a design better than the one given by more than the objective's
tolerance (issue 34, item 6), and says why when the objective does not depend on the
varied parameters. With K and H fixed, L1 only scales the crank and the frame together
(L1/L2 = sin θ/2): the lever, and the ram with it, move the same for every L1, so max |a|
does not depend on it. For the block variant the ram follows the lever tip's x, so the
guide height changes neither |a| nor the torque (the cut's virtual work is P·dx/dφ)."""
import json
import math

import numpy as np
import pytest

# What `shaper optimize` writes, in this process; test_cli_sweep.py runs the real command.
from cli_runner import shaper_run_in_process as shaper
from core.linkage.geometry import synthesize
from core.linkage.kinematics import solve
from core.space.optimize import GAIN_TOLERANCE, improves, insensitive

BASE = ["optimize", "--crank", "50", "--K", "1.4", "--stroke", "300", "--objective", "accel",
        "--rpm", "200"]


def largest_accel(crank: float, k: float) -> float:
    """max |a| on a fine grid of the closed-form kinematics (not the optimizer's peaks)."""
    motion = solve(synthesize(crank, k, 300.0), np.radians(np.arange(0.0, 360.0, 0.01)), [200.0])
    return float(np.max(np.abs(motion.ram_a)))


def test_l1_alone_gives_no_proposal_and_says_why():
    assert largest_accel(40.0, 1.4) == pytest.approx(largest_accel(60.0, 1.4), rel=1e-9)
    run = shaper(*BASE, "--vary", "crank=40:60", "--json")
    assert run.returncode == 0, run.stderr
    doc = json.loads(run.stdout)
    assert doc["improves"] is False
    assert doc["no_gain"].startswith("no better design within these bounds")
    assert "accel does not depend on crank" in doc["no_gain"]


def test_a_start_that_is_already_best_gives_no_proposal():
    """|a| grows with K (a quicker return), so from K = 1.3 in 1.3…1.5 nothing is better."""
    assert largest_accel(50.0, 1.3) < largest_accel(50.0, 1.31)
    run = shaper(*[a if a != "1.4" else "1.3" for a in BASE], "--vary", "K=1.3:1.5")
    assert run.returncode == 0, run.stderr
    rows = dict(line.split(None, 1) for line in run.stdout.splitlines())
    assert "optimum" not in rows and "frame" not in rows   # no proposal, no design rows
    assert rows["K"].startswith("best at the lower bound: a better design may lie beyond it")
    assert rows["result"].startswith("no better design within these bounds: the best found")
    assert "does not depend" not in rows["result"]
    assert "is not lower than the design's own" in rows["result"]


def test_a_real_gain_is_still_proposed():
    run = shaper(*[a if a != "1.4" else "1.45" for a in BASE], "--vary", "K=1.3:1.5", "--json")
    assert run.returncode == 0, run.stderr
    doc = json.loads(run.stdout)
    assert doc["improves"] is True and doc["no_gain"] is None
    assert doc["objective_value"] == pytest.approx(largest_accel(50.0, doc["vary"]["K"]), rel=1e-6)
    assert doc["objective_value"] < largest_accel(50.0, 1.45) * (1 - GAIN_TOLERANCE)


def test_guide_of_a_block_design_is_found_not_to_matter():
    run = shaper("optimize", "--dims", "100,300,600", "--guide", "580", "--objective", "accel",
                 "--vary", "guide=450:590", "--rpm", "60", "--json")
    assert run.returncode == 0, run.stderr
    assert "accel does not depend on guide" in json.loads(run.stdout)["no_gain"]


def test_improves_needs_more_than_the_tolerance():
    assert not improves(100.0 * (1 - 0.5 * GAIN_TOLERANCE), 100.0)
    assert improves(100.0 * (1 - 2 * GAIN_TOLERANCE), 100.0)
    assert not improves(100.0, 100.0) and improves(5.0, None) and not improves(math.inf, None)


def test_insensitive_reads_the_dense_grid_per_axis():
    x, y = np.meshgrid(np.linspace(1, 2, 5), np.linspace(3, 4, 7), indexing="ij")
    flat_in_x = (y ** 2).ravel()
    flat_in_x[3] = np.inf                                  # an invalid design
    assert insensitive(flat_in_x, (5, 7), ("x", "y")) == ("x",)
    assert insensitive((x + y).ravel(), (5, 7), ("x", "y")) == ()
    assert insensitive((x * 0 + 2).ravel(), (5, 7), ("x", "y")) == ("x", "y")
    assert insensitive(np.full(35, np.inf), (5, 7), ("x", "y")) == ()
