"""DXF attributes written as ezdxf writes them, without its per-attribute machinery.

Why: ezdxf writes every attribute of every entity through its generic namespace (the
attribute's definition looked up, the DXF version checked, a tag object made and written
one at a time): for a sheet's TEXT entities that was some 0.2 ms each, and their common
AcDbEntity part (15 attributes, most of them absent) more than half of it. Here the same
rule over a fixed list, each tag formatted by ezdxf's own ``dxftag``; the packed entities
(:mod:`.dxf_text_entity`, :mod:`.dxf_polyline`) fall back to ezdxf's export wherever a
writer or an entity is not the plain case this covers, and the tests compare the written
text with ezdxf's to the character.
"""
from __future__ import annotations

from ezdxf.entities.dxfgfx import DXFGraphic, acdb_entity
from ezdxf.lldxf.const import DXF12, SUBCLASS_MARKER
from ezdxf.lldxf.tagwriter import AbstractTagWriter, TagWriter
from ezdxf.lldxf.attributes import DefSubclass, XType
from ezdxf.lldxf.types import TAG_STRING_FORMAT, dxftag

Plan = tuple[str, tuple]


def plan(subclass: DefSubclass, names: tuple[str, ...], marker: bool = True) -> Plan:
    """The subclass's marker tag ('' without ``marker``) and its attributes ``names``, in the
    order ezdxf's export of that subclass writes them."""
    return (TAG_STRING_FORMAT % (SUBCLASS_MARKER, subclass.name) if marker else "",
            tuple(subclass.attribs[name] for name in names))


def tags(entity, part: Plan, version: str) -> str:
    """The part's tags for ``entity`` as ``DXFNamespace.export_dxf_attribs`` writes them to a
    writer of DXF ``version`` that does not force optional attributes: an attribute newer
    than the version left out, a missing one its default unless optional, none where that
    is None, an optional one left out where equal to its default."""
    values = entity.dxf.__dict__           # what DXFNamespace.get reads, callbacks aside
    out = [part[0]]
    for attrib in part[1]:
        if version < attrib.dxfversion:
            continue
        value = values.get(attrib.name)
        if value is None and attrib.xtype == XType.callback:
            value = attrib.get_callback_value(entity)
        if value is None and not attrib.optional:
            value = attrib.default
        if value is None or (attrib.optional and attrib.default is not None and attrib.default == value):
            continue
        out.append(dxftag(attrib.code, value).dxfstr())
    return "".join(out)


def plain(tagwriter: AbstractTagWriter, entity: DXFGraphic) -> bool:
    """Whether ``tagwriter`` and ``entity`` are the case the packed export writes: ezdxf's text
    writer, newer than R12, optional attributes not forced, no proxy graphic."""
    return (type(tagwriter) is TagWriter and not tagwriter.force_optional and tagwriter.dxfversion > DXF12
            and not entity.proxy_graphic)


# DXFGraphic.export_acdb_entity's attributes, in its order
ENTITY = plan(acdb_entity, ("paperspace", "layer", "linetype", "material_handle", "color", "lineweight",
                            "ltscale", "invisible", "true_color", "color_name", "transparency",
                            "plotstyle_enum", "plotstyle_handle", "shadow_mode", "visualstyle_handle"))
