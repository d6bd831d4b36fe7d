"""What the scheme shows, read back in mm: the drawn joints, links, tool path, force arrows
and label boxes, as the report's figures and the tests check them against core.

A mixin of :class:`shaperapp.scheme.view.SchemeWidget`, apart so that the widget's own
module keeps to building and moving its layers. Each reader first lets the widget catch
up with a pending rebuild, so it reads what a user would see now.
"""
from __future__ import annotations

import numpy as np

from .draw import Box, Pair


class SchemeReadBack:
    """The read-back half of the scheme widget (``_catch_up``, the layers, ``_plot`` and
    ``_view`` are the widget's)."""

    def drawn_forces(self) -> dict[str, Pair]:
        """The force arrows drawn now as {name: (start, tip)} in mm, read back from the drawn path.

        Names are those of ``FORCE_NAMES`` that are drawn: the arrow runs from start to
        tip along the force on the body named in core (see docs/forces.md): "O2" frame on
        crank, "A" block on lever, "O4" frame on lever, "B" rod or tip block on lever,
        "C" rod on ram, "guide" guide on ram, "cut" workpiece on tool. Every arrow starts
        at its point of application except "cut", whose tip touches the tool point.
        Empty while the layer is hidden.
        """
        self._catch_up()
        return self._forces.drawn()

    def force_labels(self) -> dict[str, str]:
        """The magnitude labels next to the drawn force arrows."""
        self._catch_up()
        return self._forces.labels()

    def force_label_boxes(self) -> dict[str, Box]:
        """Where the magnitude labels are drawn on screen, (left, right, bottom, top) in mm."""
        self._catch_up()
        return {name: self._screen_box(tag) for name, tag in self._forces.tags().items()}

    def force_caption(self) -> str:
        """The force layer's caption (speed and length scale); empty while hidden."""
        self._catch_up()
        return self._forces.caption()

    def drawn_joints(self) -> dict[str, tuple[float, float]]:
        """Joint positions as the pin markers show them now, mm (for checks and tests)."""
        self._catch_up()
        return self._mechanism.joints()

    def drawn_link_ends(self) -> dict[str, tuple[float, float]]:
        """Where the far end of each moved link body lands now, mm (for checks and tests)."""
        self._catch_up()
        return self._mechanism.link_ends(self._model)

    def ram_extent(self) -> tuple[float, float]:
        """x of the ram body's rear and front ends as drawn now, mm."""
        self._catch_up()
        return self._mechanism.ram_extent()

    def dimension_labels(self) -> list[str]:
        """The texts of the dimension labels now drawn."""
        self._catch_up()
        return self._dimensions.labels()

    def dimension_label_boxes(self) -> dict[str, Box]:
        """Where the dimension labels are drawn on screen, (left, right, bottom, top) in mm,
        by name ("L1" …)."""
        self._catch_up()
        return {name: self._screen_box(item) for name, item in self._dimensions.texts().items()}

    def text_boxes(self) -> list[tuple[Box, bool]]:
        """Every text shown now (the joints' names, the dimensions', the forces' magnitudes):
        the box of its lines of letters, without the margin its item keeps round them, in mm
        (left, right, bottom, top), and whether it is turned (read upwards). The report's θ,
        drawn over the scheme, keeps the labels' gap from them."""
        self._catch_up()
        items = [*self._mechanism.labels.values(), *self._dimensions.texts().values(),
                 *self._forces.tags().values()]
        return [(self._screen_box(item, _margin(item)), bool(getattr(item, "angle", 0.0)))
                for item in items if item.isVisible()]

    def _screen_box(self, item, inset: float = 0.0) -> Box:
        """The item's box (``inset`` px less on every side) as the viewport shows it, back in
        mm: what a user sees, whatever transform tricks the item uses to stay upright and
        unscaled."""
        view = self._plot
        local = item.boundingRect().adjusted(inset, inset, -inset, -inset)
        device = item.deviceTransform(view.viewportTransform()).mapRect(local)
        scene = view.viewportTransform().inverted()[0].mapRect(device)
        r = self._view.mapSceneToView(scene).boundingRect()
        return r.left(), r.right(), r.top(), r.bottom()

    def tool_path(self) -> tuple[np.ndarray, np.ndarray]:
        """Vertices of the travelled part of the tool-tip trace as drawn now, mm."""
        self._catch_up()
        return self._mechanism.tool_path()


def _margin(item) -> float:
    """The room (px) a text item keeps round its letters: a pyqtgraph text's document margin,
    a force's tag its padding."""
    text = getattr(item, "textItem", None)
    return text.document().documentMargin() if text is not None else float(getattr(item, "PAD", 0.0))
