"""A ``shaper class`` worker keeps its reports' plot views (``figures.keep_plot_views``):
each report loads its design into the kept widgets' model instead of building the
pyqtgraph plots anew. The SVG each figure replays must be the one a new widget exports,
for designs that differ in their dimensions, their variant and their number of speeds."""
from __future__ import annotations

import pytest

import shaperapp.report.figures as figures
from core.cam import CamInputs
from core.forces.masses import MassProperties
from core.linkage.metrics import analyze
from core.linkage.spec import Spec

pytestmark = pytest.mark.slow      # some 2 s a design: three plot views built and exported

LOADS = MassProperties(lever_mass_kg=20, lever_inertia_kg_m2=1.1, ram_mass_kg=70, cut_force_N=7000,
                       cut_height_mm=80)
# a class's students (the same speeds, other dimensions), then more speeds, a rod, fewer speeds
CASES = [(Spec(), [40.0, 60.0]), (Spec(time_ratio=1.6, crank=90.0), [30.0, 45.0]),
         (Spec(crank=95.0), [30.0, 45.0, 60.0]), (Spec(variant="rod", rod_input="ratio", rod_ratio=0.3), [60.0]),
         (Spec(), [40.0, 60.0])]


def _figures(monkeypatch, cases=CASES) -> list[list[bytes]]:
    """Each case's s/v/a, force and cam SVGs, as the report replays them (``svg_paint``)."""
    made: list[bytes] = []
    paint = figures.svg_paint
    monkeypatch.setattr(figures, "svg_paint", lambda svgs, *a: made.extend(svgs) or paint(svgs, *a))
    out = []
    for spec, rpms in cases:
        made.clear()
        views = figures.ReportViews(spec, rpms, LOADS, analyze(spec.design(), rpms))
        try:
            views.curves()
            views.forces()
            views.cam_curves(CamInputs(), None)
        finally:
            views.close()
        out.append(list(made))
    return out


def test_kept_views_export_what_new_ones_do(qapp, monkeypatch):
    new = _figures(monkeypatch)
    monkeypatch.setattr(figures, "_KEPT", [])
    figures.keep_plot_views()
    try:
        kept = _figures(monkeypatch)
        views = figures._KEPT[0].views
        assert sorted(views) == ["cam", "curves", "forces"]
        first = dict(views)
        _figures(monkeypatch, CASES[-1:])
        assert all(views[k] is first[k] for k in first)     # the same speeds: the same views
        _figures(monkeypatch, CASES[2:3])
        assert not any(views[k] is first[k] for k in first)     # a speed more: new views
    finally:
        figures.release_plot_views()
    assert figures._KEPT == []
    assert [len(f) for f in new] == [3] * len(CASES)
    assert len({f[0] for f in new}) == len(CASES) - 1      # the designs differ (the last is the first again)
    for case, (a, b) in enumerate(zip(new, kept)):
        for kind, x, y in zip(("curves", "forces", "cam"), a, b):
            assert x == y, (case, kind)
