"""A sheet's texts in its DXF: TEXT entities written by ``dxf_text_entity.PackedText`` (their
attributes by ``dxf_tags.tags``) write what ezdxf's own ``add_text`` and export write, to
the character; the polylines' common AcDbEntity part likewise (``dxf_polyline``)."""
from __future__ import annotations

import io

from ezdxf.entities.dxfns import DXFNamespace
from ezdxf.lldxf.tagwriter import TagWriter

from core.drawing import sheet_dxf
from core.drawing.dxf import dxf_text, new_document
from core.drawing.dxf_text_entity import add_text
from core.drawing.motion import motion_sheet
from core.drawing.sheet import Polyline, Sheet, Text, paper
from core.linkage.geometry import synthesize

TEXTS = (Text("L_1 = 110 mm", (20.0, 30.0), 5.0, "lb"), Text("曲柄 O₂A", (120.5, 33.25), 3.5, "cm", 37.5),
         Text("F_I6", (200.0, 100.0), 3.5, "rt", 90.0, subscripts=((1, 3),)),
         Text("a^k_A4A3", (250.0, 120.0), 2.5, "ct", 271.0, subscripts=((4, 8),), superscripts=((2, 3),)),
         Text("%%c 20", (10.0, 10.0), 7.0, "rm", -15.0, layer="DIMENSIONS"))


def _sections(doc) -> str:
    """The DXF's BLOCKS and ENTITIES sections as written (its header has a new GUID and
    time every time)."""
    return dxf_text(doc).split("BLOCKS", 1)[1].split("OBJECTS", 1)[0]


def _ezdxf_texts(monkeypatch):
    """``sheet_dxf`` as before the cut: each text by ezdxf's own ``add_text``."""
    def plain(msp, text, height, rotation, attribs):
        return msp.add_text(text, height=height, rotation=rotation, dxfattribs=attribs)
    monkeypatch.setattr(sheet_dxf, "add_text", plain)


def test_texts_write_the_dxf_ezdxf_writes(monkeypatch):
    sheet = Sheet(paper("A3"), TEXTS + (Polyline(((0.0, 0.0), (5.0, 7.5), (9.0, 1.0)), closed=True),))
    ours = _sections(sheet_dxf.sheet_document(sheet))
    _ezdxf_texts(monkeypatch)
    theirs = _sections(sheet_dxf.sheet_document(sheet))
    assert ours.count("\nTEXT\n") == theirs.count("\nTEXT\n") >= 8      # a run per sub- or superscript
    assert ours == theirs


def test_a_motion_sheet_writes_the_dxf_ezdxf_writes(monkeypatch):
    """Every text of a real sheet: dimensions, numbers, Chinese, every alignment and angle."""
    design = synthesize(100.0, 1.46, 300.0, guide="sagitta", rod_ratio=0.3)
    sheet = motion_sheet(design, 60.0, paper("A1"), labels={"title": "运动分析"}).sheet
    ours = _sections(sheet_dxf.sheet_document(sheet))
    _ezdxf_texts(monkeypatch)
    assert ours.count("\nTEXT\n") > 300
    assert ours == _sections(sheet_dxf.sheet_document(sheet))


def test_texts_are_written_without_the_attribute_machinery(monkeypatch):
    """The cut itself: ezdxf's namespace exported each text's 29 attributes one at a time
    (the document's header, tables and blocks still go through it, the same for both)."""
    calls = []
    export = DXFNamespace._export_dxf_attribute_optional
    monkeypatch.setattr(DXFNamespace, "_export_dxf_attribute_optional",
                        lambda self, *a: calls.append(1) or export(self, *a))
    counts = []
    for items in ((), TEXTS):
        calls.clear()
        dxf_text(sheet_dxf.sheet_document(Sheet(paper("A3"), items)))
        counts.append(len(calls))
    assert counts[1] == counts[0] > 0


def test_a_writer_that_forces_optional_attributes_gets_ezdxfs_export():
    ours, theirs = new_document(), new_document()
    add_text(ours.modelspace(), "H = 300", 3.5, 12.0, {"layer": "0", "style": "GB"})
    theirs.modelspace().add_text("H = 300", height=3.5, rotation=12.0, dxfattribs={"layer": "0", "style": "GB"})
    texts = []
    for doc in (ours, theirs):
        stream = io.StringIO()
        writer = TagWriter(stream, write_handles=True, dxfversion=doc.dxfversion)
        writer.force_optional = True
        doc.modelspace().query("TEXT").first.export_dxf(writer)
        texts.append(stream.getvalue())
    assert texts[0] == texts[1] and " 50\n12.0\n" in texts[0]
