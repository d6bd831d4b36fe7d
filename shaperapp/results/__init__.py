"""The Results pane: dimensions, cycle figures, forces and flywheel as tables."""
