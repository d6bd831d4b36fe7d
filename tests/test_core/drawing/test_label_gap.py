"""A label keeps a readable gap from the texts round it (core.base.lettering.LABEL_GAP),
not only clear of them: a joint name 1.1 text heights before a dimension on its line read
as one label with it ("O₂ H = 312.6", the report's scheme of 方案 I)."""
from __future__ import annotations

import numpy as np
import pytest

from core.base.lettering import LABEL_GAP
from core.drawing.labels import place
from core.drawing.sheet import Text


def apart(a, b, height) -> bool:
    """Boxes (x0, y0, x1, y1) at least LABEL_GAP apart: beside on one line, or over each other."""
    beside = max(a[0] - b[2], b[0] - a[2])
    over = max(a[1] - b[3], b[1] - a[3])
    return beside >= LABEL_GAP[0] * height - 1e-9 or over >= LABEL_GAP[1] * height - 1e-9


@pytest.mark.parametrize("height", [2.5, 3.5, 5.0])
@pytest.mark.parametrize("offset", [0.2, 0.6, 1.0, 1.4])
def test_a_label_keeps_the_gap_from_a_text_on_its_line(height, offset):
    """A dimension's text stands on the label's preferred line, ``offset`` text heights past
    where the label would end at its first spot (touching it is free, but too close)."""
    first = Text("O2", (1.5, 0.0), height, "lm").box()
    other = Text("H = 312.6", (first[2] + offset * height, 0.0), height, "lm")
    taken = [other.box()]
    placed = place("O2", (0.0, 0.0), height, taken, np.zeros((0, 4)), preferred=(1.0, 0.0))
    assert placed, "left out"
    label = placed[0]
    assert label.text == "O2" and apart(label.box(), other.box(), label.height), (label.box(), other.box())


AXIS_TITLES = {"φ/(°)", "s/mm", "v/(m/s)", "a/(m/s²)", "M/(N·m)", "E/J"}


@pytest.mark.parametrize("size", ["A3", "A1"])
@pytest.mark.parametrize("dims", [(90.0, 350.0, 580.0, 0.3, 64.0), None], ids=["scheme-II", "default"])
def test_a_charts_axis_titles_keep_the_gap_from_its_notes(dims, size):
    """The axis titles of the motion and kinetostatic sheets' charts keep LABEL_GAP from every
    other word of the sheet (the scales' notes, the captions), not only a word space: on A3
    the v chart's "φ/(°)" stood 0.1 h under "μv = 0.08 (m/s)/mm", right-aligned with it, and
    read as its second line (方案 II and the default design)."""
    from core.drawing.forces import forces_sheet
    from core.drawing.motion import motion_sheet
    from core.drawing.sheet import paper
    from core.forces.masses import MassProperties, masses_for_design
    from core.linkage.spec import Spec
    if dims:
        spec = Spec(mode="dimensions", crank=dims[0], frame=dims[1], lever=dims[2], variant="rod", rod_ratio=dims[3])
    else:
        spec = Spec()
    rpm = dims[4] if dims else 40.0
    design = spec.design()
    loads = MassProperties(lever_mass_kg=20, lever_inertia_kg_m2=1.1, ram_mass_kg=70, cut_force_N=7000,
                           cut_height_mm=80)
    for sheet in (motion_sheet(design, rpm, paper(size)).sheet,
                  forces_sheet(design, rpm, masses_for_design(design, loads), paper(size)).sheet):
        texts = [t for t in sheet.items if isinstance(t, Text)]
        words = [t for t in texts if not t.text.lstrip("-").replace(".", "").isdigit()]
        titles = [t for t in texts if t.text in AXIS_TITLES]
        assert len(titles) >= 4                     # M, E and two φ; s, v, a and three φ
        for title in titles:
            for other in words:
                if other is not title:
                    assert apart(title.box(), other.box(), title.height), (title.text, other.text)
