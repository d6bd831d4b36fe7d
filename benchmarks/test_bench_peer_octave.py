"""Issue 24, item 1: ``shaper curves`` against seed 000's MATLAB program in GNU Octave.

Both run as whole processes, alternating, in one run, for the same 72 002 rows (36 001
crank angles × 40 and 60 r/min): Octave runs the seed's own subroutine ``six_bar``,
extracted from the seed file at run time (its full-width plus signs '﹢' made ASCII, as
``../shared/reference/seed000_six_bar_octave.txt`` was made; the seed's code is not
copied into this repository), in the minimal main loop ``peers/seed000_curves.m``: once with one call of six_bar per
angle and speed, as the seed's program computes its rows (``octave``), and once with one
call per angle whose rates are scaled per speed, as ours are (``octave_scaled``, about
half the time; the stricter comparison). The seed's mechanism is the rod (six-bar) variant with the ram joint leading the lever tip,
so the same work on our side is ``--rod-ratio 0.3 --rod-side leading``; the issue's own
command (block variant, our default design) is timed in the same rounds. The test checks
that Octave's rows equal ours after mapping frames; it asserts nothing about speed.

Measure with ``python -m pytest -n 0 -p no:cacheprovider benchmarks/test_bench_peer_octave.py
--benchmark-enable -s``: the figures (min and median of each, and their ratios) are printed
and kept in the benchmark's extra_info; the table's time is one whole round of the four.
The seed file is ``$SHAPER_SEED000`` or ``../shared/seeds/000_*.txt`` beside the
repository; without it, or without ``octave-cli`` on PATH, the benchmark is skipped.
"""
from __future__ import annotations

import math
import os
import shutil
import statistics
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

from core.linkage.geometry import synthesize

pytestmark = pytest.mark.slow

ROOT = Path(__file__).resolve().parents[1]
PEERS = Path(__file__).resolve().parent / "peers"
DESIGN = ["--crank", "100", "--K", "1.4", "--stroke", "300"]
ROD = ["--rod-ratio", "0.3", "--rod-side", "leading"]
RPMS = (40, 60)
STEP = "0.01"
ROUNDS = 3
FULL_WIDTH_PLUS = "\ufe62"


def seed_file() -> Path:
    """Seed 000: ``$SHAPER_SEED000`` or the first ``../shared/seeds/000_*.txt``; skips
    the benchmark, saying where it looked, when there is none."""
    given = os.environ.get("SHAPER_SEED000")
    if given:
        if not Path(given).is_file():
            pytest.skip(f"seed 000 not found: SHAPER_SEED000={given} is not a file")
        return Path(given)
    pattern = ROOT.parent / "shared" / "seeds" / "000_*.txt"
    found = sorted(pattern.parent.glob(pattern.name))
    if not found:
        pytest.skip(f"seed 000 not found: set SHAPER_SEED000 to the seed file (looked for {pattern})")
    return found[0]


def six_bar_source(seed_text: str) -> str:
    """The seed's subroutine six_bar as Octave reads it: from its ``function`` line to the
    first line whose code (before any % comment) is prose, with '﹢' made '+'."""
    lines = seed_text.splitlines()
    start = next((i for i, line in enumerate(lines) if line.startswith("function")
                  and "six_bar(" in line), None)
    assert start is not None, "seed 000 has no 'function … six_bar(' line"
    code = []
    for line in lines[start:]:
        line = line.replace(FULL_WIDTH_PLUS, "+")
        if not line.split("%", 1)[0].isascii():
            break
        code.append(line)
    return "\n".join(code) + "\n"


def shaper() -> list[str]:
    exe = shutil.which("shaper")
    return [exe] if exe else [sys.executable, "-m", "core"]


def octave_lengths() -> str:
    """six_bar's ll = [l1 l3 l4 l6 l61] in m for our rod design (crank, lever, rod, frame,
    guide), written with 17 digits so that Octave gets the same doubles."""
    d = synthesize(100, 1.4, 300, rod_ratio=0.3, rod_side="leading")
    return " ".join(f"{v / 1000.0:.17g}" for v in (d.crank, d.lever, d.rod, d.frame, d.guide))


def mapped_octave_rows(octave: np.ndarray) -> dict[str, tuple[np.ndarray, float]]:
    """The seed's columns in our frame and units (header of ``shaper curves``), each with
    the largest value Octave printed for it, in our units (what its rounding scales with).

    The seed's x points the other way (its ram cuts toward −x, ours toward +x), its
    angles are from +x counter-clockwise in that mirrored frame, its lengths in m.
    So x → −x, the lever ψ = θ3 − 90° (ψ from O4→O2, + toward the cut), the rod
    λ = 180° − θ4, and the ram's displacement is counted from its place at φ = 0.
    """
    rpm, phi = octave[:, 0], octave[:, 1]
    first = np.where(phi == 0.0)[0]
    s_e = octave[:, 5]
    origin = s_e[first][np.searchsorted(rpm[first], rpm)]
    deg = 180.0 / math.pi

    def printed(column: int, unit: float = 1.0) -> float:
        return float(np.abs(octave[:, column]).max()) * unit

    return {
        "ram_x_mm": (-1000.0 * (s_e - origin), printed(5, 1000.0)),
        "ram_v_m_s": (-octave[:, 9], printed(9)),
        "ram_a_m_s2": (-octave[:, 13], printed(13)),
        "lever_deg": (np.degrees(octave[:, 3] - math.pi / 2.0), printed(3, deg)),
        "lever_omega_rad_s": (octave[:, 7], printed(7)),
        "lever_alpha_rad_s2": (octave[:, 11], printed(11)),
        "slide_v_m_s": (octave[:, 6], printed(6)),
        "rod_deg": (np.degrees(math.pi - octave[:, 4]), printed(4, deg)),
        "rod_omega_rad_s": (-octave[:, 8], printed(8)),
        "rod_alpha_rad_s2": (-octave[:, 12], printed(12)),
    }


def read_csv(path: Path) -> tuple[list[str], np.ndarray]:
    with path.open() as f:
        names = f.readline().strip().split(",")
    return names, np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)


def test_shaper_curves_against_seed000_in_octave(benchmark, tmp_path):
    seed = seed_file()
    octave = shutil.which("octave-cli")
    if octave is None:
        pytest.skip("GNU Octave is not installed here (no octave-cli on PATH): "
                    "the seed's MATLAB program cannot run")
    (tmp_path / "six_bar.m").write_text(six_bar_source(seed.read_text(encoding="utf-8")),
                                        encoding="utf-8")
    out = {name: tmp_path / f"{name}.csv" for name in ("octave", "octave_scaled", "rod", "block")}
    rpms = " ".join(str(r) for r in RPMS)

    def run_octave(name: str, scaled: bool) -> list[str]:
        call = f"seed000_curves([{octave_lengths()}], [{rpms}], {STEP}, '{out[name]}', {str(scaled).lower()})"
        return [octave, "--norc", "--quiet", "--no-history", "--path", str(tmp_path),
                "--path", str(PEERS), "--eval", call]

    commands = {
        "octave": run_octave("octave", False),
        "octave_scaled": run_octave("octave_scaled", True),
        "rod": shaper() + ["curves", *DESIGN, *ROD, "--rpm", *map(str, RPMS), "--step", STEP,
                           "--csv", str(out["rod"])],
        "block": shaper() + ["curves", *DESIGN, "--rpm", *map(str, RPMS), "--step", STEP,
                             "--csv", str(out["block"])],
    }
    times: dict[str, list[float]] = {name: [] for name in commands}

    def one_round():
        for name, command in commands.items():
            start = time.perf_counter()
            subprocess.run(command, check=True, cwd=tmp_path, capture_output=True)
            times[name].append(time.perf_counter() - start)

    benchmark.pedantic(one_round, rounds=ROUNDS, iterations=1)

    names, ours = read_csv(out["rod"])
    assert ours.shape[0] == len(RPMS) * 36001
    for run in ("octave", "octave_scaled"):
        octave_names, theirs = read_csv(out[run])
        assert theirs.shape == (ours.shape[0], 14) and octave_names[:2] == ["rpm", "crank_deg"]
        assert np.array_equal(theirs[:, :2], ours[:, :2])   # the same speeds and angles, row by row
        for name, (values, printed) in mapped_octave_rows(theirs).items():
            column = ours[:, names.index(name)]
            # Both sides print 10 significant digits (half a unit in the 10th is 5e-10 of
            # the value): 2e-9 of the larger of the two printed columns covers both roundings.
            scale = max(float(np.abs(column).max()), printed)
            worst = float(np.abs(values - column).max())
            assert worst <= 2e-9 * scale, f"{run}, {name}: differs by {worst:g} (scale {scale:g})"

    figures = {}
    for name, values in times.items():
        figures[f"{name}_min_s"] = min(values)
        figures[f"{name}_median_s"] = statistics.median(values)
    for peer in ("octave", "octave_scaled"):
        for name in ("rod", "block"):
            for stat in ("min", "median"):
                figures[f"{peer}_over_{name}_{stat}"] = (figures[f"{peer}_{stat}_s"]
                                                         / figures[f"{name}_{stat}_s"])
    figures["rounds"] = len(times["octave"])
    benchmark.extra_info.update(figures)
    print("\n" + ", ".join(f"{k} {v:.3f}" if isinstance(v, float) else f"{k} {v}"
                           for k, v in figures.items()))
