"""Where the scheme's labels go: no label crossed by a line or covering another (issue 32).

Every label is placed by the search of place.py against every line drawn (the
links', blocks', ram's and pins' outlines, the frame, the crank circle, the tool
path, dimension lines and arrow heads, the force arrows) and every label placed
before it, as large as the text is in mm at this zoom (its size is fixed on
screen). Labels that do not move (O₄, L1, L3, H; L2 and h keep to their chain)
are placed once per design, zoom and dimensions shown, clear of everything the
moving bodies sweep over the whole cycle; a frame places only the moving joints'
names (O₂, A, B, C) and the force magnitudes, and moves a still label only when a
force arrow of that frame runs through it. A name that finds no room beside its
joint goes a ring farther out with a leader line to it. Labels keep the sheets' gap
from each other (core.base.lettering.LABEL_GAP): clear is not enough, "O₂" an em before
"H = 312.6" on its line read as one label.
"""
from __future__ import annotations

from collections.abc import Callable

import numpy as np
from PySide6.QtCore import QObject
from PySide6.QtGui import QFontInfo

from core.base.lettering import label_gap

from shaperapp.plots.items import CurveItem
from shaperapp.widgets.style import LINK

from .dimensions import DimensionLayer
from .draw import Z_LABEL, joint_fonts, pen, text_box
from .forces import ForceLayer
from .mechanism import JOINT_LABEL_CLEAR, PIN_FIXED, PIN_MOVING, MechanismLayer
from .place import (LEADER_RING, Obstacles, around, boxes_at, clear_of_boxes, clear_of_segments,
                    end_to_end, leader, leaders, leaders_length, meets, owned, shrinking_candidates)
from .raster import Raster, raster_region

LINE_CLEAR_PX = 3.0          # a label keeps this many pixels off any line
LEADER_GAP_PX = 2.0          # a leader starts this far off its pin's rim
SMALL_TEXT = 9.0 / 11.0      # the next standard size down, as a share of the joint names' size


class LabelLayout(QObject):
    """Places the joint names, the searched dimension labels and the force labels."""

    def __init__(self, add: Callable[[object], None], mechanism: MechanismLayer,
                 dimensions: DimensionLayer, forces: ForceLayer, parent: QObject | None = None) -> None:
        super().__init__(parent)
        self._mechanism, self._dimensions, self._forces = mechanism, dimensions, forces
        self._leaders = CurveItem(pen(LINK, 0.8), connect="pairs")
        self._leaders.setZValue(Z_LABEL)
        add(self._leaders)
        self._static_lines = self._swept = np.empty((0, 2, 2))     # per design, see place_still
        self._raster: Raster | None = None     # the lines that stay put, per design and zoom
        self._kept_rasters: tuple | None = None  # see _rasters
        self._done: dict[tuple, tuple] = {}     # each frame's placement, per design and zoom
        self._px = 1.0
        self._still: dict[str, tuple] = {}     # still label: candidate centres, half size, rings
        self._home: dict[str, int] = {}        # ... its candidate for the design and zoom
        self._at: dict[str, int] = {}          # ... and the one it is at now
        self._chain: list = []                 # the L2 and h labels' boxes, mm
        self._halves: dict[str, np.ndarray] = {}
        self._bounds: tuple[float, float, float, float] | None = None
        self._small: dict[str, bool] = {}        # joint names drawn one size smaller now

    # ---- per design ----------------------------------------------------
    def rebuild(self) -> None:
        """A new design: the lines that stay put and what the moving bodies sweep over the
        cycle are taken again by the next placement (after the edit's paint, not before it)."""
        self._swept = None

    def place_still(self, mm_per_px: tuple[float, float], bounds: tuple[float, float, float, float],
                    window: tuple[float, float, float, float]) -> None:
        """O₄, L1, L3 and H (per design, zoom and dimensions shown), clear of the frame, the
        dimension lines, L2 and h, each other, and everything that moves. The lines that
        stay put are burnt into a raster over ``window`` (the view and a margin) here, once,
        for the frames to check their candidates against."""
        mech, dims = self._mechanism, self._dimensions
        self._px = px = float(max(mm_per_px))
        self._done = {}
        if mech.frames is None or not px > 0.0:
            self._raster = None
            return
        if self._swept is None:
            self._static_lines, self._swept = mech.static_lines(), mech.frame_lines(None)
        u = mech.frames.u
        texts = dims.texts()
        self._bounds = bounds
        fixed = np.concatenate([self._static_lines, dims.fixed_lines()])
        region, cell = raster_region(window, bounds, px)
        self._raster, swept = self._rasters(fixed, region, cell, LINE_CLEAR_PX * px)
        obstacles = Obstacles(np.empty((0, 2, 2)), 0.0, None, bounds, swept, self._spacing())
        axes, half_widths = mech.link_axes(None)
        obstacles.add(ends=axes, margin=half_widths + LINE_CLEAR_PX * px)
        self._chain = []
        # the one with fewer places first (a part shorter than its text has one: where the
        # chain's separation put it), so that the other keeps clear of it
        chain = ("L2", "h") if texts["L2"].isVisible() else ()
        moves = {name: dims.chain_moves(name) for name in chain}
        for name in sorted(chain, key=lambda name: len(moves[name])):
            box = np.array(text_box(texts[name]))
            shifts = moves[name]
            spots = box[None, :] + np.repeat(shifts, 2, axis=1)
            # the second not end to end with the first (barred spots only when all are)
            k = obstacles.best(spots, end_to_end(spots, np.array(self._chain), dims.chain_gap()))
            dims.shift_label(name, shifts[k])
            self._chain.append(text_box(texts[name]))
            obstacles.add(self._chain[-1], turned=True)
        for name, small in self._small.items():      # measured at full size: a frame may shrink them
            if small:
                mech.labels[name].setFont(joint_fonts()[False])
                self._small[name] = False
        self._halves = {name: self._half(item) for name, item in mech.labels.items()}
        self._still = {}
        for name in dims.placed():
            half = self._half(texts[name])
            centres = dims.candidates(name, half, 2.0 * half[1])
            self._still[name] = (centres, half, np.zeros(len(centres), dtype=int))
        gap = max(JOINT_LABEL_CLEAR * u, PIN_FIXED * u + 3.0 * px)
        half = self._halves["O4"]
        centres, ring = around(np.zeros(2), half, mech.pivot_direction, gap, 2.0 * half[1])
        self._still["O4"] = (centres, half, ring)
        self._home = {}
        for name, (centres, half, _) in self._still.items():
            boxes = boxes_at(centres, half)
            k = obstacles.best(boxes, self._leader_barred(name, boxes, obstacles))
            self._home[name] = k
            self._put_still(name, k)
            obstacles.add(boxes[k])
            obstacles.add(ends=self._leader_of(name), margin=LINE_CLEAR_PX * px)

    def _leader_barred(self, name: str, boxes: np.ndarray, obstacles: Obstacles) -> np.ndarray | None:
        """(m,) True where O₄'s name at each of ``boxes`` would be led to by a line through a
        label placed (moved off by the labels' gap, it ran through L1 = …); None for the
        others (their leaders are the dimensions')."""
        if name != "O4":
            return None
        ring = self._still[name][2]
        start = PIN_FIXED * self._mechanism.frames.u + LEADER_GAP_PX * self._px
        lines = leaders(np.zeros(2), boxes, start)
        return (ring >= LEADER_RING) & meets(np.array(obstacles.boxes).reshape(-1, 4), lines,
                                             np.full(len(boxes), LINE_CLEAR_PX * self._px)).any(axis=0)

    def _rasters(self, fixed: np.ndarray, region: tuple, cell: float, margin: float) -> tuple[Raster, Raster]:
        """The lines that stay put burnt into a raster, and a copy with the swept lines too, kept
        (only read once burnt) for the next placement over the same lines and view: a language
        switch places the labels again over the same lines, and burning both again was two
        thirds of that search (about 100 of 160 ms at load 4, issue 40 item 5)."""
        key = (region, cell, margin)
        kept = self._kept_rasters
        if (kept is not None and kept[0] == key and kept[1] is self._swept
                and np.array_equal(kept[2], fixed)):
            return kept[3], kept[4]
        raster = Raster(fixed, region, cell, margin)
        swept = raster.copy_with(self._swept)
        self._kept_rasters = (key, self._swept, fixed, raster, swept)
        return raster, swept

    def _put_still(self, name: str, k: int) -> None:
        centre = self._still[name][0][k]
        if name == "O4":
            self._mechanism.labels["O4"].setPos(*centre)
        else:
            self._dimensions.move_label(name, centre)
        self._at[name] = k

    def _leader_of(self, name: str) -> np.ndarray:
        """The leader of a still label as it is now placed (none at its first ring)."""
        if name == "L1":
            return self._dimensions.leader_line()
        if name != "O4":
            return np.empty((0, 2, 2))
        centres, half, ring = self._still[name]
        k = self._at[name]
        if ring[k] < LEADER_RING:
            return np.empty((0, 2, 2))
        u = self._mechanism.frames.u
        return leader(np.zeros(2), boxes_at(centres[k], half)[0], PIN_FIXED * u + LEADER_GAP_PX * self._px)

    @staticmethod
    def _half(item) -> np.ndarray:
        left, right, bottom, top = text_box(item)
        return np.array([abs(right - left), abs(top - bottom)]) / 2.0

    # ---- per frame -----------------------------------------------------
    def place_frame(self, index: int, mm_per_px: tuple[float, float], reserved: tuple = ()) -> None:
        """The moving joints' names and the force labels at crank-angle ``index``, clear of
        the ``reserved`` boxes (left, right, bottom, top; mm) too: what stands over the
        drawing, the force caption in the view's corner."""
        mech = self._mechanism
        f = mech.frames
        if f is None or index >= len(f.tip) or not self._halves or self._raster is None:
            return
        arrows = self._forces.lines(index)
        key = (index, arrows.tobytes(), self._forces.pending_key(), reserved)
        done = self._done.get(key)
        if done is not None:
            self._restore(done)
            return
        self._place_frame(index, arrows, mm_per_px, reserved)
        self._done[key] = self._state()

    def _state(self) -> tuple:
        """Where this frame's labels went: a frame seen again (the animation runs in cycles)
        is put back from it, without a search."""
        joints = {name: (label.x(), label.y(), self._small.get(name, False))
                  for name, label in self._mechanism.labels.items() if name != "O4"}
        leaders = (self._leaders.x.copy(), self._leaders.y.copy())
        return dict(self._at), joints, leaders, self._forces.label_state()

    def _restore(self, done: tuple) -> None:
        at, joints, leaders, forces = done
        for name, k in at.items():
            if k != self._at.get(name):
                self._put_still(name, k)
        for name, (x, y, small) in joints.items():
            label = self._mechanism.labels[name]
            if self._small.get(name, False) != small:
                label.setFont(joint_fonts()[small])
                self._small[name] = small
            label.setPos(x, y)
        self._leaders.set_data(*leaders)
        self._forces.restore_labels(forces)

    def _place_frame(self, index: int, arrows: np.ndarray, mm_per_px: tuple[float, float],
                     reserved: tuple) -> None:
        u = self._mechanism.frames.u
        obstacles = self._frame_obstacles(index, arrows, reserved)
        leaders = self._place_still_for(arrows, obstacles)
        joints = self._place_joints(index, obstacles)
        if len(joints.get("A", ())) and self._l1_from_pin(index):
            # L1's leader starts on the crank circle where the lever touches it: at a limit
            # position that is the crank pin A, and it runs out across the lever, A's own
            # first direction (the report's end limit sent A out on a 128 mm leader). Its
            # label has many places; A's name has a few: the joints first, then L1.
            retry = self._frame_obstacles(index, arrows, reserved)
            still = self._place_still_for(arrows, retry, later=("L1",))
            again = self._place_joints(index, retry)
            fewer = leaders_length(again) < leaders_length(joints) and not len(again["A"])
            lead = self._still_after("L1", retry) if fewer else None
            if lead is None:                 # no better: the first placement again
                obstacles = self._frame_obstacles(index, arrows, reserved)
                leaders = self._place_still_for(arrows, obstacles)
                joints = self._place_joints(index, obstacles)
            else:
                obstacles, leaders, joints = retry, still + [lead], again
        drawn = np.concatenate(leaders + list(joints.values())).reshape(-1, 2)
        self._leaders.set_data(drawn[:, 0], drawn[:, 1])
        self._forces.place_labels(u, mm_per_px, obstacles)

    def _l1_from_pin(self, index: int) -> bool:
        """L1 is placed and its leader starts at the crank pin A as drawn at ``index``."""
        if "L1" not in self._still:
            return False
        lead = self._dimensions.leader_line()
        pin = self._mechanism.joint_at("A", index)
        return bool(len(lead)) and float(np.hypot(*(lead[0, 0] - pin))) < 0.5 * self._px

    def _frame_obstacles(self, index: int, arrows: np.ndarray, reserved: tuple) -> Obstacles:
        """The lines of frame ``index`` (and its force arrows), L2 and h, and the ``reserved``
        boxes: what every label of the frame keeps clear of before the first is placed."""
        margin = LINE_CLEAR_PX * self._px
        ends, margins = self._mechanism.frame_obstacles(index)
        obstacles = Obstacles(np.concatenate([ends, arrows]),
                              np.concatenate([margins + margin, np.full(len(arrows), margin)]),
                              np.array(self._chain).reshape(-1, 4), self._bounds, self._raster, self._spacing())
        for box in reserved:            # the force caption: a label under it was hidden (113 of
            obstacles.cover(box)        # 144 frames' B or O₂ in the laptop pane, rod, forces shown)
        return obstacles

    def _spacing(self) -> tuple[float, float]:
        """The gap every label's box keeps from the others', mm (x, y): the sheets' label_gap
        of the joint names' text height (the largest label's; their size is fixed on screen)
        between the texts, less the margin each text's box keeps round its glyphs."""
        margin = 2.0 * self._mechanism.labels["O4"].textItem.document().documentMargin()
        gap = label_gap(QFontInfo(joint_fonts()[False]).pixelSize())
        return max(gap[0] - margin, 0.0) * self._px, max(gap[1] - margin, 0.0) * self._px

    def _place_joints(self, index: int, obstacles: Obstacles) -> dict[str, np.ndarray]:
        """The moving joints' names at ``index``; each one's leader (maybe none)."""
        return {name: self._place_joint(name, direction, obstacles, index)
                for name, direction in self._mechanism.label_directions(index).items() if name != "O4"}

    def _still_after(self, name: str, obstacles: Obstacles) -> np.ndarray | None:
        """Still label ``name`` at the candidate clear of everything placed whose leader is
        the shortest of those crossing no label (a long one would cross the drawing); its
        leader, or None (and left where it was) if there is none."""
        centres, half, _ = self._still[name]
        boxes = boxes_at(centres, half)
        texts = self._dimensions.texts()
        chain = [text_box(texts[n]) for n in ("L2", "h") if texts[n].isVisible()]   # as drawn now
        free = obstacles.clear(boxes) & clear_of_boxes(boxes, np.array(chain).reshape(-1, 4),
                                                        (obstacles.spacing[1],) * 2)
        taken = np.array(obstacles.boxes).reshape(-1, 4)
        margin = np.full(1, LINE_CLEAR_PX * self._px)
        was, best = self._at[name], None
        for k in np.flatnonzero(free):
            self._put_still(name, int(k))
            lead = self._leader_of(name)
            length = leaders_length({name: lead})
            if (not len(lead) or not meets(taken, lead, margin).any()) and (best is None or length < best[0]):
                best = (length, int(k))
        if best is None:
            self._put_still(name, was)
            return None
        return self._keep_still(name, best[1], obstacles)

    def _place_joint(self, name: str, direction: np.ndarray, obstacles: Obstacles, index: int) -> np.ndarray:
        """A moving joint's name: beside it (at its size, then one standard size smaller),
        else farther out with a leader that crosses no label; where nothing is clear, the
        spot the fewest lines come near. Returns its leader (maybe none)."""
        mech, px = self._mechanism, self._px
        u = mech.frames.u
        point = mech.joint_at(name, index)
        radius = (PIN_FIXED if name == "O2" else PIN_MOVING) * u
        gap = max(JOINT_LABEL_CLEAR * u, radius + 3.0 * px)
        taken = np.array(obstacles.boxes).reshape(-1, 4)
        margin = LINE_CLEAR_PX * px
        centres, boxes, far, small, order = shrinking_candidates(point, self._halves[name], direction,
                                                                 gap, SMALL_TEXT)
        names = list(mech.label_directions(index))
        joints, own = np.array([mech.joint_at(n, index) for n in names]), names.index(name)
        readable, nearest = owned(boxes, joints, own, far), owned(boxes, joints, own, np.ones_like(far))
        near = order[~far[order]]               # most frames end among these: checked first, cheaply
        # a spot that reads as this joint's first, then one at least nearer this joint than
        # any other, then (a short crank drawn large: O2 and A crowd) any clear one, its
        # leader telling whose it is
        for wanted in (readable, nearest, np.ones_like(far)):
            for part in (near, order[far[order]]):
                for k in part[obstacles.clear(boxes[part]) & wanted[part]]:
                    lead = leader(point, boxes[k], radius + LEADER_GAP_PX * px) if far[k] else np.empty((0, 2, 2))
                    if len(lead) and meets(taken, lead, np.full(1, margin)).any():
                        continue
                    return self._put_joint(name, centres[k], boxes[k], bool(small[k]), lead, obstacles)
        # nothing clear: the spot the fewest lines come near, but never one whose leader
        # would cross a label
        barred = far & meets(taken, leaders(point, boxes, radius + LEADER_GAP_PX * px),
                             np.full(len(boxes), margin)).any(axis=0)
        k = order[obstacles.best(boxes[order], barred[order])]
        lead = leader(point, boxes[k], radius + LEADER_GAP_PX * px) if far[k] else np.empty((0, 2, 2))
        return self._put_joint(name, centres[k], boxes[k], bool(small[k]), lead, obstacles)

    def _put_joint(self, name: str, centre: np.ndarray, box, small: bool, lead: np.ndarray,
                   obstacles: Obstacles) -> np.ndarray:
        label = self._mechanism.labels[name]
        if self._small.get(name, False) != small:
            label.setFont(joint_fonts()[small])
            self._small[name] = small
        label.setPos(*centre)
        obstacles.add(box)
        obstacles.add(ends=lead, margin=LINE_CLEAR_PX * self._px)
        return lead

    def _keep_still(self, name: str, k: int, obstacles: Obstacles) -> np.ndarray:
        """A still label at its candidate ``k`` for this frame, as an obstacle; returns its leader."""
        if k != self._at[name]:
            self._put_still(name, k)
        centres, half, _ = self._still[name]
        obstacles.add(boxes_at(centres[k], half)[0])
        lead = self._leader_of(name)
        obstacles.add(ends=lead, margin=LINE_CLEAR_PX * self._px)
        return lead

    def _place_still_for(self, arrows: np.ndarray, obstacles: Obstacles,
                         later: tuple[str, ...] = ()) -> list[np.ndarray]:
        """The still labels as obstacles of this frame: each at its home, unless a force
        arrow of this frame runs through it there; then, for this frame, at its first
        candidate clear of everything. Those ``later`` are left out (placed by the caller
        after the joints' names). Returns their leaders."""
        margin = LINE_CLEAR_PX * self._px
        leaders, crossed = [], []
        # those that stay home first, so that one that has to move keeps clear of them too
        for name, (centres, half, _) in self._still.items():
            if name in later:
                continue
            home = self._home[name]
            if len(arrows) and not clear_of_segments(boxes_at(centres[home], half), arrows, margin)[0]:
                crossed.append(name)
                continue
            leaders.append(self._keep_still(name, home, obstacles))
        for name in crossed:
            boxes = boxes_at(*self._still[name][:2])
            leaders.append(self._keep_still(name, obstacles.best(boxes, self._leader_barred(name, boxes, obstacles)),
                                            obstacles))
        return leaders
