"""The Compare tab: several designs' curves and figures side by side."""
