"""The feed cam (issue 23): one synthesis, as the Cam tab recomputes it on every edit.

Run with ``pytest benchmarks/test_bench_cam.py --benchmark-enable -n 0``.
"""
from core.cam import CamInputs, Program, design_cam
from core.cam import extremes
from core.linkage.spec import Spec


def test_cam_synthesis_timed_against_the_linkage(benchmark):
    design = Spec().design()
    inputs = CamInputs(arm_mm=120.0, program=Program(15.0, 60.0, 10.0, 60.0, "cosine", "parabolic"))

    def edit():
        # an edit brings new inputs: the extremes' caches (keyed on the follower) start empty
        extremes.pressure_peaks.cache_clear()
        extremes.min_convex_radius.cache_clear()
        return design_cam(inputs, design, 0.05)
    cam = benchmark(edit)
    assert cam.within_allowance and cam.timing is not None
