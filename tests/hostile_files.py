"""A corpus of hostile design files, built under a test's tmp_path (never in git).

Each case is a function ``build(folder) -> path``. Special files (FIFOs, links to
/dev/zero, sockets, folders, sparse multi-gigabyte files) are made on the spot;
nothing points a test at a device path directly. Used by the core test (every case
refused by ``load_design``) and the GUI test (every case refused by the open action
with the design on screen unchanged).
"""
from __future__ import annotations

import json
import os
import socket
from pathlib import Path
from typing import Callable

import pytest

VALID = {"format": "shaper-design", "version": 1,
         "spec": {"mode": "synthesis", "crank": 100.0, "time_ratio": 1.4, "stroke": 300.0},
         "rpm": [40.0, 60.0], "step_deg": 1.0}


_SPEC_14 = '{"mode": "synthesis", "crank": 100.0, "time_ratio": 1.4, "stroke": 300.0}'
_SPEC_16 = '{"mode": "synthesis", "crank": 100.0, "time_ratio": 1.6, "stroke": 300.0}'
_GEAR = '{"z1": 13, "z2": 52, "module_mm": 4}'
_TAIL = '"rpm": [40, 60], "step_deg": 1'
# design files each valid but for one key written twice in one object, by that key
DUPLICATES = {
    "spec": f'{{"format": "shaper-design", "version": 1, "spec": {_SPEC_14}, "spec": {_SPEC_16}, {_TAIL}}}',
    "version": f'{{"format": "shaper-design", "version": 1, "version": 1, "spec": {_SPEC_14}, {_TAIL}}}',
    "time_ratio": ('{"format": "shaper-design", "version": 1, "spec": {"mode": "synthesis", "crank": 100.0, '
                   f'"time_ratio": 1.4, "time_ratio": 1.6, "stroke": 300.0}}, {_TAIL}}}'),
    "gear": f'{{"format": "shaper-design", "version": 1, "spec": {_SPEC_14}, {_TAIL}, "gear": {_GEAR}, "gear": {_GEAR}}}',
    "z1": ('{"format": "shaper-design", "version": 1, "spec": %s, %s, '
           '"gear": {"z1": 3, "z1": 13, "z2": 52, "module_mm": 4}}' % (_SPEC_14, _TAIL)),
}


def _doc(**changes) -> dict:
    doc = json.loads(json.dumps(VALID))
    for key, value in changes.items():
        if value is _DROP:
            doc.pop(key, None)
        else:
            doc[key] = value
    return doc


_DROP = object()


def _json_case(**changes) -> Callable[[Path], Path]:
    def build(folder: Path) -> Path:
        path = folder / "case.json"
        path.write_text(json.dumps(_doc(**changes)), encoding="utf-8")
        return path
    return build


def _spec_case(**fields) -> Callable[[Path], Path]:
    spec = dict(VALID["spec"], **fields)
    return _json_case(spec=spec)


def _raw_case(content: bytes) -> Callable[[Path], Path]:
    def build(folder: Path) -> Path:
        path = folder / "case.json"
        path.write_bytes(content)
        return path
    return build


def _text_case(text: str) -> Callable[[Path], Path]:
    return _raw_case(text.encode("utf-8"))


def _valid_with(spec_text: str) -> bytes:
    """The valid document with ``"crank": <spec_text>`` spliced in as raw JSON."""
    return ('{"format": "shaper-design", "version": 1, "spec": {"crank": %s}, '
            '"rpm": [40, 60], "step_deg": 1}' % spec_text).encode()


def _fifo(folder: Path) -> Path:
    path = folder / "fifo.json"
    os.mkfifo(path)
    return path


def _link_to(target: str) -> Callable[[Path], Path]:
    def build(folder: Path) -> Path:
        path = folder / "link.json"
        path.symlink_to(target)
        return path
    return build


def _folder(folder: Path) -> Path:
    path = folder / "folder.json"
    path.mkdir()
    return path


def _link_to_folder(folder: Path) -> Path:
    (folder / "real").mkdir()
    path = folder / "dirlink.json"
    path.symlink_to(folder / "real")
    return path


def _dangling(folder: Path) -> Path:
    path = folder / "dangling.json"
    path.symlink_to(folder / "nowhere.json")
    return path


def _loop(folder: Path) -> Path:
    a, b = folder / "a.json", folder / "b.json"
    a.symlink_to(b)
    b.symlink_to(a)
    return a


def _missing(folder: Path) -> Path:
    return folder / "missing.json"


def _socket(folder: Path) -> Path:
    path = folder / "s.json"
    if len(str(path)) > 100:
        pytest.skip("tmp_path too long for a unix socket")
    sock = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    sock.bind(str(path))
    sock.close()                      # the socket file stays in the folder
    return path


def _unreadable(folder: Path) -> Path:
    if os.geteuid() == 0:
        pytest.skip("root reads files whatever their mode")
    path = folder / "locked.json"
    path.write_text(json.dumps(VALID))
    path.chmod(0)
    return path


def _sparse_huge(folder: Path) -> Path:
    """5 GB of zeros that take no disk space: must be refused without reading it."""
    path = folder / "huge.json"
    with open(path, "wb") as handle:
        handle.truncate(5 * 10 ** 9)
    return path


def _just_over_cap(folder: Path) -> Path:
    """A valid document padded with spaces to one byte over the 1 MB cap."""
    body = json.dumps(VALID).encode()
    path = folder / "big.json"
    path.write_bytes(body + b" " * (1_000_001 - len(body)))
    return path


def _huge_string(folder: Path) -> Path:
    """Under the cap, but one field is a 900 kB string: refused with a short message."""
    return _spec_case(frame="x" * 900_000)(folder)


CASES: dict[str, Callable[[Path], Path]] = {
    # special files and paths
    "fifo": _fifo,
    "link_to_dev_zero": _link_to("/dev/zero"),
    "link_to_dev_null": _link_to("/dev/null"),
    "link_to_dev_urandom": _link_to("/dev/urandom"),
    "folder": _folder,
    "link_to_folder": _link_to_folder,
    "dangling_link": _dangling,
    "link_loop": _loop,
    "missing": _missing,
    "socket": _socket,
    "unreadable": _unreadable,
    "sparse_5_GB": _sparse_huge,
    "over_1_MB": _just_over_cap,
    "huge_string_field": _huge_string,
    # bytes and encodings
    "empty": _raw_case(b""),
    "nul_bytes": _raw_case(b"\x00" * 64),
    "bad_utf8": _raw_case(b'{"format": "shaper-design\xff\xfe"}'),
    "utf16": _raw_case(json.dumps(VALID).encode("utf-16")),
    "latin1": _raw_case('{"format": "shaper-design", "version": 1, "spec": {"mode": "é"}}'.encode("latin-1")),
    # JSON syntax and shape
    "broken": _text_case("{broken"),
    "not_json": _text_case("not json at all"),
    "trailing_garbage": _raw_case(json.dumps(VALID).encode() + b" }{"),
    "top_array": _text_case("[]"),
    "top_number": _text_case("42"),
    "deep_arrays": _raw_case(b"[" * 100_000 + b"]" * 100_000),
    "deep_objects_in_spec": _raw_case(_valid_with('{"a": ' * 50_000 + "1" + "}" * 50_000)),
    "nested_20_in_rpm": _json_case(rpm=json.loads("[" * 20 + "40" + "]" * 20)),
    # numbers
    "nan": _raw_case(_valid_with("NaN")),
    "infinity": _raw_case(_valid_with("Infinity")),
    "minus_infinity": _raw_case(_valid_with("-Infinity")),
    "float_overflow": _raw_case(_valid_with("1e400")),
    "int_400_digits": _raw_case(_valid_with("1" * 400)),
    "int_5000_digits": _raw_case(_valid_with("9" * 5000)),
    "bool_as_number": _spec_case(crank=True),
    "string_as_number": _spec_case(crank="100"),
    "null_as_number": _spec_case(crank=None),
    "list_as_number": _spec_case(crank=[100]),
    # format and version
    "format_missing": _json_case(format=_DROP),
    "format_other": _json_case(format="other-design"),
    "version_missing": _json_case(version=_DROP),
    "version_true": _json_case(version=True),
    "version_float": _json_case(version=1.0),
    "version_2": _json_case(version=2),
    "version_string": _json_case(version="1"),
    # keys and spec
    "spec_missing": _json_case(spec=_DROP),
    "spec_list": _json_case(spec=[100, 1.4, 300]),
    "spec_unknown_field": _spec_case(colour="red"),
    # a key twice in one object: json kept the last silently (issue 42)
    "duplicate_spec": _text_case(DUPLICATES["spec"]),
    "duplicate_top_key": _text_case(DUPLICATES["version"]),
    "duplicate_spec_field": _text_case(DUPLICATES["time_ratio"]),
    "duplicate_gear": _text_case(DUPLICATES["gear"]),
    "duplicate_z1": _text_case(DUPLICATES["z1"]),
    "mode_unknown": _spec_case(mode="magic"),
    "k_below_1": _spec_case(time_ratio=0.5),
    "inactive_frame_text": _spec_case(frame="ጼ"),
    "inactive_k_invalid": _spec_case(mode="dimensions", frame=386.37, lever=579.56, time_ratio=0.9),
    "inactive_rod_negative": _spec_case(rod_length=-5.0),
    "crank_almost_frame": _spec_case(mode="dimensions", crank=100.0, frame=100.0000001, lever=400.0,
                                     guide_rule="height", guide_height=300.0),
    "rod_too_short": _spec_case(variant="rod", rod_input="length", rod_length=1.0),
    # speeds
    "rpm_strings": _json_case(rpm=["40", "60"]),
    "rpm_true": _json_case(rpm=[True]),
    "rpm_denormal": _json_case(rpm=[1e-320]),
    "rpm_smallest_double": _json_case(rpm=[5e-324]),
    "rpm_text": _json_case(rpm="fast"),
    "rpm_empty": _json_case(rpm=[]),
    "rpm_17": _json_case(rpm=[40.0] * 17),
    "rpm_zero": _json_case(rpm=[0]),
    "rpm_negative": _json_case(rpm=[-40]),
    "rpm_null": _json_case(rpm=[None]),
    "rpm_object": _json_case(rpm={"a": 40}),
    # angle step
    "step_true": _json_case(step_deg=True),
    "step_smallest_double": _json_case(step_deg=5e-324),
    "step_zero": _json_case(step_deg=0),
    "step_string": _json_case(step_deg="1"),
    "step_too_fine": _json_case(step_deg=1e-5),
    # loads
    "forces_list": _json_case(forces=[1, 2]),
    "forces_negative_mass": _json_case(forces={"ram_mass_kg": -1}),
    "forces_gravity_text": _json_case(forces={"gravity": "yes"}),
    "forces_gravity_number": _json_case(forces={"gravity": 1}),
    "forces_offset_strings": _json_case(forces={"ram_cg_mm": ["1", "2"]}),
    "forces_offset_bools": _json_case(forces={"ram_cg_mm": [True, False]}),
    "forces_mass_bool": _json_case(forces={"ram_mass_kg": True}),
    "forces_unknown": _json_case(forces={"wheels": 4}),
    "forces_delta_zero": _json_case(forces={"delta": 0}),
}


def build_case(name: str, folder: Path) -> Path:
    """Make case ``name`` in a fresh sub-folder of ``folder``; return the path to open."""
    where = folder / name
    where.mkdir()
    return CASES[name](where)
