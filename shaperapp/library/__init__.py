"""The design library pane: list, filter, open, keep and compare designs."""
