"""The Cam tab: the table's feed cam (issue 23), its inputs, profile, plots and exports."""
