"""The title block of every sheet, after GB/T 10609.1: 180 × 56 mm in the border's lower
right corner, in the standard's three zones of ruled cells, with the course design's fields
(those of the report's cover). Its label texts come from the caller, who chooses the
language; its values are the user's text, set as typed (no index notation)."""
from __future__ import annotations

import unicodedata
from dataclasses import dataclass, field, replace
from typing import Mapping

import numpy as np

from .dxf import OUTLINE, THIN, TITLE
from .sheet import TEXT_HEIGHTS, Box, Item, Paper, Text, line, rectangle, text_width
from .cells import cell_text

TITLE_WIDTH = 180.0
TITLE_HEIGHT = 56.0
# GB/T 10609.1's 180 × 56 mm in its zones: the signature area on the left (80 mm), the
# "other" area in the middle (50 mm), the name area on the right (50 mm: the unit, the
# drawing's name, its code), every field in a ruled cell
TITLE_ZONES = (80.0, 50.0, 50.0)
TITLE_SIGN_COLUMNS = (22.0, 34.0, 24.0)      # role, name, date
TITLE_OTHER_COLUMNS = (22.0, 28.0)           # label, value
TITLE_NAME_ROWS = (18.0, 18.0, 20.0)         # the unit (school), the drawing's name, its code (the design)
TITLE_ROWS = 4
SPEED_ROW = 7.0                              # mm of the design's cell under its name: the sheet's speed
TITLE_ROW = TITLE_HEIGHT / TITLE_ROWS
TITLE_LABEL_KEYS = ("design", "scale", "sheet", "drawn", "date", "checked", "approved",
                    "number", "class", "supervisor")
# The title block's words in English: every sheet's ENGLISH texts start from these.
TITLE_ENGLISH = {"design": "Design", "scale": "Scale", "sheet": "Sheet", "drawn": "Drawn",
                 "date": "Date", "checked": "Checked", "approved": "Approved",
                 "number": "Number", "class": "Class", "supervisor": "Supervisor"}


@dataclass(frozen=True)
class TitleBlock:
    """What the title block says: the course design's fields, those of the report's cover
    (``shaper drawing`` and ``shaper report`` take them as the same options). ``labels``
    maps TITLE_LABEL_KEYS to the caller's words."""

    title: str                 # the sheet's name, e.g. "Motion analysis"
    design: str                # the design's name
    scale: str                 # e.g. "1:5"
    sheet: str                 # e.g. "1/2"
    drawn: str = ""            # the student's name (who drew it)
    date: str = ""
    school: str = ""
    labels: Mapping[str, str] = field(default_factory=dict)
    number: str = ""           # the student's number
    group: str = ""            # the class
    supervisor: str = ""
    speed: str = ""            # the crank speed the sheet is drawn at, "n_2 = 60 r/min" (index notation; '' for none)


def title_block_box(p: Paper) -> Box:
    x1, y0 = p.border[2], p.border[1]
    return (x1 - TITLE_WIDTH, y0, x1, y0 + TITLE_HEIGHT)


def title_block(p: Paper, block: TitleBlock) -> list[Item]:
    """The title block in the border's lower right corner, GB/T 10609.1's 180 × 56 mm:
    left the signature area (drawn by the student with the date, the supervisor, checked,
    approved: role, name, date), in the middle the student number, the class, the scale
    and the sheet, right the school, the sheet's name (large) and the design, under it the
    crank speed the sheet is drawn at (a sheet of one speed of several). The outline
    and the zones' borders thick, the cells thin."""
    x0, y0, x1, y1 = title_block_box(p)
    lab = lambda key: block.labels.get(key, key)            # noqa: E731
    mid, right = x0 + TITLE_ZONES[0], x0 + TITLE_ZONES[0] + TITLE_ZONES[1]
    rows = [y1 - k * TITLE_ROW for k in range(TITLE_ROWS + 1)]
    sign = x0 + np.cumsum((0.0,) + TITLE_SIGN_COLUMNS)
    other = mid + np.cumsum((0.0,) + TITLE_OTHER_COLUMNS)
    names = y1 - np.cumsum((0.0,) + TITLE_NAME_ROWS)
    items: list[Item] = [rectangle((x0, y0, x1, y1), OUTLINE)]
    items += [line([(x0, y), (right, y)], THIN) for y in rows[1:-1]]
    items += [line([(x, y0), (x, y1)], THIN) for x in (*sign[1:-1], other[1])]
    items += [line([(right, y), (x1, y)], THIN) for y in names[1:-1]]
    items += [line([(x, y0), (x, y1)], OUTLINE) for x in (mid, right)]

    def cell(text: str, x_a: float, x_b: float, top: float, bottom: float, largest: float = 3.5,
             users: bool = False) -> None:
        """A label on one line; a user's text (a name, a number) as large as fits, at
        2.5 mm on two lines before it is cut: it is who drew the sheet."""
        box = (float(x_a), float(bottom), float(x_b), float(top))
        if text:
            items.extend(wrapped_cell(text, box, largest, TEXT_HEIGHTS[0]) if users
                         else [cell_text(text, box, largest, layer=TITLE)])
    signatures = [(lab("drawn"), block.drawn, block.date), (lab("supervisor"), block.supervisor, ""),
                  (lab("checked"), "", ""), (lab("approved"), "", "")]
    others = [(lab("number"), block.number), (lab("class"), block.group),
              (lab("scale"), block.scale), (lab("sheet"), block.sheet)]
    for k, ((role, name, date), (label, value)) in enumerate(zip(signatures, others)):
        top, bottom = rows[k], rows[k + 1]
        cell(role, sign[0], sign[1], top, bottom)
        cell(name, sign[1], sign[2], top, bottom, users=True)
        cell(date, sign[2], sign[3], top, bottom, users=True)
        cell(label, other[0], other[1], top, bottom)
        cell(value, other[1], other[2], top, bottom, users=k < 2)
    for text, k, largest in ((block.school, 0, 5.0), (block.title, 1, 7.0), (block.design, 2, 5.0)):
        box = (right, float(names[k + 1]), x1, float(names[k]))
        if k == 2 and block.speed:          # the design over the speed it is drawn at
            box, speed_box = (right, box[1] + SPEED_ROW, x1, box[3]), (right, box[1], x1, box[1] + SPEED_ROW)
            items.append(cell_text(block.speed, speed_box, 3.5, layer=TITLE, notation=True))
        items += wrapped_cell(text, box, largest) if text else []
    return items


def wrapped_cell(text: str, box: Box, largest: float, least: float = 5.0) -> list[Text]:
    """``text`` in the cell ``box`` on one line as large as fits (≤ ``largest``), or, when
    that would be smaller than ``least`` or cut, on two lines (≤ 5 mm), or more where the
    cell holds them (:func:`most_lines`), broken where a line may break (:func:`line_breaks`): whole and as large
    as they come, in the fewest lines, the breaks nearest the even split of those; when no
    lines hold it whole, the lines that show the most of it, the last cut with "…", where
    they show more than one line (a long design or sheet name in the name area's 50 mm
    cells; a student's name in the 34 mm signature cell, the student's identity on the
    sheet; "Mechanical Engineering 2101" in the 28 mm class cell, three lines at 2.5 mm).
    More lines, not a smaller height: GB/T 14691's next height down, 1.8 mm, is for letters
    and digits; its Chinese characters are at least 3.5 mm (the title block's 2.5 mm is
    already the least the sheets print)."""
    one = cell_text(text, box, largest, layer=TITLE)
    breaks = line_breaks(text)
    if one.text == text and one.height >= min(largest, least) or not breaks:
        return [one]
    best, kept = [one], len(one.text) - one.text.endswith("…")
    for count in range(2, most_lines(box) + 1):
        tries = [_lines(text, cuts, box, largest) for cuts in _cut_sets(text, breaks, count, box)]
        if not tries:
            continue
        lines, whole, shown = max(tries, key=lambda t: (t[1], t[0][0].height, t[2]))
        if whole:
            return lines if lines[0].height > one.height or one.text != text else [one]
        if one.text != text and shown > kept:
            best, kept = lines, shown
    return best


def most_lines(box: Box) -> int:
    """How many lines of the least height (2.5 mm) the cell ``box`` holds, LINE_PITCH apart
    and 1.6 heights for the outer lines' room (one line's share, as :func:`cell_text`
    gives it): 3 in the title block's 14 mm rows and the design's 13 mm, 4 in the name
    area's 18 mm."""
    room = (box[3] - box[1]) / TEXT_HEIGHTS[0]
    return max(int((room - 1.6) / LINE_PITCH + 1e-9) + 1, 1)


def _cut_sets(text: str, breaks: list[int], count: int, box: Box) -> list[tuple[int, ...]]:
    """The ways to break ``text`` into ``count`` lines whose every line but the last fits
    ``box`` at the least height (else what follows it is lost from the middle): those that
    break after a comma first ("L1 100 mm, K / 1.4, H 300 mm" parted K from its value), the
    most even first among equals."""
    room = box[2] - box[0] - 2.0
    even = [len(text) * k / count for k in range(1, count)]

    def grown(cuts: tuple[int, ...], start: int):
        """The fitting cut sets that begin with ``cuts``, in ``itertools.combinations``'
        order. A line only gets wider as its break moves on, so the first break that makes it
        too wide ends the search there: a 200-character Chinese name (a break between any two
        characters) had 1.3 million sets of three breaks to measure, 15 s a sheet."""
        if len(cuts) == count - 1:
            yield cuts
            return
        for i in range(start, len(breaks)):
            if text_width(_parts(text, (*cuts, breaks[i]))[-2], TEXT_HEIGHTS[0]) > room:
                break
            yield from grown((*cuts, breaks[i]), i + 1)

    return sorted(grown((), 0), key=lambda cuts: (sum(not _after_comma(text, c) for c in cuts),
                                                  sum(abs(c - e) for c, e in zip(cuts, even))))


def _after_comma(text: str, at: int) -> bool:
    """Whether a break at ``at`` follows a comma or a semicolon (a clause's end)."""
    return text[:at].rstrip()[-1:] in (",", ";", "，", "；", "、")


def _parts(text: str, cuts: tuple[int, ...]) -> list[str]:
    """``text`` cut at ``cuts``, the spaces at each break dropped."""
    ends = (0, *cuts, len(text))
    out = []
    for k, part in enumerate(text[a:b] for a, b in zip(ends, ends[1:])):
        part = part.lstrip() if k else part
        out.append(part.rstrip() if k < len(cuts) else part)
    return out


def _lines(text: str, cuts: tuple[int, ...], box: Box, largest: float) -> tuple[list[Text], bool, int]:
    """``text`` broken at ``cuts`` on lines of ``box``, all as large as the smallest fits (≤
    5 mm, and as many as the cell holds at that height); whether all are whole, and how many
    characters they show (0 when one before the last is cut: what follows it would be lost
    from the middle)."""
    x0, y0, x1, y1 = box
    parts = _parts(text, cuts)
    n = len(parts)
    cap = (y1 - y0) / ((n - 1) * LINE_PITCH + 1.6)
    height = min(cell_text(part, box, min(largest, 5.0, cap)).height for part in parts)   # all alike
    # set LINE_PITCH heights apart about the cell's middle, as one text of several lines
    # (each in the middle of its share, 2.5 mm lines stood 2.8 heights apart in a 14 mm row)
    middle = (y0 + y1) / 2.0
    lines = [cell_text(part, box, height, layer=TITLE) for part in parts]
    lines = [replace(line, position=(line.position[0], middle + ((n - 1) / 2.0 - k) * LINE_PITCH * height))
             for k, line in enumerate(lines)]
    whole = [line.text == part for line, part in zip(lines, parts)]
    shown = sum(len(line.text) for line in lines) - lines[-1].text.endswith("…") if all(whole[:-1]) else 0
    return lines, all(whole), shown


LINE_PITCH = 1.6         # two lines of a cell, baseline to baseline, in text heights (GB/T 14691: ≥ 1.4)
NO_BREAK_BEFORE = "，。、；：！？）》」』】”’…"
NO_BREAK_AFTER = "（《「『【“‘"


def line_breaks(text: str) -> list[int]:
    """Where ``text`` may go on to a second line: after a space, or beside a CJK character
    (Chinese breaks between any two characters, and a Chinese name or school has no spaces),
    but not before a closing mark nor after an opening one."""
    wide = [unicodedata.east_asian_width(ch) in "WF" for ch in text]
    return [i for i in range(1, len(text))
            if text[i - 1] == " " and text[i] != " "
            or (wide[i - 1] or wide[i]) and " " not in text[i - 1:i + 1]
            and text[i] not in NO_BREAK_BEFORE and text[i - 1] not in NO_BREAK_AFTER]


def sheet_title_block(p: Paper, block: TitleBlock | None, labels: Mapping[str, str],
                      scale: str) -> tuple[Box, tuple[Item, ...]]:
    """A sheet's title block as its area on the paper and its items: the caller's block
    (or one named by ``labels["title"]``, sheet 1/1) with the drawing's scale and the
    title block's words from ``labels``."""
    block = block or TitleBlock(labels["title"], "", "", "1/1")
    block = replace(block, title=block.title or labels["title"], scale=scale,
                    labels={k: labels.get(k, TITLE_ENGLISH[k]) for k in TITLE_LABEL_KEYS})
    return title_block_box(p), tuple(title_block(p, block))
