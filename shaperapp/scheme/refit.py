"""When the scheme fits its view to a new design, and when it keeps the user's view.

Pure decisions on rectangles (mm), split from view.py so that the widget keeps to its
layers and signals: a nudged input keeps the view, as in the plots; a file just opened,
a large edit, or a drawing that no longer fits the view it showed is fitted.
"""
from __future__ import annotations

from PySide6.QtCore import QRectF

# After an edit the view is kept while it holds the whole drawing and the drawing fills at
# least this share of it across or up (a fresh fit fills about 93 %).
FILL_KEPT = 0.8
# A view the user zoomed or panned is kept after an edit unless the drawing moved or
# grew or shrank by more than this share of its size (a large edit: then it is fitted).
LARGE_EDIT = 0.25


def navigated(view: QRectF, fitted: QRectF | None) -> bool:
    """Has the view changed since the last fit (a zoom, a pan, a resize)?"""
    if fitted is None:
        return True
    tol = 1e-6 * max(fitted.width(), fitted.height())
    return any(abs(a - b) > tol for a, b in zip(view.getCoords(), fitted.getCoords()))


def large_edit(before: QRectF, after: QRectF) -> bool:
    """Did the drawing move, grow or shrink by more than LARGE_EDIT of its size?"""
    w, h = max(before.width(), 1e-9), max(before.height(), 1e-9)
    return (abs(after.left() - before.left()) > LARGE_EDIT * w
            or abs(after.right() - before.right()) > LARGE_EDIT * w
            or abs(after.top() - before.top()) > LARGE_EDIT * h
            or abs(after.bottom() - before.bottom()) > LARGE_EDIT * h)


def still_fits(view: QRectF, want: QRectF) -> bool:
    """The view holds the new drawing ``want`` and the drawing fills at least FILL_KEPT
    of it across or up: a nudged input keeps the view."""
    return view.contains(want) and (want.width() >= FILL_KEPT * view.width()
                                    or want.height() >= FILL_KEPT * view.height())


def needs_fit(opened: bool, before: QRectF | None, after: QRectF, view: QRectF,
              fitted: QRectF | None, want: QRectF) -> bool:
    """After a new design (``before``: the previous one's drawing, ``after`` the new one's,
    ``want`` it with the force arrows shown): a file just opened is fitted; the view a fit
    showed is kept while the new drawing still fits it well; a view the user zoomed,
    panned or resized is kept unless the edit was large or the whole drawing it showed
    no longer fits in it."""
    if opened or before is None:
        return True
    if not navigated(view, fitted):
        return not still_fits(view, want)
    return large_edit(before, after) or (view.contains(before) and not view.contains(after))
