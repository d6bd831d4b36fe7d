"""Issue 34 item 8: the scheme refits after File › Open and after an edit the view no longer
shows, and keeps the user's zoom and pan after a small edit.

"Fitted" is checked against the drawing's own extent (``_fit_rect``: the mechanism, its
travel and its dimensions), not against a view recorded from the program: the view holds
all of it and the drawing fills nearly all of the view across or up.
"""
from __future__ import annotations

import dataclasses

import pytest
from PySide6.QtCore import QPointF


def view_of(scheme):
    scheme._catch_up()
    return scheme._view.viewRect()


def fitted(scheme) -> bool:
    view, want = view_of(scheme), scheme._fit_rect()
    return view.contains(want) and (want.width() >= 0.9 * view.width() or want.height() >= 0.9 * view.height())


def test_a_small_edit_keeps_the_users_zoom_and_pan(qtbot, scheme, model):
    """The user zoomed in on the crank and panned: L1 100 -> 101 mm keeps that view (on main
    the drawing no longer fitted the zoomed view, so every edit fitted again)."""
    assert fitted(scheme)
    scheme._view.scaleBy((0.4, 0.4), center=QPointF(0.0, model.design.frame))
    scheme._view.translateBy(x=5.0, y=-3.0)
    before = view_of(scheme)
    model.set_spec(crank=101.0)
    assert model.error is None
    qtbot.wait(20)
    assert view_of(scheme) == before


def test_a_small_edit_of_a_fitted_view_keeps_it(qtbot, scheme, model):
    before = view_of(scheme)
    model.set_spec(crank=101.0)
    qtbot.wait(20)
    assert view_of(scheme) == before


@pytest.mark.parametrize("spec", [{"time_ratio": 5.0, "stroke": 2000.0}, {"crank": 30.0, "stroke": 90.0}])
def test_a_large_edit_fits_even_a_zoomed_view(qtbot, scheme, model, spec):
    """A zoomed view of the old design says nothing about the new one: K = 5, H = 2000 (four
    times larger) or a third of the size is fitted."""
    scheme._view.scaleBy((0.5, 0.5))
    assert not fitted(scheme)
    model.set_spec(**spec)
    assert model.error is None
    qtbot.wait(20)
    assert fitted(scheme)


def test_open_fits_even_when_the_old_view_holds_the_new_design(qtbot, scheme, model):
    """The user zoomed out a little (the drawing still fills 85 % of the view): opening a
    file of a design of about the same size shows it fitted, as a new document should
    (on main the view was kept: it still held the drawing well enough)."""
    scheme._view.scaleBy((1.1, 1.1))
    assert not fitted(scheme) and scheme._view.viewRect().contains(scheme._fit_rect())
    model.load_state(dataclasses.replace(model.valid_spec, crank=101.0), model.rpms, model.step_deg)
    qtbot.wait(20)
    assert model.design.crank == pytest.approx(101.0)
    assert fitted(scheme)


def test_open_while_the_scheme_is_hidden_fits_when_shown(qtbot, scheme, model):
    scheme._view.scaleBy((0.5, 0.5))
    scheme.hide()
    model.load_state(dataclasses.replace(model.valid_spec, crank=101.0), model.rpms, model.step_deg)
    scheme.show()
    qtbot.waitExposed(scheme)
    assert fitted(scheme)
