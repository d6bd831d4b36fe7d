"""The installed version, read from the package metadata only when asked: reading it
(``importlib.metadata``) costs 15 ms, and importing nothing else keeps ``shaper --version``
at the interpreter's own start-up."""
from __future__ import annotations


def version_text(prog: str) -> str:
    """'shaper 0.1.0', or 'shaper unknown' when the package is not installed."""
    from importlib import metadata
    try:
        version = metadata.version("shaper-designer")
    except metadata.PackageNotFoundError:
        version = "unknown"
    return f"{prog} {version}"
