"""The Gear tab: the gear pair that drives the crank (issue 35, item 4)."""
