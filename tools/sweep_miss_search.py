"""Search random rod designs for a torque extremum the loaded sweep misses:
``python tools/sweep_miss_search.py SEED SECONDS``.

Why: the sweep brackets the torque's extrema on core.space.sweep.SWEEP_INTERVALS cells (plus
samples crowding toward the sharp angles) while ``summarize`` takes 3600; a design whose
torque turns twice inside one coarse cell is reported wrong. This draws rod designs with
L1/L2 from 0.3 to 0.995 (where the lever whips round), random loads (the tests' own
``_loads``) and one speed of 1 … 150 r/min for SECONDS, and prints how many it compared and
every design whose peak or least torque differs from the summary's by more than 1e-8 of
the peak (docs/performance.md, the loaded sweep).
"""
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path[:0] = [str(ROOT), str(ROOT / "tests"), str(ROOT / "tests" / "test_core")]

from test_sweep_loaded import _loads  # noqa: E402

from core.base.errors import DesignError  # noqa: E402
from core.forces.flywheel import cycle_summary, summarize  # noqa: E402
from core.linkage.designs import Designs  # noqa: E402
from core.linkage.geometry import Design  # noqa: E402
from core.linkage.kinematics import rpm_to_omega  # noqa: E402
from core.space.sweep import SWEEP_INTERVALS  # noqa: E402


def main(seed: int, seconds: float) -> None:
    rng = np.random.default_rng(seed)
    misses, count, end = [], 0, time.monotonic() + seconds
    while time.monotonic() < end:
        crank, ratio = rng.uniform(20, 150), rng.uniform(0.3, 0.995)
        frame = crank / ratio
        lever = rng.uniform(1.2, 4) * (frame + crank)
        try:
            design = Design(crank=crank, frame=frame, lever=lever, guide=rng.uniform(0.3, 1.0) * lever,
                            rod=rng.uniform(0.1, 1.5) * lever,
                            rod_side=str(rng.choice(["leading", "trailing"])))
            masses = _loads(rng, True)
            rpms = [float(rng.choice([1.0, 5.0, 20.0, 60.0, 150.0]))]
            got = cycle_summary(Designs.of(design), rpm_to_omega(np.array(rpms)), masses,
                                intervals=SWEEP_INTERVALS)
            want = summarize(design, rpms, masses).speeds[0]
        except DesignError:             # a drawn design the domain refuses
            continue
        count += 1
        scale = max(abs(want.max_torque_N_m), abs(want.min_torque_N_m))
        error = max(abs(got["min_torque_N_m"][0, 0] - want.min_torque_N_m),
                    abs(got["max_torque_N_m"][0, 0] - want.max_torque_N_m)) / scale
        if error > 1e-8:
            misses.append((round(ratio, 3), float(error), design, rpms))
    print(f"{count} designs; misses (L1/L2, error / peak, design, r/min): {misses}")


if __name__ == "__main__":
    main(int(sys.argv[1]), float(sys.argv[2]))
