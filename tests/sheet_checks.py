"""Checks every drawing sheet must pass: each drawing keeps to its own area, the areas do
not overlap, nothing lies outside the border, no two texts overlap or stand closer than a
word space (GB/T 14691) side by side, no line, circle or arrowhead runs through a text's
glyphs, and no text holds a Unicode subscript digit, which the CAD fonts of a DXF lack
(indices are subscript runs).

The crossing and spacing checks are written here on their own, from the items' plain
geometry, not with core's placement code: the test must not share the code it checks."""
import math
import re

import numpy as np

from core.drawing.checks import outside_border, overlapping_texts
from core.drawing.sheet import Circle, Polyline, Text, item_box

UNICODE_SUBSCRIPTS = re.compile("[\u2080-\u209c]")


# A glyph's body inside a run's box: the letters' side bearings and the room above the
# capitals and at the baseline, in text heights, are ink-free, so a line there does not
# touch a letter (a leader line may end at the box).
BODY_INSET = 0.12
CIRCLE_SEGMENTS = 96


def glyph_bodies(text: Text) -> list[np.ndarray]:
    """Each run's glyph body as its four corners ((4, 2) paper mm): baseline to capital
    height over the run's width, shrunk by BODY_INSET of its height, rotated as drawn."""
    bodies = []
    for run in text.runs():
        w, h, inset = run.width, run.height, BODY_INSET * run.height
        if w <= 2 * inset or not run.text.strip():
            continue
        x0 = {"l": 0.0, "c": -w / 2.0, "r": -w}[run.align[0]]
        y0 = {"b": 0.0, "m": -h / 2.0, "t": -h}[run.align[1]]
        local = np.array([[x0 + inset, y0 + inset], [x0 + w - inset, y0 + inset],
                          [x0 + w - inset, y0 + h - inset], [x0 + inset, y0 + h - inset]])
        c, s = math.cos(math.radians(run.rotation)), math.sin(math.radians(run.rotation))
        bodies.append(local @ np.array([[c, s], [-s, c]]) + np.asarray(run.position))
    return bodies


def item_segments(item) -> np.ndarray:
    """An item's strokes as segments (n, 4): x0, y0, x1, y1; a circle as a 96-gon."""
    if isinstance(item, Circle):
        t = np.linspace(0.0, 2.0 * math.pi, CIRCLE_SEGMENTS + 1)
        pts = np.column_stack([item.center[0] + item.radius * np.cos(t),
                               item.center[1] + item.radius * np.sin(t)])
    elif isinstance(item, Polyline):
        pts = np.asarray(item.points, dtype=float).reshape(-1, 2)
        if item.closed or item.filled:
            pts = np.vstack([pts, pts[:1]])
    else:
        return np.zeros((0, 4))
    return np.column_stack([pts[:-1], pts[1:]])


def _segments_meet_box(seg: np.ndarray, box: tuple[float, float, float, float]) -> np.ndarray:
    """Which segments (n, 4) have a point inside the axis-parallel ``box`` (Liang–Barsky)."""
    x0, y0, dx, dy = seg[:, 0], seg[:, 1], seg[:, 2] - seg[:, 0], seg[:, 3] - seg[:, 1]
    lo, hi = np.zeros(len(seg)), np.ones(len(seg))
    ok = np.ones(len(seg), bool)
    for p, q in ((-dx, x0 - box[0]), (dx, box[2] - x0), (-dy, y0 - box[1]), (dy, box[3] - y0)):
        parallel = np.abs(p) < 1e-12
        ok &= ~(parallel & (q < 0))
        with np.errstate(divide="ignore", invalid="ignore"):
            t = np.where(parallel, 0.0, q / np.where(parallel, 1.0, p))
        lo = np.where(~parallel & (p < 0), np.maximum(lo, t), lo)
        hi = np.where(~parallel & (p > 0), np.minimum(hi, t), hi)
    return ok & (lo <= hi)


def _inside_polygon(point: np.ndarray, poly: np.ndarray) -> bool:
    """Even-odd rule: whether ``point`` lies inside the polygon ``poly`` ((n, 2))."""
    a, b = poly, np.roll(poly, -1, axis=0)
    straddles = (a[:, 1] > point[1]) != (b[:, 1] > point[1])
    with np.errstate(divide="ignore", invalid="ignore"):
        x = a[:, 0] + (point[1] - a[:, 1]) * (b[:, 0] - a[:, 0]) / (b[:, 1] - a[:, 1])
    return bool(np.count_nonzero(straddles & (point[0] < x)) % 2)


def _meets_body(body: np.ndarray, seg: np.ndarray) -> np.ndarray:
    """Which segments (n, 4) meet the glyph ``body`` (a rotated rectangle's corners)."""
    origin, u = body[0], body[1] - body[0]
    length, height = float(np.hypot(*u)), float(np.hypot(*(body[3] - body[0])))
    u = u / length
    v = np.array([-u[1], u[0]])
    to_local = lambda xy: np.column_stack([(xy - origin) @ u, (xy - origin) @ v])   # noqa: E731
    local = np.hstack([to_local(seg[:, :2]), to_local(seg[:, 2:])])
    return _segments_meet_box(local, (0.0, 0.0, length, height))


def crossed_texts(sheet) -> list[tuple[Text, object]]:
    """(text, item) for every text whose glyph body a line, polyline, circle or filled
    arrowhead of the sheet meets; each text once, with the first such item. Each item's
    segments are made once, and a body is tested against all its near items' segments in
    one pass (one test per item was most of this check's time on a crowded sheet)."""
    strokes = [it for it in sheet.items if not isinstance(it, Text)]
    boxes = np.array([item_box(it) for it in strokes]).reshape(-1, 4)
    segs = [item_segments(it) for it in strokes]
    filled = np.array([isinstance(it, Polyline) and it.filled for it in strokes], dtype=bool)
    found = []
    for text in (it for it in sheet.items if isinstance(it, Text)):
        for body in glyph_bodies(text):
            (x0, y0), (x1, y1) = body.min(axis=0), body.max(axis=0)
            near = np.flatnonzero((boxes[:, 0] <= x1) & (boxes[:, 2] >= x0)
                                  & (boxes[:, 1] <= y1) & (boxes[:, 3] >= y0))
            hit = _first_crossing(body, near, strokes, segs, filled)
            if hit is not None:
                found.append((text, hit))
                break
    return found


def _first_crossing(body: np.ndarray, near: np.ndarray, strokes: list, segs: list[np.ndarray],
                    filled: np.ndarray):
    """The first of ``strokes[near]`` whose segments, or (a filled one) whose area, meet the
    glyph ``body``; None if none does."""
    if not len(near):
        return None
    counts = np.array([len(segs[i]) for i in near])
    met = np.zeros(len(near), dtype=bool)
    if counts.sum():
        owner = np.repeat(np.arange(len(near)), counts)
        met[owner[_meets_body(body, np.concatenate([segs[i] for i in near]))]] = True
    for j in np.flatnonzero(~met & filled[near]):                # an arrowhead over it all
        met[j] = _inside_polygon(body.mean(axis=0), np.asarray(strokes[near[j]].points, float))
    first = np.flatnonzero(met)
    return strokes[near[first[0]]] if len(first) else None


# GB/T 14691 (ISO 3098-1, type B lettering): words stand e = 6/10 h apart. Two texts side
# by side whose glyph bodies stand closer than that read as one word ("105120135"). Lines one
# above another may stand closer: the standard's smallest baseline spacing, 14/10 h, leaves
# 0.64 h between two lines' bodies, and 0.35 h under an index (lowered 0.25 h).
WORD_SPACE = 0.6
LINE_SPACE = 0.35


def crowded_texts(sheet) -> list[tuple[Text, Text, float]]:
    """(text, text, clear mm) for every two texts whose glyph bodies (:func:`glyph_bodies`)
    stand closer than the smaller text's height times WORD_SPACE side by side (their
    bodies share part of a line) or LINE_SPACE otherwise (one over the other), touching or
    overlapping ones at 0. Measured between the bodies as convex quadrilaterals (a turned
    dimension text too, its line across its own baseline), each pair once, at its nearest."""
    texts = [it for it in sheet.items if isinstance(it, Text)]
    bodies, owner = [], []
    for i, text in enumerate(texts):
        for body in glyph_bodies(text):
            bodies.append(body)
            owner.append(i)
    if len(bodies) < 2:
        return []
    quads, owner = np.array(bodies), np.array(owner)
    heights = np.array([t.height for t in texts])[owner]
    lo, hi = quads.min(axis=1), quads.max(axis=1)
    reach = WORD_SPACE * heights.max()
    i, j = np.nonzero(np.triu((lo[:, None, 0] < hi[None, :, 0] + reach) & (lo[None, :, 0] < hi[:, None, 0] + reach)
                              & (lo[:, None, 1] < hi[None, :, 1] + reach)
                              & (lo[None, :, 1] < hi[:, None, 1] + reach)
                              & (owner[:, None] != owner[None, :]), k=1))
    clear = _quad_distance(quads[i], quads[j])
    up = quads[i, 3] - quads[i, 0]                  # across the first one's baseline
    up /= np.hypot(up[:, 0], up[:, 1])[:, None]
    pi, pj = (quads[i] * up[:, None]).sum(-1), (quads[j] * up[:, None]).sum(-1)
    one_line = (pi.min(1) < pj.max(1)) & (pj.min(1) < pi.max(1))
    least = np.where(one_line, WORD_SPACE, LINE_SPACE) * np.minimum(heights[i], heights[j])
    close = clear < least - 1e-9
    found: dict[tuple[int, int], float] = {}
    for a, b, d in zip(owner[i][close], owner[j][close], clear[close]):
        key = (min(a, b), max(a, b))
        found[key] = min(found.get(key, math.inf), float(d))
    return [(texts[a], texts[b], d) for (a, b), d in sorted(found.items())]


def _quad_distance(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """The distance between convex quadrilaterals ``a`` and ``b`` ((k, 4, 2) each), 0 where
    they meet: the nearest of each one's corners to the other's edges, unless no edge
    normal separates them (the separating axis theorem)."""
    def corner_to_edges(p: np.ndarray, q: np.ndarray) -> np.ndarray:
        s, e = q, np.roll(q, -1, axis=1)                    # (k, 4, 2) edges of q
        d = (e - s)[:, None, :, :]                          # (k, 1, 4, 2)
        w = p[:, :, None, :] - s[:, None, :, :]             # (k, 4, 4, 2)
        t = np.clip((w * d).sum(-1) / np.maximum((d * d).sum(-1), 1e-300), 0.0, 1.0)
        return np.hypot(*np.moveaxis(w - t[..., None] * d, -1, 0)).min(axis=(1, 2))

    separated = np.zeros(len(a), dtype=bool)
    for quad in (a, b):
        for k in range(2):
            edge = quad[:, k + 1] - quad[:, k]
            n = np.column_stack([-edge[:, 1], edge[:, 0]])[:, None, :]
            pa, pb = (a * n).sum(-1), (b * n).sum(-1)
            separated |= (pa.max(1) < pb.min(1)) | (pb.max(1) < pa.min(1))
    return np.where(separated, np.minimum(corner_to_edges(a, b), corner_to_edges(b, a)), 0.0)


def inside(box, area, tol=1e-6) -> bool:
    return (box[0] >= area[0] - tol and box[1] >= area[1] - tol
            and box[2] <= area[2] + tol and box[3] <= area[3] + tol)


def assert_laid_out(sheet, areas) -> None:
    """``areas``: name → (area box, its items) of a sheet built by core.drawing."""
    assert outside_border(sheet) == [] and overlapping_texts(sheet) == []
    crossed = [(t.text, t.position, type(it).__name__, it.layer) for t, it in crossed_texts(sheet)]
    assert crossed == [], crossed
    crowded = [(a.text, b.text, round(clear, 2)) for a, b, clear in crowded_texts(sheet)]
    assert crowded == [], crowded
    assert [t.text for t in sheet.items if isinstance(t, Text) and UNICODE_SUBSCRIPTS.search(t.text)] == []
    named = list(areas.items())
    # a caption cut short loses its scale ("μ_a = 0.06 (m/…"); only a user's text in the title
    # block may be cut
    cut = [t.text for name, (_, items) in named if name != "title" for t in items
           if isinstance(t, Text) and "…" in t.text]
    assert cut == [], cut
    for name, (area, items) in named:
        strays = [it for it in items if not inside(item_box(it), area)]
        assert strays == [], (name, strays[:3])
    for i, (a_name, (a, _)) in enumerate(named):
        for b_name, (b, _) in named[i + 1:]:
            assert not (a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]), (a_name, b_name)


def assert_pdf_sheet(path, size_mm) -> str:
    """A written sheet's PDF: its page is the paper (within 0.5 mm), a Chinese one embeds a
    CJK font (when pdffonts is installed); returns its text, NFKC-normalized (the CJK font
    maps some characters to radicals), or '' without pdftotext."""
    import re
    import shutil
    import subprocess
    import unicodedata
    info = subprocess.run(["pdfinfo", str(path)], capture_output=True, text=True).stdout
    w, h = (float(v) * 25.4 / 72 for v in re.search(r"([\d.]+) x ([\d.]+) pts", info).groups())
    assert abs(w - size_mm[0]) < 0.5 and abs(h - size_mm[1]) < 0.5
    if shutil.which("pdffonts"):
        fonts = subprocess.run(["pdffonts", str(path)], capture_output=True, text=True).stdout
        rows = [line for line in fonts.splitlines()[2:] if line.strip()]
        assert any("CJK" in r or "Hei" in r or "Han" in r for r in rows), fonts
    if shutil.which("pdftotext") is None:
        return ""
    text = subprocess.run(["pdftotext", str(path), "-"], capture_output=True, text=True).stdout
    return unicodedata.normalize("NFKC", text)
