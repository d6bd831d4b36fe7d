"""The vector polygons (velocity, acceleration, forces) and their painter."""
