"""Peak memory and time of ``shaper report`` at 16 crank speeds with loads and 3600
positions (issue 33): at most 600 MB.

On 79f5cea the report repeated the whole positions table for every speed: 5127 pages,
a peak of 662–679 MB and 33–44 s. Now the whole table is printed for the first speed
and four columns at every speed (``shaperapp/report/positions.py``): figures measured
with this test and ``/usr/bin/time -v`` are in docs/performance.md.

The command runs in a fresh process that reports its own peak resident size (VmHWM,
``peak_probe``).
"""
from peak_probe import peak_mb_of

TARGET_MB = 600.0
SPEEDS_16 = [str(10 * k) for k in range(1, 17)]


def test_report_at_16_speeds_and_3600_positions_stays_under_600_mb(benchmark, tmp_path):
    target = tmp_path / "report.pdf"
    peaks = {}

    def work():
        peaks["peak MB"] = peak_mb_of("report", "--crank", "100", "--K", "1.4", "--stroke", "300",
                                      "--rpm", *SPEEDS_16, "--lever-mass", "20", "--lever-inertia", "1.1",
                                      "--ram-mass", "70", "--cut-force", "7000", "--cut-height", "80",
                                      "--positions", "3600", "-o", str(target), timeout=900)
    benchmark.pedantic(work, rounds=1, iterations=1)
    benchmark.extra_info.update({k: round(v, 1) for k, v in peaks.items()})
    print({k: round(v, 1) for k, v in peaks.items()})
    assert target.stat().st_size > 0
    assert peaks["peak MB"] <= TARGET_MB, peaks
