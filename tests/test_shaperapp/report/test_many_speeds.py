"""The report at 16 crank speeds (issue 32): no table is cut at the page's edge, every
speed's value of every per-speed table is in the PDF's text layer, in both languages.

The expected values are the CLI's own (``shaper analyze`` and ``shaper dynamics`` print
every speed) and the positions table's JSON formatted with one number of decimals per
column, computed here: five significant digits of the column's largest magnitude. On
79f5cea the per-speed tables ran off the page's right edge (speeds from 80 r/min on were
missing from the page and from the text layer) and the report had 38 pages.
"""
from __future__ import annotations

import json
import re
import shutil
import subprocess
from collections import Counter

import pytest

from cli_runner import shaper_run_in_process
from report_numbers import cli_values, column_text

pytestmark = [pytest.mark.slow,
              pytest.mark.skipif(shutil.which("pdftotext") is None, reason="pdftotext not installed")]

DESIGN = ["--crank", "100", "--K", "1.4", "--stroke", "300"]
RPMS = [str(10 * k) for k in range(1, 17)]
LOADS = ["--lever-mass", "20", "--lever-inertia", "1.1", "--ram-mass", "70",
         "--cut-force", "7000", "--cut-height", "80"]


def positions_values() -> list[str]:
    """Per speed, the ram's velocity and acceleration, the crank torque and the power at
    numbered position 4 and at the cut's start, as their columns print them."""
    result = shaper_run_in_process("table", *DESIGN, "--rpm", *RPMS, *LOADS, "--json")
    records = json.loads(result.stdout)
    out = []
    for rpm in map(float, RPMS):
        rows = [r for r in records if r["rpm"] == rpm]
        assert len(rows) == 18
        for column in ("ram_v_m_s", "ram_a_m_s2", "crank_torque_N_m", "power_W"):
            values = [r[column] for r in rows]
            for row in (rows[3], rows[14]):
                out.append(column_text(values, row[column]))
    return out


@pytest.fixture(scope="module")
def expected() -> list[str]:
    values = cli_values("analyze", *DESIGN, "--rpm", *RPMS)
    values += cli_values("dynamics", *DESIGN, "--rpm", *RPMS, *LOADS)
    return values


@pytest.fixture(scope="module", params=["en", "zh"])
def printed(request, tmp_path_factory):
    path = tmp_path_factory.mktemp("many") / f"{request.param}.pdf"
    result = shaper_run_in_process("report", *DESIGN, "--rpm", *RPMS, *LOADS, "--lang", request.param,
                                   "-o", path)
    assert result.returncode == 0, result.stderr
    text = subprocess.run(["pdftotext", "-layout", str(path), "-"], capture_output=True, text=True,
                          check=True).stdout
    return re.sub(r"\s+", " ", text)


def occurrences(text: str, value: str) -> int:
    """How often ``value`` stands in ``text`` as a whole number (no digit glued on)."""
    return len(re.findall(r"(?<![\d.])" + re.escape(value) + r"(?![\d])", text))


def test_every_speed_of_every_per_speed_table_is_printed(printed, expected):
    """Each CLI value at least as often as the CLI prints it (one per speed it holds)."""
    short = {v: n for v, n in Counter(expected).items() if occurrences(printed, v) < n}
    assert short == {}


def test_the_positions_tables_hold_every_speed(printed):
    missing = [v for v in positions_values() if occurrences(printed, v) == 0]
    assert missing == []


def test_many_speeds_do_not_repeat_the_whole_table_per_speed(printed):
    pages = re.findall(r"(\d+) / (\d+)", printed)
    assert int(pages[-1][1]) <= 20
