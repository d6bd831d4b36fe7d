"""core.base.arrays.sorted_unique against numpy's np.unique, which it replaces to keep
numpy.ma out of start-up."""
import numpy as np
from hypothesis import given
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

from core.base.arrays import sorted_unique


@given(arrays(np.float64, st.integers(0, 60), elements=st.floats(-1e6, 1e6) | st.sampled_from([0.0, -0.0, 1.0])))
def test_equals_numpy_unique(values):
    np.testing.assert_array_equal(sorted_unique(values), np.unique(values))


@given(arrays(np.int64, st.integers(0, 60), elements=st.integers(-5, 5)))
def test_integers_equal_numpy_unique(values):
    got = sorted_unique(values)
    assert got.dtype == values.dtype
    np.testing.assert_array_equal(got, np.unique(values))
