"""What a DIMENSION measures, reckoned from its definition points; a DXF's notes as read."""
import math

import numpy as np


def measurement(dim) -> float:
    """A linear or aligned dimension's length (ezdxf's measurement); a two-line angular
    dimension's angle in degrees between its lines' directions away from their common
    vertex (ezdxf's own get_measurement takes it counter-clockwise from the first line to
    the second, which is not what CAD and ezdxf's renderer draw: they draw the arc through
    the dimension's location)."""
    if dim.dimtype != 2:
        return float(dim.get_measurement())
    first = np.array(dim.dxf.defpoint3)[:2] - np.array(dim.dxf.defpoint2)[:2]
    second = np.array(dim.dxf.defpoint)[:2] - np.array(dim.dxf.defpoint4)[:2]
    cross = first[0] * second[1] - first[1] * second[0]
    return abs(math.degrees(math.atan2(cross, float(first @ second))))


def notes_of(path) -> str:
    """The notes of a DXF (its TEXT layer's TEXT entities), one a line: the runs (a subscript
    is a TEXT of its own) joined in the order written, a line starting at the notes' left edge."""
    import ezdxf
    texts = list(ezdxf.readfile(path).modelspace().query("TEXT[layer=='TEXT']"))
    left = min(t.dxf.insert.x for t in texts)
    lines: list[str] = []
    for t in texts:
        if abs(t.dxf.insert.x - left) < 1e-6:
            lines.append("")
        lines[-1] += t.dxf.text
    return "\n".join(lines)
