"""The mechanism drawn to scale: links, dimensions and force arrows."""
