"""Count the sheets' squeezed, cut and smaller texts: ``python tools/sheet_text_widths.py OUT.json``,
then ``python tools/sheet_text_widths.py --compare BEFORE.json AFTER.json``.

Why: a text the PDF's font draws wider than the sheet's estimate is squeezed (condensed,
unevenly from cell to cell), a broken printout no single test's few sheets show. This builds
the four contents on A3 and A1, English and Chinese, the default design and 方案 I (the gear
sheet once per paper and language: 28 sheets) as ``shaper drawing`` does, in this process,
and records each text with its height and the least squeeze of its characters other than
CJK as ``shaperapp.widgets.sheet_paint`` draws them (an older tree without per-script
drawing: the whole text's squeeze, for a text with any letter or digit). With ``PYTHONPATH``
on an export of another commit (``git archive REV | tar -x -C DIR``) it records that
commit's sheets; ``--compare`` prints the counts of both and the texts set smaller or
larger. Only a developer's tool: about 4 s of CPU a tree.
"""
from __future__ import annotations

import collections
import itertools
import json
import os
import sys
from pathlib import Path

os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "tests"))

LOADS = "--lever-mass 20 --lever-inertia 1.1 --ram-mass 70 --cut-force 7000 --cut-height 80".split()
CAM = "--arm 120 --swing 15 --pressure 40 --rise 60 --dwell 10 --return 60".split()
GEAR = "--z1 13 --z2 40 --module 6 --centre 162".split()
DESIGNS = {"default": "--crank 100 --K 1.4 --stroke 300 --rpm 40".split(),
           "方案I": "--dims 110,380,540 --rod-ratio 0.25 --rpm 60".split()}
EXTRA = {"motion": [], "forces": LOADS, "cam": CAM, "gear": GEAR}


def cjk(text: str) -> bool:
    return any(ord(ch) >= 0x2E80 for ch in text)


def least_squeeze(item, paint, metrics, cap: float) -> float:
    """The least squeeze of ``item``'s runs' characters other than CJK as drawn."""
    squeeze = 1.0
    for run in item.runs():
        if hasattr(paint, "_segments"):
            squeeze = min([squeeze] + [q for part, _, q in paint._segments(run, metrics, cap)
                                       if part.strip() and not cjk(part[0])])
            continue
        natural = metrics.horizontalAdvance(run.text) * run.height / cap
        if natural > 0 and any(not cjk(ch) and not ch.isspace() for ch in run.text):
            squeeze = min(squeeze, run.width / natural)
    return squeeze


def record(path: str) -> None:
    from PySide6.QtGui import QFontMetricsF
    from PySide6.QtWidgets import QApplication

    import shaperapp.drawing.render as render
    import shaperapp.widgets.sheet_paint as paint
    from cli_runner import shaper_in_process
    from core.drawing.sheet import Text
    from shaperapp.widgets.fonts import prefer_simplified_chinese, report_font

    app = QApplication.instance() or QApplication([])
    prefer_simplified_chinese()
    fonts = {}
    for lang in ("en", "zh"):
        font = report_font("zh_CN" if lang == "zh" else "en")
        font.setPixelSize(100)
        fonts[lang] = QFontMetricsF(font)
    built, out = [], {}
    render.write_sheet = lambda sheet, *args, **kwargs: built.append(sheet)    # keep, do not write
    for content, size, lang, design in itertools.product(EXTRA, ("A3", "A1"), ("en", "zh"), DESIGNS):
        if content == "gear" and design != "default":
            continue
        built.clear()
        status, _, err = shaper_in_process("drawing", "--content", content, "--sheet", size, "--lang", lang,
                                           "-o", "unwritten.pdf", *DESIGNS[design], *EXTRA[content])
        if status:
            raise SystemExit(f"{content} {size} {lang} {design}: {err.strip()}")
        metrics = fonts[lang]
        out[f"{content} {size} {lang} {design}"] = [
            (item.text, item.height, least_squeeze(item, paint, metrics, metrics.capHeight()))
            for item in built[0].items if isinstance(item, Text)]
    del app
    Path(path).write_text(json.dumps(out, ensure_ascii=False), encoding="utf-8")
    print(f"{len(out)} sheets recorded in {path}")


def compare(before_path: str, after_path: str) -> None:
    tables = [json.loads(Path(p).read_text(encoding="utf-8")) for p in (before_path, after_path)]
    for name, table in zip(("before", "after"), tables):
        rows = [row for sheet in table.values() for row in sheet]
        latin = sum(1 for text, _, q in rows if q < 0.99 and not cjk(text))
        mixed = sum(1 for text, _, q in rows if q < 0.99 and cjk(text))
        cut = sum(1 for text, _, _ in rows if "…" in text)
        print(f"{name}: {len(table)} sheets, {len(rows)} texts; squeezed by more than 1 %: {latin} without "
              f"Chinese, {mixed} letters or digits beside Chinese; cut with …: {cut}")
    before, after = tables
    for sheet in before:
        heights = [collections.Counter((text, h) for text, h, _ in t[sheet]) for t in (before, after)]
        gone, new = heights[0] - heights[1], heights[1] - heights[0]
        if gone or new:
            print(f"{sheet}: before {dict(gone)}; after {dict(new)}")


if __name__ == "__main__":
    if sys.argv[1:2] == ["--compare"]:
        compare(*sys.argv[2:4])
    else:
        record(sys.argv[1])
