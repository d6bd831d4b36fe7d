"""A ``shaper class`` worker keeps its reports' views (``kept_views.keep_plot_views``):
each report loads its design into the kept widgets' model instead of building the scheme
and the pyqtgraph plots anew. The SVG each figure replays must be the one a new widget
exports (the scheme's two shots with where O4 and the lever's tips lie in them), for
designs that differ in their dimensions, their variant and their number of speeds, each
after others of its kind (a kept scheme has placed another design's labels before)."""
from __future__ import annotations

import pytest

import shaperapp.report.figures as figures
import shaperapp.report.kept_views as kept_views
from core.cam import CamInputs
from core.forces.masses import MassProperties
from core.linkage.metrics import analyze
from core.linkage.spec import Spec

pytestmark = pytest.mark.slow      # some 2 s a design: three plot views built and exported

LOADS = MassProperties(lever_mass_kg=20, lever_inertia_kg_m2=1.1, ram_mass_kg=70, cut_force_N=7000,
                       cut_height_mm=80)
# a class's students (the same speeds, other dimensions), then more speeds, a rod, fewer speeds
CASES = [(Spec(), [40.0, 60.0]), (Spec(time_ratio=1.6, crank=90.0), [30.0, 45.0]),
         (Spec(crank=110.0, time_ratio=1.46, stroke=320.0), [40.0, 60.0]),
         (Spec(crank=103.0, time_ratio=1.3, stroke=306.0), [40.0, 60.0]),
         (Spec(crank=95.0), [30.0, 45.0, 60.0]), (Spec(variant="rod", rod_input="ratio", rod_ratio=0.3), [60.0]),
         (Spec(variant="rod", rod_input="ratio", rod_ratio=0.25, crank=100.0, time_ratio=1.5), [60.0]),
         (Spec(), [40.0, 60.0])]


def _figures(monkeypatch, cases=CASES, after_each=lambda: None) -> list[list[bytes]]:
    """Each case's scheme shots and s/v/a, force and cam SVGs, in the report's order, as
    the report replays them (``scheme_paint``, ``svg_paint``); ``after_each`` is called
    after each case's views are closed."""
    made: list = []
    paint, schemes = figures.svg_paint, figures.scheme_paint
    monkeypatch.setattr(figures, "svg_paint", lambda svgs, *a: made.extend(svgs) or paint(svgs, *a))
    monkeypatch.setattr(figures, "scheme_paint", lambda shots, *a: made.extend(shots) or schemes(shots, *a))
    out = []
    for spec, rpms in cases:
        made.clear()
        views = figures.ReportViews(spec, rpms, LOADS, analyze(spec.design(), rpms))
        try:
            views.limit_schemes()
            views.curves()
            views.forces()
            views.cam_curves(CamInputs(), None)
        finally:
            views.close()
        out.append(list(made))
        after_each()
    return out


def test_kept_views_export_what_new_ones_do(qapp, monkeypatch):
    new = _figures(monkeypatch)
    monkeypatch.setattr(kept_views, "_KEPT", [])
    kept_views.keep_plot_views()
    held = []           # the kept views after each case (read in the same run: no case more)
    try:
        kept = _figures(monkeypatch, after_each=lambda: held.append(dict(kept_views._KEPT[0].views)))
        for case, views in enumerate(held):
            assert sorted(views) == ["cam", "curves", "forces", "scheme"], case
        # cases 2 and 3: other dimensions, the same speeds, loads and variant: the same views
        assert all(held[3][k] is held[2][k] for k in held[2]), [k for k in held[2] if held[3][k] is not held[2][k]]
        # case 4 after 3: a speed more: new views
        assert not any(held[4][k] is held[3][k] for k in held[3]), [k for k in held[3] if held[4][k] is held[3][k]]
    finally:
        held.clear()
        kept_views.release_plot_views()
    assert kept_views._KEPT == []
    assert [len(f) for f in new] == [5] * len(CASES)
    assert len({f[0].svg for f in new}) == len(CASES) - 1      # the designs differ (the last is the first again)
    for case, (a, b) in enumerate(zip(new, kept)):
        for kind, x, y in zip(("scheme at the start", "scheme at the end", "curves", "forces", "cam"), a, b):
            assert x == y, (case, kind)
