"""The design-space map and the optimizer, run on a worker thread."""
