"""The vectorized "%.10g" (core.files.numtext, issue 24) against Python's own formatting, and the
CSV files of ``shaper`` against the files the code before it wrote.

Python's ``"%.10g" % value`` is the reference: it is what every CSV here was written with
before, and it is correctly rounded, so it is independent of the numpy arithmetic tested.
"""
import json
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

from core.cli import main
from core.files.io import curve_table, snap_zeros, table_csv
from core.linkage.geometry import synthesize
from core.linkage.kinematics import solve
from core.files.numtext import g10_rows
from output_checks import golden_digest, golden_sha

GOLDEN = json.loads((Path(__file__).parents[1] / "data" / "csv_golden.json").read_text())


def python_rows(data) -> str:
    return "".join(",".join("" if v != v else "%.10g" % v for v in row) + "\n"
                   for row in np.asarray(data, dtype=float).tolist())


@settings(max_examples=300, deadline=None)
@given(arrays(np.float64, st.tuples(st.integers(1, 40), st.integers(1, 16)),
              elements=st.floats(allow_nan=True, allow_infinity=True, width=64)))
def test_any_doubles_as_python_formats_them(data):
    assert g10_rows(data) == python_rows(data)


@settings(max_examples=200, deadline=None)
@given(st.integers(-14, 30), st.integers(10 ** 9, 10 ** 10 - 1), st.integers(-3, 3),
       st.booleans())
def test_near_ties_powers_of_ten_and_carries(exponent, mantissa, ulps, negative):
    """Ten-digit decimals and their half-way points, moved a few ulps: where a rounding
    of the scaled value could differ from the correctly rounded conversion."""
    values = []
    for digits in (mantissa, mantissa + 0.5):
        x = float(f"{digits}e{exponent - 9}")
        for _ in range(abs(ulps)):
            x = np.nextafter(x, np.inf if ulps > 0 else -np.inf)
        values.append(-x if negative else x)
    data = np.array(values).reshape(1, -1)
    assert g10_rows(data) == python_rows(data)


@pytest.mark.parametrize("value", [0.0, -0.0, 1.0, 10.0, 1e9, 9999999999.5, 9999999999.4,
                                   1234567890.5, 0.0001, 0.00009999999999, 1e-5, 1e10, 1e22,
                                   1e23, 5e-324, 1.7976931348623157e308, 0.5, 2.5, -3.25e-7,
                                   float("inf"), float("-inf"), float("nan")])
def test_edge_values(value):
    data = np.array([[value, 1.0], [2.0, value]])
    assert g10_rows(data) == python_rows(data)


@pytest.mark.parametrize("rod_ratio", [None, 0.3])
def test_curve_table_text_as_python_formats_it(rod_ratio):
    """The curves table of 36 001 angles × 2 speeds, every cell as "%.10g" would write it."""
    motion = solve(synthesize(100, 1.4, 300, rod_ratio=rod_ratio),
                   np.radians(np.linspace(0, 360, 36001)), [40, 60])
    names, data = curve_table(motion)
    assert table_csv(names, data) == ",".join(names) + "\n" + python_rows(snap_zeros(data))


@pytest.mark.parametrize("case", GOLDEN["files"], ids=lambda case: case["command"][:40])
def test_cli_csv_is_byte_identical_to_the_base_commit(case, tmp_path):
    """The file the base commit wrote for the same command (its SHA-256, in
    tests/data/csv_golden.json with the command that produced it)."""
    target = tmp_path / "out.csv"
    assert main(case["command"].split() + ["--csv", str(target)]) == 0
    raw = target.read_bytes()
    assert raw.count(b"\n") == case["lines"]
    assert golden_digest(raw, case) == golden_sha(case)
