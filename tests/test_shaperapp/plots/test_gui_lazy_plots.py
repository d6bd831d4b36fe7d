"""The Kinematics tab's lever plots, hidden at first, are made when first shown (issue 24:
a pyqtgraph plot costs several milliseconds at every start), and then draw what core
computes, as if they had always been there."""
from __future__ import annotations

import numpy as np
import pytest
from PySide6.QtCore import Qt

from shaperapp.plots.kinematics import LEVER_PLOTS, PlotsWidget

from gui_helpers import shown


def test_hidden_lever_plots_are_built_when_first_shown(qtbot, model):
    plots = shown(qtbot, PlotsWidget(model), 900, 700)
    stack = plots.stack()
    assert set(stack._plots) == {"ram_x", "ram_v", "ram_a"}
    model.set_spec(time_ratio=1.6)                      # a change before the plot exists
    plots.set_plot_visible("lever_omega", True)
    assert "lever_omega" in stack._plots and "lever_alpha" not in stack._plots
    qtbot.wait(10)
    drawn = stack.plot("lever_omega").curves
    assert len(drawn) == model.motion.rpm.size
    for curve, want in zip(drawn, model.motion.lever_omega):
        np.testing.assert_allclose(curve.y, want, rtol=1e-12, atol=1e-12)
    bottom = stack.plot("ram_a").item.getAxis("bottom")
    assert not bottom.style["showValues"]               # the x values moved under the new plot
    assert stack.plot("lever_omega").item.getAxis("bottom").style["showValues"]


def test_a_hidden_plot_asked_for_is_built_and_current(qtbot, model):
    plots = shown(qtbot, PlotsWidget(model), 900, 700)
    angle = plots.stack().plot("lever_angle")           # read back while hidden
    assert not plots.plot_visible("lever_angle")
    np.testing.assert_allclose(angle.curves[0].y, np.degrees(model.motion.lever_angle), rtol=1e-12)


def test_the_first_plot_cannot_start_hidden(qtbot, model):
    from shaperapp.plots.stack import PlotStack
    with pytest.raises(ValueError, match="stays shown"):
        PlotStack(model, None, PlotsWidget(model).stack()._series, lambda: "", hidden=("ram_x",))


def test_a_stack_makes_one_legend_per_group(qtbot, model, monkeypatch):
    """Issue 43 item 5: the kinematics' six series are one group, so one legend is made
    (five more, each a few pyqtgraph items, were made and dropped before the first paint)."""
    from shaperapp.plots import stack as stack_module
    made = []
    real = stack_module.GroupLegend

    def counted(*args, **kwargs):
        made.append(real(*args, **kwargs))
        return made[-1]
    monkeypatch.setattr(stack_module, "GroupLegend", counted)
    plots = PlotsWidget(model)
    qtbot.addWidget(plots)
    groups = {series.group for series in plots.stack()._series}
    assert len(made) == len(groups) == 1
    assert list(plots.stack()._legends.values()) == made


def test_a_band_gets_a_text_item_only_where_it_is_labelled(qtbot, model, monkeypatch):
    """Issue 43 item 5: only the first plot labels its bands, so a band's text item is made
    when it first shows a label: the Kinematics tab made one per band and plot (nine, of
    which two were ever shown) before the window's first paint. The bands and their
    labels are what the source gives."""
    import pyqtgraph as pg
    from shaperapp.plots import curves as curves_module
    made = []

    class Counted(pg.TextItem):
        def __init__(self, *args, **kwargs):
            super().__init__(*args, **kwargs)
            made.append(self)
    monkeypatch.setattr(curves_module.pg, "TextItem", Counted)
    plots = shown(qtbot, PlotsWidget(model), 900, 700)
    stack = plots.stack()
    bands = stack._source.bands()
    labelled = [band.label for band in bands if band.label]
    assert labelled == ["working stroke", "return stroke"]
    first, *others = stack._plots.values()
    assert first.band_labels() == labelled
    assert len(made) == len(labelled)
    for plot in others:
        assert plot.band_labels() == []
        assert len(plot.bands()) == len(bands)            # every band still shaded
    model.set_spec(time_ratio=1.6)                       # redrawn: the same items reused
    qtbot.wait(10)
    assert len(made) == len(labelled) and first.band_labels() == labelled


def test_heights_wait_for_the_refresh_that_is_due(qtbot, model, monkeypatch):
    """Issue 43 item 5: a stack whose refresh is due (built hidden, or hidden since an edit)
    fits its plots' heights in that refresh, not at each step of its construction and of
    the window's layout before it (eight fits before the first paint, each re-laying out
    the legends)."""
    from shaperapp.plots import stack as stack_module
    fits = []
    real = stack_module.fit_heights
    monkeypatch.setattr(stack_module, "fit_heights", lambda *a: (fits.append(1), real(*a)))
    plots = PlotsWidget(model)
    qtbot.addWidget(plots)
    plots.set_plot_visible("lever_angle", True)          # a relayout while hidden
    assert fits == []
    plots.resize(700, 800)
    plots.show()
    qtbot.waitExposed(plots)
    assert fits                                          # fitted once shown
    view = plots.stack()._view
    assert view.minimumHeight() >= view.ci.layout.effectiveSizeHint(Qt.SizeHint.MinimumSize).height()
