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


def source_fingerprint(*packages: str) -> str:
    """A hash of every file of the named packages (their sources and data, compiled
    bytecode left out): what a made file depends on beyond its inputs. Why: the version
    stays as it is from one fix to the next, so a stamp of the version alone kept files a
    fixed build would make otherwise (``shaper class``'s "up to date" students). A package
    that cannot be found counts by its name."""
    import hashlib
    from importlib.util import find_spec
    from pathlib import Path
    digest = hashlib.sha256()
    for name in packages:
        digest.update(name.encode() + b"\0")
        spec = find_spec(name)
        for folder in (spec.submodule_search_locations or []) if spec is not None else []:
            root = Path(folder)
            for path in sorted(p for p in root.rglob("*") if p.is_file() and "__pycache__" not in p.parts):
                digest.update(path.relative_to(root).as_posix().encode() + b"\0" + path.read_bytes() + b"\0")
    return digest.hexdigest()
