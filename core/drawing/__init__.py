"""Drawings for paper and CAD: the course design's sheets and the mechanism as DXF.

Above the engine and the file formats it draws from (positions, polygons,
dynamics), below the CLI. Headless: ezdxf writes DXF; the PDF and SVG of a
sheet are painted by the GUI package from the same sheet description.
"""
