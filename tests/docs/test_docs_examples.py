"""Every ```python block of the README and of docs/ runs as written: an example that
imports a name from the wrong module (``summarize`` from ``core.forces.dynamics``) fails here."""
import re
from pathlib import Path

import pytest
from locations import ROOT

ROOT = ROOT
PAGES = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]
BLOCKS = [(page.name, i, block) for page in PAGES
          for i, block in enumerate(re.findall(r"```python\n(.*?)```",
                                               page.read_text(encoding="utf-8"), re.S))]


def test_the_docs_have_python_examples():
    assert BLOCKS


@pytest.mark.parametrize("page, index, code", BLOCKS, ids=[f"{p}#{i}" for p, i, _ in BLOCKS])
def test_python_example_runs(page, index, code, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    exec(compile(code, f"{page}#{index}", "exec"), {"__name__": "__doc_example__"})
