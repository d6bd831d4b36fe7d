"""Checks shared by the robustness tests: outputs hold only finite numbers, FIFOs are read."""
import csv
import io
import json
import math
import re
import threading


def finite_json(text: str):
    """Parse JSON, refusing NaN/Infinity literals, and require every float to be finite."""
    def refuse(name):
        raise AssertionError(f"{name} in JSON output")

    def walk(value):
        if isinstance(value, dict):
            for item in value.values():
                walk(item)
        elif isinstance(value, list):
            for item in value:
                walk(item)
        elif isinstance(value, float):
            assert math.isfinite(value), value

    document = json.loads(text, parse_constant=refuse)
    walk(document)
    return document


def finite_csv(text: str) -> tuple[list[str], list[list[str]]]:
    """Header and rows of a CSV whose cells are all finite numbers or empty (undefined)."""
    rows = list(csv.reader(io.StringIO(text)))
    assert len({len(r) for r in rows}) == 1, "ragged CSV"
    for row in rows[1:]:
        for cell in row:
            assert cell == "" or math.isfinite(float(cell)), row
    return rows[0], rows[1:]


def read_fifo_in_background(path) -> tuple[threading.Thread, list[str]]:
    """Start a thread that reads the FIFO ``path`` to its end; join it, then read the list."""
    received: list[str] = []
    reader = threading.Thread(target=lambda: received.append(path.read_text()), daemon=True)
    reader.start()
    return reader, received


def error_names(stderr: str) -> list[str]:
    """What the one error line names: the option(s) or argument before the first ': '
    (``-o/--output`` gives both, ``--crank (L1)`` the option); none for the user's
    own stray words. Fails unless stderr is exactly one ``shaper: error:`` line."""
    lines = stderr.splitlines()
    assert len(lines) == 1, stderr
    assert lines[0].startswith("shaper: error: ") and "Traceback" not in stderr
    message = lines[0][len("shaper: error: "):]
    if message.startswith("ambiguous option:") or ": unknown option; " in message \
            or ": not an argument of 'shaper " in message:
        return []                       # the user's own mistyped word (with a close match)
    # argparse's "unrecognized arguments: 60" named no option (issue 42): never accepted
    if message.startswith("argument "):
        head = re.match(r"argument (\S+?):", message).group(1)
    else:
        head = re.sub(r" \((L[1-4]|default|from \$\w+)\)$", "", message.split(": ")[0])
    return head.split("/")


def without_reworded(raw: bytes, columns) -> bytes:
    """A CSV with the cells of ``columns`` emptied, every other cell as it was written (the
    lines parsed and written again as CSV, quoting where needed)."""
    import csv
    import io
    lines = raw.decode("utf-8").split("\n")
    names = next(csv.reader([lines[0]]))
    blank = {i for i, name in enumerate(names) if name in set(columns)}
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\n")
    for line in lines[1:]:
        if line:
            writer.writerow(["" if i in blank else cell for i, cell in enumerate(next(csv.reader([line])))])
    return (lines[0] + "\n" + out.getvalue()).encode("utf-8")


def golden_digest(raw: bytes, case: dict) -> str:
    """The SHA-256 to compare with the case's: of the file as the base commit would have
    written it (:func:`as_golden_wrote`), and where the case names columns of message text
    reworded since (``columns_reworded_since``: a refusal's advice, not a number), with
    those cells emptied, against ``sha256_reworded``, the base commit's own file emptied
    alike; every number is still compared byte for byte."""
    import hashlib
    wrote = as_golden_wrote(raw, case)
    reworded = case.get("columns_reworded_since")
    if reworded:
        return hashlib.sha256(without_reworded(wrote, reworded)).hexdigest()
    return hashlib.sha256(wrote).hexdigest()


def golden_sha(case: dict) -> str:
    return case["sha256_reworded"] if case.get("columns_reworded_since") else case["sha256"]


def as_golden_wrote(raw: bytes, case: dict) -> bytes:
    """A CSV written now, as tests/data/csv_golden.json's base commit would have written it:
    without the columns the case says were added since (``columns_added_since``), so the
    base commit's columns are still compared byte for byte."""
    added = set(case.get("columns_added_since", ()))
    if not added:
        return raw
    lines = raw.split(b"\n")
    keep = [i for i, name in enumerate(lines[0].split(b",")) if name.decode() not in added]
    return b"\n".join(b",".join(line.split(b",")[i] for i in keep) if line else line for line in lines)
