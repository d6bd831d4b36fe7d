"""Small array helpers shared by core and the GUI.

Why not numpy's own: ``np.unique`` imports ``numpy.ma`` on its first call (7–9 ms
here), which every ``shaper`` command and the window's first paint would pay for
one call on a few dozen numbers.
"""
from __future__ import annotations

import numpy as np


def sorted_unique(values: np.ndarray) -> np.ndarray:
    """The values of a 1-D array sorted, each once, as ``np.unique(values)`` gives them
    for numbers without NaN."""
    ordered = np.sort(np.asarray(values).ravel())
    if ordered.size == 0:
        return ordered
    return ordered[np.concatenate(([True], ordered[1:] != ordered[:-1]))]
