"""The table of crank positions."""
