"""Drawings for paper and CAD: the course design's sheets and the mechanism as DXF.

Above the engine and the file formats it draws from (positions, polygons,
dynamics), below the CLI. Headless: ezdxf writes DXF; the PDF and SVG of a
sheet are painted by the GUI package from the same sheet description.
"""

# How a DXF writes its texts (``--cad-font``; here, free of ezdxf, for the CLI's options):
# "gb", TEXT entities in the GB styles (editable; AutoCAD and ZWCAD draw them with
# gbenor.shx/gbcbig.shx, LibreCAD in its wqy-unicode font: ``core.drawing.dxf``), or "outline", the filled outlines of a CJK TrueType font
# (``core.drawing.outline_text``), which every CAD program draws alike, LibreCAD too.
CAD_FONTS = ("gb", "outline")
