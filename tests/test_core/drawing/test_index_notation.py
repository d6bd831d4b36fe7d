"""The sheets' index notation (issue 32, item 6): a caption or a translated string writes
an index after an underscore, and the sheet sets it as a subscript, so M_m, J_F, ΔW_max,
ω_max and μ_l no longer print with a literal underscore (PDF, SVG and DXF alike)."""
from __future__ import annotations

import re

import pytest
from hypothesis import assume, given
from hypothesis import strategies as st

from core.cam import CamInputs, Program, design_cam
from core.drawing import cam_sheet, forces, motion
from core.drawing.sheet import Text, marked, paper
from core.drawing.cells import cell_text, table
from core.forces.masses import MassProperties, masses_for_design
from core.linkage.geometry import synthesize

BLOCK = synthesize(100.0, 1.4, 300.0)
LOADS = MassProperties(lever_mass_kg=20.0, lever_inertia_kg_m2=1.1, ram_mass_kg=70.0,
                       cut_force_N=7000.0, cut_height_mm=80.0)
LATIN_GREEK = "abcmxFIOWαδψωρμ"
PLAIN = "ABC xyz 曲柄，()=/·− 12"


def subscripted(text: Text) -> list[tuple[str, str]]:
    """(what precedes, the index) for each subscript span."""
    return [(text.text[:a], text.text[a:b]) for a, b in text.subscripts]


@pytest.mark.parametrize("caption, plain, indices", [
    ("Mean driving torque M_m", "Mean driving torque Mm", ["m"]),
    ("Flywheel J_F = ΔW_max/(ω²δ)", "Flywheel JF = ΔWmax/(ω²δ)", ["F", "max"]),
    ("Follower ω_max / α_max", "Follower ωmax / αmax", ["max", "max"]),
    ("Frame O_2O_4, L_2", "Frame O2O4, L2", ["2", "4", "2"]),
    ("δ_0′ = 60°", "δ0′ = 60°", ["0"]),
    ("平均驱动力矩 M_m", "平均驱动力矩 Mm", ["m"]),
    ("需加飞轮 J_F − J_e", "需加飞轮 JF − Je", ["F", "e"]),
    ("M_m虚线", "Mm虚线", ["m"]),                  # a Chinese word right after an index
    ("no index here: snake_", "no index here: snake_", []),
    ("v_w,max", "vw,max", ["w,max"]),              # one index of two parts (the answer key's heading)
    ("v_r,max, |a|_max", "vr,max, |a|max", ["r,max", "max"]),
    ("μ_l, μ_s", "μl, μs", ["l", "s"]),            # a comma and a space end it
])
def test_marked_examples(caption, plain, indices):
    text, spans = marked(caption)
    assert text == plain
    assert [text[a:b] for a, b in spans] == indices


@given(st.lists(st.tuples(st.text(PLAIN, max_size=6),
                          st.one_of(st.text(LATIN_GREEK, min_size=1, max_size=4),
                                    st.text("0123456789", min_size=1, max_size=3))), max_size=5))
def test_marked_is_the_text_without_the_marks_and_spans_are_the_indices(parts):
    """Written as plain parts each followed by "_" and an index, the notation reads back as
    the parts and indices joined, with exactly the indices as spans (when an index is not
    followed by more of its own kind, or by a comma and a letter or digit, which would
    lengthen it)."""
    def kind(ch: str) -> str:
        return "digit" if ch.isdigit() else "letter" if ch in LATIN_GREEK or ch in "ABCxyz" else "other"
    for (_, index), (after, _) in zip(parts, parts[1:]):
        assume(not after or kind(after[0]) != kind(index[0]))
        assume(not (after[:1] == "," and after[1:2] and kind(after[1]) != "other"))
    caption = "".join(f"{p}_{i}" for p, i in parts)
    text, spans = marked(caption)
    assert text == "".join(p + i for p, i in parts)
    assert [text[a:b] for a, b in spans] == [i for _, i in parts]


def all_texts(sheet) -> list[Text]:
    return [t for t in sheet.items if isinstance(t, Text)]


def sheets():
    design_masses = masses_for_design(BLOCK, LOADS)
    cam = design_cam(CamInputs(120.0, Program(15.0, 60.0, 10.0, 60.0)), BLOCK)
    return {"motion": motion.motion_sheet(BLOCK, 40.0, paper("A1")).sheet,
            "forces": forces.forces_sheet(BLOCK, 40.0, design_masses, paper("A1")).sheet,
            "cam": cam_sheet.cam_sheet(cam, 40.0, paper("A1")).sheet}


@pytest.fixture(scope="module")
def drawn():
    return sheets()


@pytest.mark.parametrize("name", ["motion", "forces", "cam"])
def test_no_sheet_text_holds_an_underscore(drawn, name):
    assert [t.text for t in all_texts(drawn[name]) if "_" in t.text] == []


def test_forces_sheet_sets_m_m_j_f_and_delta_w_max_as_subscripts(drawn):
    found = {pair for t in all_texts(drawn["forces"]) for pair in subscripted(t)}
    wanted = {("Mean driving torque M", "m"), ("Energy fluctuation ΔW", "max"),
              ("Flywheel J", "F"), ("Mean reduced inertia J", "e")}
    assert wanted <= found
    assert any(index == "max" and before.endswith("ΔW") and "J" in t.text
               for t in all_texts(drawn["forces"]) for before, index in subscripted(t))


@pytest.mark.parametrize("name, letters", [
    ("motion", {"l", "s", "v", "a", "φ"}), ("forces", {"l", "F", "M", "E", "φ"}),
    ("cam", {"l", "ψ", "ω", "α", "δ"})])
def test_every_scale_mu_has_its_index_as_a_subscript(drawn, name, letters):
    """μ_l, μ_v … on every caption and chart: the μ followed by its subscript index, and no
    μ followed by a plain letter."""
    texts = all_texts(drawn[name])
    indices = {t.text[a:b] for t in texts for a, b in t.subscripts if t.text[a - 1:a] == "μ"}
    assert letters <= indices
    starts = {(id(t), a) for t in texts for a, _ in t.subscripts}
    plain_mu = [t.text for t in texts for m in re.finditer("μ", t.text) if (id(t), m.end()) not in starts]
    assert plain_mu == []


def test_cam_sheet_sets_omega_max_and_the_sector_angles_as_subscripts(drawn):
    found = {index for t in all_texts(drawn["cam"]) for _, index in subscripted(t)}
    assert {"max", "0", "s", "min"} <= found


def test_table_reads_the_notation_but_a_cell_of_user_text_does_not():
    items = table((0.0, 100.0), (60.0, 40.0), [("Mean driving torque M_m", "300.8 N·m")])
    (label,) = [t for t in items if isinstance(t, Text) and t.text.startswith("Mean")]
    assert label.text == "Mean driving torque Mm" and subscripted(label) == [("Mean driving torque M", "m")]
    name = cell_text("my_design_2", (0.0, 0.0, 80.0, 8.0))         # the title block's cells
    assert name.text == "my_design_2" and name.subscripts == ()
