"""The report's scheme at the limit positions (§3) is the same for the same design, whatever
the process drew before it: a class writes its students' reports one after another in one
process with the kept views (shaperapp.report.kept_views), and an earlier design's label
placement once leaked into a later one's page (docs/performance.md, "A student's cost in
`shaper class`", The outputs)."""
from __future__ import annotations

import hashlib

import pytest

import shaperapp.report.figures as figures
from core.linkage.metrics import analyze
from core.linkage.spec import Spec
from shaperapp.report.kept_views import keep_plot_views, release_plot_views

SCHEME_I = Spec(mode="dimensions", crank=110.0, frame=380.0, lever=540.0, variant="rod", rod_ratio=0.25)
DEFAULT = Spec(crank=100.0, time_ratio=1.4, stroke=300.0)


def limit_svgs(spec: Spec, monkeypatch) -> list[str]:
    """The two limit positions' SVGs that §3 paints, hashed."""
    shots = []
    paint = figures.scheme_paint
    monkeypatch.setattr(figures, "scheme_paint", lambda made, *rest: shots.extend(made) or paint(made, *rest))
    rpms = [60.0]
    views = figures.ReportViews(spec, rpms, None, analyze(spec.design(), rpms))
    try:
        views.limit_schemes()
    finally:
        views.close()
    return [hashlib.sha256(bytes(shot.svg)).hexdigest() for shot in shots]


@pytest.mark.parametrize("kept", [False, True], ids=["fresh-views", "kept-views"])
def test_a_designs_limit_schemes_do_not_depend_on_the_design_drawn_before(qapp, monkeypatch, kept):
    if kept:
        keep_plot_views()
    try:
        first = limit_svgs(SCHEME_I, monkeypatch)
        other = limit_svgs(DEFAULT, monkeypatch)
        again = limit_svgs(SCHEME_I, monkeypatch)
    finally:
        if kept:
            release_plot_views()
    assert len(first) == 2 and first != other
    assert again == first
