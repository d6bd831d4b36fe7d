"""The Chinese catalogue covers every UI string, and the shipped .qm matches the .ts.

A new ``self.tr`` string without a translation fails here, not in front of a user.
"""
import shutil
import subprocess
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
from PySide6.QtCore import QTranslator
from locations import ROOT

ROOT = ROOT
TS = ROOT / "resources" / "shaperapp_zh_CN.ts"
QM = ROOT / "resources" / "shaperapp_zh_CN.qm"


def messages(path):
    out = {}
    for context in ET.parse(path).getroot().iter("context"):
        name = context.find("name").text
        for msg in context.iter("message"):
            tr = msg.find("translation")
            if tr.get("type") in ("obsolete", "vanished"):
                continue
            out[(name, msg.find("source").text)] = (tr.text, tr.get("type"))
    return out


def test_every_string_is_translated():
    entries = messages(TS)
    assert len(entries) > 200
    untranslated = [src for src, (text, kind) in entries.items() if not text or kind == "unfinished"]
    assert untranslated == []


@pytest.mark.skipif(shutil.which("pyside6-lupdate") is None, reason="pyside6-lupdate not installed")
def test_catalogue_lists_every_source_string(tmp_path):
    fresh = tmp_path / "fresh.ts"
    sources = sorted(str(p) for p in (ROOT / "shaperapp").rglob("*.py"))
    subprocess.run(["pyside6-lupdate", *sources, "-ts", str(fresh)], check=True, capture_output=True)
    missing = set(messages(fresh)) - set(messages(TS))
    assert missing == set(), "run the translation update described in docs/architecture.md"


def test_compiled_catalogue_matches_source():
    translator = QTranslator()
    assert translator.load(str(QM))
    for (context, source), (text, _) in messages(TS).items():
        assert translator.translate(context, source) == text, (context, source)
