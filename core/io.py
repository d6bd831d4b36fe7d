"""Files: curve CSV and design JSON, written atomically, read defensively.

The last level of core: it formats results, it never computes them. The GUI
and the CLI both write through here, so their CSV files are identical.
"""
from __future__ import annotations

import json
import math
import os
import tempfile
from pathlib import Path
from typing import Any, Iterable

import numpy as np

from .dynamics import MassProperties
from .errors import DesignError, FileFormatError
from .kinematics import Motion
from .spec import Spec

CURVE_COLUMNS = ("rpm", "crank_deg", "time_s", "ram_x_mm", "ram_v_m_s", "ram_a_m_s2",
                 "lever_deg", "lever_omega_rad_s", "lever_alpha_rad_s2")
EXTRA_COLUMNS = ("slide_v_m_s", "coriolis_m_s2")
ROD_COLUMNS = ("rod_deg", "rod_omega_rad_s", "rod_alpha_rad_s2", "pressure_angle_deg")
FILE_FORMAT = "shaper-design"
FILE_VERSION = 1


def curve_table(motion: Motion) -> tuple[tuple[str, ...], np.ndarray]:
    """Long-form table, one row per (rpm, angle): column names and a 2-D array."""
    m, n = motion.ram_v.shape
    tile = lambda a: np.broadcast_to(a, (m, n))  # noqa: E731
    columns: list[tuple[str, np.ndarray]] = [
        ("rpm", tile(motion.rpm[:, None])),
        ("crank_deg", tile(np.degrees(motion.crank_angle))),
        ("time_s", motion.time),
        ("ram_x_mm", tile(motion.ram_x)),
        ("ram_v_m_s", motion.ram_v),
        ("ram_a_m_s2", motion.ram_a),
        ("lever_deg", tile(np.degrees(motion.lever_angle))),
        ("lever_omega_rad_s", motion.lever_omega),
        ("lever_alpha_rad_s2", motion.lever_alpha),
        ("slide_v_m_s", motion.slide_v),
        ("coriolis_m_s2", motion.coriolis),
    ]
    if motion.rod_angle is not None:
        columns += [
            ("rod_deg", tile(np.degrees(motion.rod_angle))),
            ("rod_omega_rad_s", motion.rod_omega),
            ("rod_alpha_rad_s2", motion.rod_alpha),
            ("pressure_angle_deg", tile(np.degrees(motion.pressure_angle))),
        ]
    names = tuple(name for name, _ in columns)
    data = np.stack([np.asarray(values, dtype=float).reshape(-1) for _, values in columns], axis=1)
    return names, data


def table_csv(names: Iterable[str], data: np.ndarray) -> str:
    """CSV text with a header; numbers with 10 significant digits."""
    data = np.asarray(data, dtype=float)
    names = list(names)
    row = ",".join(["%.10g"] * len(names))
    body = "\n".join([row] * data.shape[0]) % tuple(data.ravel()) if data.size else ""
    return ",".join(names) + "\n" + body + ("\n" if data.size else "")


def curves_csv(motion: Motion) -> str:
    return table_csv(*curve_table(motion))


def atomic_write(path: str | os.PathLike, text: str) -> None:
    """Write ``text`` so the file is either the old one or the whole new one."""
    target = Path(path)
    directory = target.parent if str(target.parent) else Path(".")
    fd, tmp = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".tmp", dir=directory)
    try:
        with os.fdopen(fd, "w", encoding="utf-8", newline="") as handle:
            handle.write(text)
            handle.flush()
            os.fsync(handle.fileno())
        os.replace(tmp, target)
    except BaseException:
        try:
            os.unlink(tmp)
        except FileNotFoundError:
            pass
        raise


def design_document(spec: Spec, rpms: Iterable[float], step_deg: float,
                    extra: dict[str, Any] | None = None) -> dict[str, Any]:
    doc: dict[str, Any] = {"format": FILE_FORMAT, "version": FILE_VERSION,
                           "spec": spec.to_dict(), "rpm": [float(r) for r in rpms],
                           "step_deg": float(step_deg)}
    if extra:
        doc.update(extra)
    return doc


def save_design(path: str | os.PathLike, spec: Spec, rpms: Iterable[float], step_deg: float,
                extra: dict[str, Any] | None = None) -> None:
    text = json.dumps(design_document(spec, rpms, step_deg, extra), indent=2, ensure_ascii=False)
    atomic_write(path, text + "\n")


def load_design(path: str | os.PathLike) -> dict[str, Any]:
    """Read and fully validate a design file; returns {'spec', 'rpm', 'step_deg', …}.

    Raises FileFormatError with a plain message for anything unreadable,
    foreign or invalid; the caller's state is never touched before it returns.
    """
    try:
        raw = Path(path).read_bytes()
    except OSError as exc:
        raise FileFormatError(f"cannot read {path}: {exc.strerror or exc}") from None
    return parse_design(raw, str(path))


def parse_design(raw: bytes, path: str) -> dict[str, Any]:
    """Validate a design document given as bytes; ``path`` names its source in messages.

    The rules of :func:`load_design`, for documents that do not come from a file
    (the design library keeps them in a database).
    """
    if len(raw) > 10_000_000:
        raise FileFormatError(f"{path} is too large to be a design file")
    try:
        doc = json.loads(raw.decode("utf-8"), parse_constant=_refuse_constant)
    except (UnicodeDecodeError, json.JSONDecodeError, ValueError):
        raise FileFormatError(f"{path} is not a design file (not valid JSON)") from None
    if not isinstance(doc, dict) or doc.get("format") != FILE_FORMAT:
        raise FileFormatError(f"{path} is not a shaper design file")
    if doc.get("version") != FILE_VERSION:
        raise FileFormatError(f"{path} has unsupported version {doc.get('version')!r}")
    try:
        spec_data = doc["spec"]
        if not isinstance(spec_data, dict):
            raise FileFormatError(f"{path}: 'spec' must be an object")
        spec = Spec.from_dict(spec_data)
        spec.design()
        rpms = doc.get("rpm", [40.0, 60.0])
        if not isinstance(rpms, list):
            raise FileFormatError(f"{path}: 'rpm' must be a list of crank speeds")
        from .kinematics import check_rpms, crank_angles
        rpm = [float(v) for v in check_rpms(rpms)]
        step = doc.get("step_deg", 1.0)
        if isinstance(step, bool) or not isinstance(step, (int, float)):
            raise FileFormatError(f"{path}: 'step_deg' must be a number")
        crank_angles(step)
        masses = masses_from_dict(doc["forces"]) if "forces" in doc else None
    except DesignError as exc:
        raise FileFormatError(f"{path}: invalid design ({exc})") from None
    result = dict(doc)
    result.update(spec=spec, rpm=rpm, step_deg=float(step), masses=masses)
    return result


def masses_to_dict(masses: MassProperties) -> dict[str, Any]:
    """The load inputs as stored in a design file (units in the keys)."""
    data = {name: getattr(masses, name) for name in MassProperties.__dataclass_fields__}
    data["ram_cg_mm"] = list(masses.ram_cg_mm)
    return data


def masses_from_dict(data: object) -> MassProperties:
    """Validate stored load inputs; DesignError names the bad field."""
    if not isinstance(data, dict):
        raise DesignError("forces", data, "must be an object of load inputs")
    known = set(MassProperties.__dataclass_fields__)
    for key, value in data.items():
        if key not in known:
            raise DesignError(key, value, "is not a load input")
        if key == "gravity":
            continue
        if key == "ram_cg_mm":
            if not isinstance(value, list) or len(value) != 2:
                raise DesignError(key, value, "must be a pair [dx, dy] in mm")
            continue
        if key == "lever_cg_mm" and value is None:
            continue
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise DesignError(key, value, "must be a number")
    values = dict(data)
    if "ram_cg_mm" in values:
        values["ram_cg_mm"] = tuple(values["ram_cg_mm"])
    return MassProperties(**values)


def _refuse_constant(name: str) -> float:
    raise ValueError(name)


def finite_or_none(value: float | None) -> float | None:
    return None if value is None or not math.isfinite(value) else float(value)
