"""Drawing sheets: the Qt side of ``core.drawing`` (PDF and SVG, labels, the dialog, the command)."""
