"""A sheet's texts as DXF TEXT entities whose own tags are written in one piece.

Why: a student's four sheets hold some 1500 TEXT entities, and ezdxf writes each of
their attributes through its generic namespace, some 0.2 ms a text, 3 % of a ``shaper
class`` student (py-spy, docs/performance.md). The tags are ezdxf's own, in
``Text.export_entity``'s order, written by :func:`.dxf_tags.tags`; the tests compare the
written text with ezdxf's to the character (``test_sheet_dxf_text.py``).
"""
from __future__ import annotations

from ezdxf.entities import factory
from ezdxf.entities.text import Text, acdb_text, acdb_text2
from ezdxf.lldxf.tagwriter import AbstractTagWriter
from ezdxf.math import Vec3

from .dxf_tags import ENTITY, plain, plan, tags

# DXFGraphic.export_acdb_entity's part, then Text.export_acdb_text's and export_acdb_text2's
PARTS = (ENTITY,
         plan(acdb_text, ("insert", "height", "text", "thickness", "rotation", "oblique", "style", "width",
                          "text_generation_flag", "halign", "align_point", "extrusion")),
         plan(acdb_text2, ("valign",)))


class PackedText(Text):
    """A TEXT whose own tags are written in one string where :func:`.dxf_tags.plain` holds;
    ezdxf's own export otherwise (a binary DXF, an audit's tag collector, R12)."""

    def export_entity(self, tagwriter: AbstractTagWriter) -> None:
        if not plain(tagwriter, self):
            super().export_entity(tagwriter)
            return
        version = tagwriter.dxfversion
        tagwriter.write_str("".join(tags(self, part, version) for part in PARTS))


def add_text(msp, text: str, height: float, rotation: float, attribs: dict) -> PackedText:
    """``msp.add_text(text, height=height, rotation=rotation, dxfattribs=attribs)`` as a
    :class:`PackedText`: the same entity, handle and DXF text."""
    dxfattribs = dict(attribs)                  # add_text's own steps
    dxfattribs["text"] = str(text)
    dxfattribs["height"] = float(height)
    dxfattribs["rotation"] = float(rotation)
    dxfattribs.setdefault("insert", Vec3())
    entity = PackedText.new(dxfattribs=dxfattribs)
    factory.bind(entity, msp.doc)
    msp.add_entity(entity)
    return entity
