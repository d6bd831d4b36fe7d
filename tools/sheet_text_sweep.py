"""Sweep the drawing sheets for crowded texts: ``python tools/sheet_text_sweep.py [CONTENT …]``.

Why: a sheet whose numbers run together ("105120135" under an A3 sheet's φ axis) is a
broken printout that no single test's few sheets may show. This builds each sheet as
``shaper drawing`` does (in this process, the file not written) over the task book's
data sets 方案 I–III, the default design and K = 2 and 2.9 designs; for the motion sheet
at 6, 12, 24 and 36 positions; on A0–A3, in English and Chinese; and checks each with
``tests/sheet_checks.crowded_texts`` (no two texts nearer than a word space) and for
captions cut with an ellipsis. It prints one line per sheet and a count per content.
With ``PYTHONPATH`` on an export of another commit it sweeps that commit's sheets (the
checker is this tree's). Only a developer's tool: 65 s of CPU for all 344 (77 s wall, load 3).
"""
from __future__ import annotations

import itertools
import os
import sys
from pathlib import Path

os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "tests"))

LOADS = ["--lever-mass", "20", "--lever-inertia", "1.1", "--ram-mass", "70", "--cut-force", "7000",
         "--cut-height", "80"]
CAM = ["--arm", "120", "--swing", "15", "--pressure", "40", "--rise", "60", "--dwell", "10", "--return", "60"]
GEAR = ["--z1", "13", "--z2", "40", "--module", "6", "--centre", "162"]
DESIGNS = {
    "方案I": ["--dims", "110,380,540", "--rod-ratio", "0.25", "--rpm", "60"],
    "方案II": ["--dims", "90,350,580", "--rod-ratio", "0.3", "--rpm", "64"],
    "方案III": ["--dims", "110,430,810", "--rod-ratio", "0.36", "--rpm", "72"],
    "default": ["--crank", "100", "--K", "1.4", "--stroke", "300", "--rpm", "40"],
    "K2.9 rod": ["--crank", "100", "--K", "2.9", "--stroke", "600", "--rod-ratio", "0.5", "--rpm", "40"],
    "K2.9": ["--crank", "100", "--K", "2.9", "--stroke", "600", "--rpm", "40"],
    "K2": ["--crank", "100", "--K", "2.0", "--stroke", "400", "--rpm", "60"],
}
EXTRA = {"motion": [], "forces": LOADS, "cam": CAM, "gear": GEAR}


def main(contents: list[str]) -> int:
    import shaperapp.drawing.render as render
    from cli_runner import shaper_in_process
    from sheet_checks import crowded_texts

    built = []
    render.write_sheet = lambda sheet, *args, **kwargs: built.append(sheet)     # keep, do not write
    for content in contents:
        sheets = crowded = cut_short = 0
        designs = ["-"] if content == "gear" else list(DESIGNS)
        counts = [6, 12, 24, 36] if content == "motion" else [0]
        for lang, name, size, count in itertools.product(("en", "zh"), designs, ("A0", "A1", "A2", "A3"), counts):
            built.clear()
            args = ["drawing", "--content", content, "--sheet", size, "--lang", lang, "-o", "unwritten.pdf",
                    *DESIGNS.get(name, []), *EXTRA[content]]
            args += ["--positions", str(count)] if count else []
            status, _, err = shaper_in_process(*args)
            if status:
                print(content, name, size, count, lang, "refused:", err.strip())
                continue
            bad = crowded_texts(built[0])
            cut = [t.text for t in built[0].items if hasattr(t, "text") and "…" in t.text]
            sheets, crowded, cut_short = sheets + 1, crowded + bool(bad), cut_short + bool(cut)
            print(f"{content} {name} {size} {count or ''} {lang}: {len(bad)} crowded"
                  + "".join(f"\n    {a.text!r} ~ {b.text!r} {d:.2f} mm" for a, b, d in bad[:4])
                  + (f"; cut: {cut}" if cut else ""))
        print(f"== {content}: {sheets} sheets, {crowded} with crowded texts, {cut_short} with a text cut")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:] or ["motion", "forces", "cam", "gear"]))
