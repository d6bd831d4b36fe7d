"""Positions of our rod-variant shaper solved by pyslvs, timed in pyslvs's own process.

Run by ``benchmarks/test_bench_peer_pyslvs.py`` with the interpreter that has pyslvs
(``$SHAPER_PYSLVS_PYTHON``; pyslvs is no dependency of this project), never imported by
it: ``python pyslvs_positions.py REQUEST.json``. The request names the link lengths
(mm), the rod's side, a ``.npy`` file of crank angles φ (rad, counted as ``core``
counts them) and how many times to solve them. It writes the positions to the request's
``out`` (``.npz``) and prints the timings as JSON on stdout.

Two ways of posing the mechanism are timed, both positions only (one speed):

- ``expr_solving``: pyslvs's mechanism-expression API (VPoints, ``t_config``,
  ``expr_solving``), the way its GUI solves a linkage. Its triangular configuration
  treats the crank pin, which slides in the lever's slot (an RP joint whose slot is on
  a moving link), as a point fixed on the lever, so its lever tip and ram are wrong; the
  test reports how far off they are.
- ``tinycadlib``: pyslvs's triangle functions, the ones an expression stack executes
  (PLA for the crank pin, PLPP for the lever tip on the line O4–A and for the ram joint
  on the guide line), called per angle. These give the exact positions.
"""
from __future__ import annotations

import json
import math
import platform
import statistics
import sys
import time

import numpy as np
import pyslvs
from pyslvs import Coord, VJoint, VPoint, expr_solving, plap, plpp, t_config


def tinycadlib_positions(request: dict, betas: list[float]) -> list[tuple[float, ...]]:
    """A, B, C for every crank direction β (rad from +x), by PLA and two PLPPs."""
    l1, l2, l3, l4 = request["crank"], request["frame"], request["lever"], request["rod"]
    o2, o4 = Coord(0.0, l2), Coord(0.0, 0.0)
    g0, g1 = Coord(0.0, request["guide"]), Coord(1.0, request["guide"])
    trailing = request["rod_side"] == "trailing"   # C on the −x side of B
    out = []
    for beta in betas:
        a = plap(o2, l1, beta)
        b = plpp(o4, l3, o4, a)
        c = plpp(b, l4, g0, g1, trailing)
        out.append((a.x, a.y, b.x, b.y, c.x, c.y))
    return out


def expression(request: dict, beta0: float) -> list[VPoint]:
    """The mechanism as pyslvs VPoints, placed at the first crank direction β0:
    O2 (ground–crank), A (crank pin in the lever's slot), O4 (ground–lever),
    B (lever–rod), C (rod end sliding on the horizontal guide)."""
    l1, l2, l3, l4 = request["crank"], request["frame"], request["lever"], request["rod"]
    guide = request["guide"]
    ax, ay = l1 * math.cos(beta0), l2 + l1 * math.sin(beta0)
    s = math.hypot(ax, ay)
    bx, by = l3 * ax / s, l3 * ay / s
    side = -1.0 if request["rod_side"] == "trailing" else 1.0
    cx = bx + side * math.sqrt(l4 * l4 - (guide - by) ** 2)
    return [
        VPoint.r_joint(["ground", "crank"], 0.0, l2),
        VPoint.slider_joint(["lever", "crank"], VJoint.RP, math.degrees(math.atan2(ay, ax)), ax, ay),
        VPoint.r_joint(["ground", "lever"], 0.0, 0.0),
        VPoint.r_joint(["lever", "rod"], bx, by),
        VPoint.slider_joint(["ground", "rod"], VJoint.RP, 0.0, cx, guide),
    ]


def expr_positions(vpoints, stack, degrees: list[float]) -> list[tuple[float, ...]]:
    out = []
    for angle in degrees:
        joints = expr_solving(stack, vpoints, {(0, 1): angle})
        (ax, ay), (bx, by), (cx, cy) = joints[1][1], joints[3], joints[4][1]
        out.append((ax, ay, bx, by, cx, cy))
    return out


def timed(function, repeats: int) -> tuple[list[float], object]:
    """Times in ms of ``repeats`` calls, and the last call's result."""
    times, result = [], None
    for _ in range(repeats):
        start = time.perf_counter()
        result = function()
        times.append((time.perf_counter() - start) * 1000.0)
    return times, result


def main(path: str) -> int:
    with open(path, encoding="utf-8") as f:
        request = json.load(f)
    phi = np.load(request["angles"])
    theta = 2.0 * math.asin(request["crank"] / request["frame"])
    # φ = 0 at the limit position that begins the cut; the crank turns clockwise, so its
    # direction from +x is β = π + θ/2 − φ (as core.linkage.kinematics.shape poses it).
    betas = [math.pi + theta / 2.0 - p for p in phi.tolist()]
    degrees = [math.degrees(b) for b in betas]
    vpoints = expression(request, betas[0])
    stack = t_config(vpoints, [(0, 1)])
    tiny_ms, tiny = timed(lambda: tinycadlib_positions(request, betas), request["repeats"])
    expr_ms, expr = timed(lambda: expr_positions(vpoints, stack, degrees),
                          request["expr_repeats"])
    np.savez(request["out"], tinycadlib=np.array(tiny), expr_solving=np.array(expr))
    print(json.dumps({
        "pyslvs": pyslvs.__version__, "numpy": np.__version__,
        "python": platform.python_version(), "angles": len(betas),
        "expr_stack": [" ".join(step) for step in stack.as_list()],
        "tinycadlib_ms": tiny_ms, "expr_solving_ms": expr_ms,
        "tinycadlib_median_ms": statistics.median(tiny_ms),
        "expr_solving_median_ms": statistics.median(expr_ms),
    }))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
