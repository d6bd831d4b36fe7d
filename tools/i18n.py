"""Maintain the Chinese catalogue: ``python tools/i18n.py update|todo|apply|merge|release``.

- ``update``   run pyside6-lupdate over every module of shaperapp (new strings appear
               as unfinished, vanished ones are dropped) and recompile the .qm.
- ``todo``     print the untranslated strings as JSON {context: {source: ""}}.
- ``apply F``  take translations from such a JSON file F (filled in) and recompile.
- ``merge T``  copy translations from another .ts T (e.g. a branch's) where ours are missing.
- ``release``  recompile resources/shaperapp_zh_CN.qm from the .ts.

Only a developer's tool: the app reads the compiled .qm.
"""
from __future__ import annotations

import json
import os
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
TS = ROOT / "resources" / "shaperapp_zh_CN.ts"
QM = ROOT / "resources" / "shaperapp_zh_CN.qm"


def sources() -> list[str]:
    return sorted(str(p) for p in (ROOT / "shaperapp").rglob("*.py"))


def _tree() -> ET.ElementTree:
    return ET.parse(TS)


def _messages(tree: ET.ElementTree):
    for context in tree.getroot().iter("context"):
        name = context.find("name").text
        for msg in context.iter("message"):
            yield name, msg.find("source").text, msg.find("translation")


def _write(tree: ET.ElementTree) -> None:
    body = ET.tostring(tree.getroot(), encoding="unicode")
    TS.write_text('<?xml version="1.0" encoding="utf-8"?>\n<!DOCTYPE TS>\n' + body + "\n",
                  encoding="utf-8")


def release() -> None:
    """Compile beside the .qm, then put the new file in its place: a running app maps its
    .qm into memory (QTranslator), and rewriting that file in place left it showing English
    and then killed it with SIGBUS, as an app started from this checkout was."""
    fresh = QM.with_name(QM.name + ".new")
    subprocess.run(["pyside6-lrelease", str(TS), "-qm", str(fresh)], check=True, capture_output=True)
    os.replace(fresh, QM)


def update() -> None:
    subprocess.run(["pyside6-lupdate", *sources(), "-ts", str(TS), "-no-obsolete", "-locations", "none"], check=True,
                   capture_output=True)
    release()


def todo() -> dict[str, dict[str, str]]:
    out: dict[str, dict[str, str]] = {}
    for context, source, tr in _messages(_tree()):
        if not tr.text or tr.get("type") == "unfinished":
            out.setdefault(context, {})[source] = ""
    return out


def _fill(lookup) -> int:
    tree = _tree()
    count = 0
    for context, source, tr in _messages(tree):
        if tr.text and tr.get("type") != "unfinished":
            continue
        text = lookup(context, source)
        if text:
            tr.text = text
            tr.attrib.pop("type", None)
            count += 1
    _write(tree)
    release()
    return count


def apply(path: str) -> int:
    table = json.loads(Path(path).read_text(encoding="utf-8"))
    return _fill(lambda c, s: table.get(c, {}).get(s))


def merge(path: str) -> int:
    other = {(c, s): tr.text for c, s, tr in _messages(ET.parse(path))
             if tr.text and tr.get("type") not in ("unfinished", "obsolete", "vanished")}
    return _fill(lambda c, s: other.get((c, s)))


def main(argv: list[str]) -> int:
    if not argv:
        print(__doc__)
        return 2
    command, rest = argv[0], argv[1:]
    if command == "update":
        update()
    elif command == "todo":
        print(json.dumps(todo(), ensure_ascii=False, indent=1))
    elif command == "apply":
        print(f"{apply(rest[0])} translations applied")
    elif command == "merge":
        print(f"{merge(rest[0])} translations merged")
    elif command == "release":
        release()
    else:
        print(__doc__)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
