"""What a wheel holds: setuptools puts in it only the packages pyproject.toml names, and an
editable install (the README's) finds the others anyway, so a package missing from the
list breaks only ``pip install .`` and a built wheel (seven were missing: core.base,
core.course_design, core.files, core.forces, core.linkage, core.space, shaperapp.parts;
the installed ``shaper`` stopped at its first import)."""
from __future__ import annotations

import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def test_pyproject_names_every_package_of_the_source_tree():
    config = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))["tool"]["setuptools"]
    named = set(config["packages"])
    found = {".".join(init.parent.relative_to(ROOT).parts)
             for top in ("core", "shaperapp") for init in (ROOT / top).rglob("__init__.py")
             if "__pycache__" not in init.parts}
    mapped = {name for name, folder in config["package-dir"].items() if (ROOT / folder / "__init__.py").is_file()}
    assert named == found | mapped, (sorted((found | mapped) - named), sorted(named - found - mapped))
