"""CPU time of designing cams with every refusal's advice, and a hash of every outcome:
``python tools/cam_search_cpu.py [RANDOM]``.

Why: an advice's search (``core.cam.advice``) designs hundreds of whole cams, which is
where the cam tests and the Cam tab's waits spend their time. This designs the tests'
refused cams (the pivot boss, the hub, a typed roller, an allowance, a short arm), the
form's default and RANDOM (default 20) random programs and rooms, each with
``design_cam`` as the CLI does, and prints the CPU time (this process, after the imports)
and a hash of each outcome's ``repr`` (the Cam, or the refusal's field, value and text).
Run it with ``PYTHONPATH`` on another tree to compare: the same hash means the same
numbers and texts. Only a developer's tool.
"""
from __future__ import annotations

import hashlib
import sys
import time

import numpy as np

from core.base.errors import DesignError
from core.cam import CamInputs, Program, design_cam

SHEET = Program(15.0, 60.0, 10.0, 60.0)
FORM = dict(arm_mm=120.0, pressure_deg=40.0, return_pressure_deg=70.0)
LAWS = ("sine", "cosine", "parabolic", "poly345")
CASES = [
    CamInputs(program=SHEET, boss_mm=90.0, **FORM),
    CamInputs(program=Program(60.0, 100.0, 10.0, 60.0), boss_mm=100.0, **FORM),
    CamInputs(program=SHEET, boss_mm=130.0, **FORM),
    CamInputs(arm_mm=65.0, program=Program(13.0, 130.0, 8.0, 60.0, "sine", "cosine"), pressure_deg=27.5,
              hub_mm=100.0, boss_mm=35.0, clearance_mm=5.0),
    CamInputs(arm_mm=120.0, program=SHEET, roller_mm=5.0, boss_mm=90.0),
    CamInputs(arm_mm=120.0, program=SHEET, pressure_deg=5.0),
    CamInputs(arm_mm=15.0, program=Program(26.94, 97.56, 36.63, 45.13, "parabolic", "parabolic"), pressure_deg=35.06),
    CamInputs(arm_mm=52.5, program=Program(8.375, 44.0, 0.0, 40.0, "sine", "parabolic"), pressure_deg=36.0),
    CamInputs(),
    CamInputs(arm_mm=97.26, program=Program(58.35, 57.11, 23.17, 38.46, "cosine", "cosine"), pressure_deg=38.85,
              roller_mm=12.75),
]


def random_cases(n: int) -> list[CamInputs]:
    """``n`` random programs and rooms (seed 4): about half refused by the hub or the boss."""
    rng = np.random.default_rng(4)
    out = []
    for i in range(n):
        arm = rng.uniform(20, 200)
        program = Program(rng.uniform(5, 60), rng.uniform(40, 150), rng.uniform(0, 40), rng.uniform(40, 150),
                          LAWS[i % 4], LAWS[(i // 4) % 4])
        out.append(CamInputs(arm_mm=arm, program=program, pressure_deg=rng.uniform(25, 50),
                             hub_mm=rng.uniform(0, 1.5) * arm, boss_mm=rng.uniform(0.2, 1.2) * arm,
                             clearance_mm=rng.uniform(0, 10)))
    return out


def main(argv: list[str]) -> int:
    cases = CASES + random_cases(int(argv[0]) if argv else 20)
    digest, start = hashlib.sha256(), time.process_time()
    for inputs in cases:
        try:
            outcome = repr(design_cam(inputs))
        except DesignError as exc:
            outcome = repr((type(exc).__name__, exc.parameter, exc.value, exc.allowed))
        digest.update(outcome.encode())
    print(f"{time.process_time() - start:.2f} s CPU, {len(cases)} cams, outcomes {digest.hexdigest()[:16]}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
