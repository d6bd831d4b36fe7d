"""Reading design files defensively: all or nothing, never blocking, bounded.

A design file is small JSON written by the GUI (``core.files.io.save_design``).
Anything else — a FIFO, a device, a link to /dev/zero, a huge or deeply
nested document, bools or strings where numbers belong, NaN, an unknown
version — is refused with :class:`FileFormatError` and one plain sentence
that names the file. Nothing here computes a design beyond validating it.
"""
from __future__ import annotations

import errno
import json
import math
import os
import re
import stat
from dataclasses import fields
from typing import TYPE_CHECKING, Any

import numpy as np

from core.base.errors import DesignError, FileFormatError
from core.linkage.kinematics import angle_count, check_file_samples, check_rpms
from core.linkage.spec import Spec

if TYPE_CHECKING:
    from core.forces.masses import MassProperties

FILE_FORMAT = "shaper-design"
FILE_VERSION = 1
MAX_FILE_BYTES = 1_000_000
"""A design file is a few hundred bytes; anything over 1 MB is refused unread."""
MAX_DEPTH = 16
"""Deepest nesting of arrays/objects accepted (a design file needs 3)."""
MAX_INT_DIGITS = 20
"""Longer integer literals are refused before Python turns them into huge ints."""
DEFAULT_FILE_RPMS = (40.0, 60.0)
DEFAULT_FILE_STEP = 1.0
PART_KEYS = ("cam", "gear")
"""The parts a design file may hold beside the linkage, speeds and loads, each validated on
reading and kept as written: a reader that does not edit a part must write it back."""
OWN_KEYS = ("format", "version", "spec", "rpm", "step_deg", "forces", "masses", "defaulted")
"""The keys of a loaded design that are not parts: the file's own, and what :func:`load_design`
adds: ``masses`` (the loads, read from ``forces``) and ``defaulted`` (:func:`defaulted_keys`)."""
NOTED_LOADS = ("lever_mass_kg", "lever_inertia_kg_m2", "ram_mass_kg", "ram_cg_mm", "rod_mass_kg",
               "crank_mass_kg", "block_mass_kg", "cut_force_N", "cut_height_mm", "idle_fraction",
               "gravity", "delta")
"""The loads whose default a reader must say when a file's ``forces`` lacks them: a number the
design is computed with (a missing ram mass would weigh nothing). The others mean "not given"
when absent as when null: ``lever_cg_mm`` (L3/2), ``guide_length_mm`` (the stroke), the
weights given instead of the masses, ``rotors`` (none)."""
SPEC_LENGTHS = ("crank", "stroke", "frame", "lever", "guide_height", "rod_length")


class _Refused(ValueError):
    """A JSON literal the parser must not turn into a value (NaN, 1e999, a 400-digit int):
    the reason (a key of FILE_REASONS) and what it quotes."""

    def __init__(self, reason: str, value: object) -> None:
        super().__init__(reason)
        self.reason = reason
        self.value = value


def load_design(path: str | os.PathLike) -> dict[str, Any]:
    """Read and fully validate a design file; returns {'spec', 'rpm', 'step_deg', 'masses', …}.

    Raises FileFormatError with one plain sentence for anything unreadable,
    foreign or invalid; the caller's state is never touched before it returns.
    """
    name = os.fsdecode(path)
    return parse_design(read_limited(name), name)


def parse_design(raw: bytes, name: str, entry: str | None = None) -> dict[str, Any]:
    """The rules of :func:`load_design` for a document given as bytes (the design
    library keeps documents in a database); ``name`` names its source in messages,
    ``entry`` the library entry it is (FileFormatError.entry)."""
    if len(raw) > MAX_FILE_BYTES:
        raise FileFormatError("too_large", name, MAX_FILE_BYTES // 1_000_000, entry=entry)
    doc = _parse(raw, name, entry)
    if not isinstance(doc, dict) or doc.get("format") != FILE_FORMAT:
        raise FileFormatError("not_design", name, entry=entry)
    version = doc.get("version")
    if type(version) is not int or version != FILE_VERSION:
        if "version" not in doc:
            raise FileFormatError("no_version", name, FILE_VERSION, entry=entry)
        raise FileFormatError("version", name, json.dumps(version)[:40], FILE_VERSION, entry=entry)
    if "spec" not in doc:
        raise FileFormatError("no_spec", name, entry=entry)
    try:
        spec = _spec(doc["spec"], name, entry)
        rpm = _rpms(doc.get("rpm", list(DEFAULT_FILE_RPMS)), name, entry)
        step = _step(doc.get("step_deg", DEFAULT_FILE_STEP), name, entry)
        check_file_samples(step, len(rpm))     # the file's own limit, the GUI's too
        masses = masses_from_dict(doc["forces"]) if "forces" in doc else None
        if "cam" in doc:            # validated here, kept as written (older files have none)
            from core.cam.file import cam_from_dict     # the cam's modules: only for a file with one
            cam_from_dict(doc["cam"])
        if "gear" in doc:           # the same for the gear pair's inputs (issue 35), and the
            # pair made from them, as the GUI's File › Open makes it: a centre distance no
            # shift fits was read here and kept in a library whose pane could not open it
            from core.gear.file import gear_from_dict
            from core.gear.pair import design_pair
            design_pair(gear_from_dict(doc["gear"]))
    except FileFormatError:
        raise
    except (DesignError, ArithmeticError, ValueError) as exc:   # never a traceback
        raise FileFormatError("invalid", name, _shorten(str(exc)), entry=entry, cause=exc) from None
    result = dict(doc)
    result.update(spec=spec, rpm=rpm, step_deg=step, masses=masses)
    result["defaulted"] = defaulted_keys(doc, spec, rpm, step, masses)
    return result


def defaulted_keys(doc: dict[str, Any], spec: Spec, rpm: list[float], step: float,
                   masses: MassProperties | None) -> tuple[tuple[str, str], ...]:
    """(key, the value taken) of every key ``doc`` lacks that the design is computed with,
    so that a reader can say it (``shaper … --design`` one note a key on stderr, File › Open
    in the status bar): a user's design is never changed without a word. Silent, as
    documented: a part the file has not (``forces``, ``cam``, ``gear``), a spec field the
    design does not use (``frame`` in synthesis mode), and a key whose absence means what its
    null does ("not given", "chosen by the tool": ``NOTED_LOADS``' others, the cam's roller,
    base, distance and phase, the gear's optional keys)."""
    out: list[tuple[str, str]] = []
    given = doc["spec"]
    used = {"mode", "variant", "guide_rule", *spec.active_fields()}
    if spec.variant == "rod":
        used |= {"rod_input", "rod_side"}
    for f in fields(Spec):
        if f.name in used and f.name not in given:
            value = getattr(spec, f.name)
            unit = " mm" if f.name in SPEC_LENGTHS else ""
            out.append((f"spec.{f.name}", value if isinstance(value, str) else _number(value) + unit))
    if "rpm" not in doc:
        out.append(("rpm", ", ".join(map(_number, rpm)) + " r/min"))
    if "step_deg" not in doc:
        out.append(("step_deg", f"{_number(step)}°"))
    if masses is not None:
        loads = doc["forces"]
        for name in NOTED_LOADS:
            alternative = {"lever_mass_kg": "lever_weight_N", "ram_mass_kg": "ram_weight_N"}.get(name)
            unused = name == "rod_mass_kg" and spec.variant != "rod"
            if name not in loads and not unused and (alternative is None or loads.get(alternative) is None):
                out.append((f"forces.{name}", _load_text(name, getattr(masses, name))))
    if isinstance(doc.get("cam"), dict):
        from core.cam.file import NUMBER_KEYS, TEXT_KEYS, default_values
        defaults = default_values()
        out += [(f"cam.{k}", _load_text(k, defaults[k])) for k in NUMBER_KEYS + TEXT_KEYS if k not in doc["cam"]]
    return tuple(out)


def _load_text(key: str, value: object) -> str:
    """A default as a note says it, its unit from the key (``_mm``, ``_deg``, ``_kg`` …)."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, str):
        return value
    units = (("_kg_m2", " kg·m²"), ("_kg", " kg"), ("_N", " N"), ("_mm", " mm"), ("_deg", "°"))
    unit = next((u for suffix, u in units if key.endswith(suffix)), "")
    if isinstance(value, tuple):
        return "[" + ", ".join(map(_number, value)) + "]" + unit
    return _number(value) + unit


def _number(value: float) -> str:
    """The shortest text that reads back as ``value`` (300, 0.05; 1/30 in full): a note's
    value, typed into the file, is the one taken."""
    short = f"{value:g}"
    return short if float(short) == value else repr(float(value))


def file_parts(doc: dict[str, Any]) -> dict[str, Any]:
    """The parts of a loaded design beside the linkage, speeds and loads: the cam and the
    gear (None when absent: their defaults) and any key a later version added to a version-1
    file, as the cam and the gear were added. A reader that opens and saves the file passes
    them all on, or Save drops what it does not know (``shaper design`` keeps them too)."""
    return {**dict.fromkeys(PART_KEYS), **{k: v for k, v in doc.items() if k not in OWN_KEYS}}


def _shorten(text: str, limit: int = 160) -> str:
    """One readable sentence even when a file holds a megabyte-long string."""
    return text if len(text) <= limit else text[:limit - 1] + "…"


# ---- reading ------------------------------------------------------------------
def read_limited(name: str) -> bytes:
    """At most MAX_FILE_BYTES of a regular file; special files are refused before opening."""
    try:
        info = os.stat(name)
    except OSError as exc:
        raise FileFormatError("unreadable", name, exc.strerror or exc, errno=exc.errno) from None
    _require_regular(info, name)
    flags = os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_NOCTTY", 0) \
        | getattr(os, "O_BINARY", 0)
    try:
        fd = os.open(name, flags)
    except OSError as exc:
        raise FileFormatError("unreadable", name, exc.strerror or exc, errno=exc.errno) from None
    try:
        _require_regular(os.fstat(fd), name)      # swapped for a FIFO after the stat?
        chunks, size = [], 0
        while size <= MAX_FILE_BYTES:
            chunk = os.read(fd, MAX_FILE_BYTES + 1 - size)
            if not chunk:
                break
            chunks.append(chunk)
            size += len(chunk)
    except OSError as exc:
        if exc.errno in (errno.EAGAIN, errno.EWOULDBLOCK):
            raise FileFormatError("not_regular", name) from None
        raise FileFormatError("unreadable", name, exc.strerror or exc, errno=exc.errno) from None
    finally:
        os.close(fd)
    if size > MAX_FILE_BYTES:
        raise FileFormatError("too_large", name, MAX_FILE_BYTES // 1_000_000)
    return b"".join(chunks)


def _require_regular(info: os.stat_result, name: str) -> None:
    if stat.S_ISDIR(info.st_mode):
        raise FileFormatError("folder", name)
    if not stat.S_ISREG(info.st_mode):
        raise FileFormatError("special", name)
    if info.st_size > MAX_FILE_BYTES:
        raise FileFormatError("too_large", name, MAX_FILE_BYTES // 1_000_000)


# A string literal, its escapes included, as Friedl's "unrolled loop": runs of plain bytes are
# taken whole. The plain alternation (one branch per byte) took 0.3–0.9 s over a 900 kB
# string field, near the 2 s a hostile file may take to be refused, on a loaded machine.
_STRING = re.compile(rb'"[^"\\]*(?:\\.[^"\\]*)*"', re.DOTALL)


def _nesting_depth(raw: bytes) -> int:
    """Deepest [ / { nesting outside string literals, without recursion."""
    bare = np.frombuffer(_STRING.sub(b'""', raw), dtype=np.uint8)
    if bare.size == 0:
        return 0
    step = (np.isin(bare, (ord("["), ord("{"))).astype(np.int64)
            - np.isin(bare, (ord("]"), ord("}"))).astype(np.int64))
    return int(np.cumsum(step).max(initial=0))


def _parse(raw: bytes, name: str, entry: str | None) -> object:
    try:
        text = raw.decode("utf-8-sig")
    except UnicodeDecodeError:
        raise FileFormatError("not_utf8", name, entry=entry) from None
    if _nesting_depth(raw) > MAX_DEPTH:
        raise FileFormatError("too_deep", name, MAX_DEPTH, entry=entry)
    try:
        return json.loads(text, parse_constant=_refuse_constant, parse_int=_parse_int,
                          parse_float=_parse_float, object_pairs_hook=_unique_keys)
    except _Refused as exc:
        raise FileFormatError(exc.reason, name, exc.value, entry=entry) from None
    except (json.JSONDecodeError, ValueError, RecursionError):
        raise FileFormatError("not_json", name, entry=entry) from None


def _unique_keys(pairs: list[tuple[str, Any]]) -> dict[str, Any]:
    """One JSON object as a dict, refused when a key appears twice in it (at any depth):
    json keeps the last silently, so a file with two "spec" objects (or "z1": 3, "z1": 13)
    opened as a design its reader never saw (issue 42)."""
    out = dict(pairs)
    if len(out) != len(pairs):
        seen: set[str] = set()
        for key, _ in pairs:
            if key in seen:
                raise _Refused("duplicate_key", json.dumps(key, ensure_ascii=False)[:40])
            seen.add(key)
    return out


def _refuse_constant(literal: str) -> float:
    raise _Refused("constant", literal)


def _parse_int(literal: str) -> int:
    if len(literal.lstrip("-")) > MAX_INT_DIGITS:
        raise _Refused("long_integer", len(literal.lstrip("-")))
    return int(literal)


def _parse_float(literal: str) -> float:
    value = float(literal)
    if not math.isfinite(value):
        raise _Refused("huge_number", literal[:20])
    return value


# ---- validation -----------------------------------------------------------------
def _is_number(value: object) -> bool:
    """A JSON number: int or float, never a bool (which Python counts as an int)."""
    return type(value) in (int, float)


def _spec(data: object, name: str, entry: str | None) -> Spec:
    if not isinstance(data, dict):
        raise FileFormatError("spec_type", name, entry=entry)
    spec = Spec.from_dict(data)
    spec.check_fields()      # inactive fields too: what is saved must reopen in any mode
    spec.design()
    return spec


def _rpms(data: object, name: str, entry: str | None) -> list[float]:
    if not isinstance(data, list) or not data:
        raise FileFormatError("rpm_type", name, entry=entry)
    for value in data:
        if not _is_number(value):
            raise FileFormatError("rpm_value", name, json.dumps(value)[:40], entry=entry)
    return [float(v) for v in check_rpms(data)]   # core's bounds, floor included


def _step(value: object, name: str, entry: str | None) -> float:
    if not _is_number(value):
        raise FileFormatError("step_type", name, entry=entry)
    angle_count(float(value))      # core's bounds, without building the angles
    return float(value)


def masses_to_dict(masses: MassProperties) -> dict[str, Any]:
    """The load inputs as stored in a design file (units in the keys), as typed: a link
    given by its weight keeps its weight (``lever_weight_N``) and no mass."""
    from core.forces.masses import WEIGHTS
    data = {f.name: getattr(masses, f.name) for f in fields(masses)}
    data["ram_cg_mm"] = list(masses.ram_cg_mm)
    data["rotors"] = [{"J_kg_m2": j, "speed_ratio": r} for j, r in masses.rotors]
    for mass, weight in WEIGHTS:
        del data[mass if data[weight] is not None else weight]
    return data


def masses_from_dict(data: object) -> MassProperties:
    """Validate stored load inputs; DesignError names the bad field."""
    from core.forces.masses import MassProperties  # only for a file with loads
    if not isinstance(data, dict):
        raise DesignError("forces", type(data).__name__, "must be an object of load inputs")
    known = {f.name for f in fields(MassProperties)}
    for key, value in data.items():
        if key not in known:
            raise DesignError(key, value, "is not a load input")
        if key == "gravity":
            if type(value) is not bool:
                raise DesignError(key, value, "must be true or false")
        elif key == "ram_cg_mm":
            if not isinstance(value, list) or len(value) != 2 or not all(map(_is_number, value)):
                raise DesignError(key, value, "must be a pair [dx, dy] in mm")
        elif key == "rotors":
            _check_rotors(value)
        elif key in ("lever_cg_mm", "lever_weight_N", "ram_weight_N", "guide_length_mm") \
                and value is None:
            continue
        elif not _is_number(value):
            raise DesignError(key, value, "must be a number")
    values = dict(data)
    if "ram_cg_mm" in values:
        values["ram_cg_mm"] = tuple(values["ram_cg_mm"])
    if "rotors" in values:
        values["rotors"] = tuple((r["J_kg_m2"], r["speed_ratio"]) for r in values["rotors"])
    return MassProperties(**values)


def _check_rotors(value: object) -> None:
    """``"rotors": [{"J_kg_m2": J, "speed_ratio": ω_i/ω2}, …]``: the shape and types only
    (MassProperties checks the ranges)."""
    keys = {"J_kg_m2", "speed_ratio"}
    if not isinstance(value, list) or not all(isinstance(r, dict) and set(r) == keys
                                              and all(map(_is_number, r.values())) for r in value):
        raise DesignError("rotors", value, 'must be a list of {"J_kg_m2": J, "speed_ratio": R}')
