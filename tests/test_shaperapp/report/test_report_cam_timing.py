"""The cam's timing reads as what it is: ``shaper cam`` printed 'rise starts at crank angle
207.121 ° (cut ends at 186.377 °, 201.487 ° clear)' and the Chinese report '…（切削终止于
186.377 °，间隔 201.487 °）', where 201.487° is the crank's turn from the end of the cut to the
start of the next, not the gap before the rise (20.744°) that a teacher subtracts. The span
is checked against the cut's start and end of ``shaper table`` (an independent solution of
the ram's position) and must be named as the turn to the next cut, in both languages."""
from __future__ import annotations

import json
import re

import pytest

from cli_runner import shaper_in_process

DESIGN = ("--dims", "110,380,540", "--rod-ratio", "0.25", "--guide", "sagitta", "--rpm", "60")
CAM = ("--arm", "125", "--swing", "15", "--pressure", "40", "--rise", "75", "--dwell", "10", "--return", "75")


def test_the_turn_to_the_next_cut_is_named_so(qapp):
    from shaperapp.report.cam import value_text
    from shaperapp.widgets import i18n
    status, out, err = shaper_in_process("cam", *CAM, *DESIGN)
    assert status == 0, err
    line = next(t for t in out.splitlines() if t.startswith("rise starts at crank angle"))
    status, table, err = shaper_in_process("table", *DESIGN, "--json")
    assert status == 0, err
    rows = {r["name"]: r["crank_deg"] for r in json.loads(table) if r["name"]}
    value = line[len("rise starts at crank angle"):].strip()
    phase, end, span = (float(v) for v in re.findall(r"\d+\.\d+", value))
    assert end == pytest.approx(rows["cut_end"], abs=5e-4)
    assert span == pytest.approx(360.0 + rows["cut_start"] - rows["cut_end"], abs=1e-3)
    assert value == f"{phase:.3f}° (cut ends at {end:.3f}°, the next starts {span:.3f}° later)"
    i18n.set_language("zh_CN")
    try:
        chinese = value_text(value)
    finally:
        i18n.set_language("en")
    assert chinese == f"{phase:.3f}° （切削终止于 {end:.3f}°，再转 {span:.3f}° 开始下一次切削）"
