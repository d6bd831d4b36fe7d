"""core.base.arrays against the numpy functions it replaces: sorted_unique against
np.unique (to keep numpy.ma out of start-up), nonzero_pairs against np.nonzero of a 2-D
mask (slow in numpy 2.4)."""
import numpy as np
from hypothesis import given
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

from core.base.arrays import nonzero_pairs, sorted_unique


@given(arrays(np.float64, st.integers(0, 60), elements=st.floats(-1e6, 1e6) | st.sampled_from([0.0, -0.0, 1.0])))
def test_equals_numpy_unique(values):
    np.testing.assert_array_equal(sorted_unique(values), np.unique(values))


@given(arrays(np.int64, st.integers(0, 60), elements=st.integers(-5, 5)))
def test_integers_equal_numpy_unique(values):
    got = sorted_unique(values)
    assert got.dtype == values.dtype
    np.testing.assert_array_equal(got, np.unique(values))


@given(arrays(np.bool_, st.tuples(st.integers(0, 40), st.integers(0, 40))))
def test_pairs_equal_numpy_nonzero(mask):
    """The same two index arrays, dtype and order, empty rows and columns included."""
    rows, columns = nonzero_pairs(mask)
    want_rows, want_columns = np.nonzero(mask)
    assert rows.dtype == want_rows.dtype and columns.dtype == want_columns.dtype
    np.testing.assert_array_equal(rows, want_rows)
    np.testing.assert_array_equal(columns, want_columns)
