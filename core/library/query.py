"""The library's filter and sort syntax, turned into parameterized SQL.

A filter is a comma-separated list of conditions that must all hold::

    K>=1.4, variant=rod, name~cut, a_max<5, tag=final

Each condition is ``FIELD OP VALUE``:

- FIELD is a figure key as in the JSON (``K``, ``stroke_mm``, ``a_max_m_s2`` …) or its
  short name (``H``, ``L1``…``L4``, ``theta``, ``a_max``, ``J_F`` …), any letter case;
  ``name``, ``notes``, ``variant``, ``rod_side``, ``created``, ``modified`` are text, and
  ``tag`` matches one of the entry's tags.
- OP is ``=``, ``!=``, ``<``, ``<=``, ``>``, ``>=``, or ``~`` (contains, ignoring ASCII case).
- VALUE is a number for numeric fields, text otherwise; put it in double quotes to
  include a comma or a quote (``name~"K=1.4, rod"``, ``\\"`` for a quote).

An entry without a value (``rod_mm`` of a block design, torques without loads) never
matches a comparison. Per-speed figures are those at the speed chosen for the query
(``--rpm``), else at each design's first speed.

Field names and operators come from fixed tables; values are always bound as SQL
parameters, never pasted into the SQL text.
"""
from __future__ import annotations

import re
from dataclasses import dataclass

from core.space.figures import DESIGN_FIGURES, SPEED_FIGURES

OPERATORS = ("<=", ">=", "!=", "=", "<", ">", "~")

# field key → (SQL expression, kind); kind is "num", "text" or "tag"
FIELDS: dict[str, tuple[str, str]] = {
    "name": ("e.name", "text"), "notes": ("e.notes", "text"), "variant": ("e.variant", "text"),
    "rod_side": ("e.rod_side", "text"), "created": ("e.created", "text"),
    "modified": ("e.modified", "text"), "tag": ("", "tag"), "rpm": ("s.rpm", "num"),
}
FIELDS.update({key: (f"e.{key}", "num") for key, *_ in DESIGN_FIGURES})
FIELDS.update({key: (f"s.{key}", "num") for key, *_ in SPEED_FIGURES})

ALIASES: dict[str, str] = {alias.lower(): key for key, _, alias, _ in DESIGN_FIGURES + SPEED_FIGURES}
ALIASES.update({key.lower(): key for key in FIELDS})
ALIASES.update({"tags": "tag", "theta": "theta_deg", "stroke": "stroke_mm", "crank": "crank_mm",
                "frame": "frame_mm", "lever": "lever_mm", "rod": "rod_mm", "pressure": "pressure_angle_max_deg",
                "flywheel": "flywheel_inertia_kg_m2", "jf": "flywheel_inertia_kg_m2",
                "torque_mean": "mean_torque_N_m", "torque_max": "max_torque_N_m"})

_CONDITION = re.compile(r"\s*([A-Za-z_][A-Za-z0-9_]*)\s*(<=|>=|!=|=|<|>|~)\s*")


class QueryError(ValueError):
    """A filter or sort field that cannot be understood; the message says what is allowed."""


@dataclass(frozen=True)
class Condition:
    field: str      # canonical key
    op: str
    value: str | float


def _shown(text: str) -> str:
    """A value as a message quotes it: at most 40 characters (a pasted megabyte stays out)."""
    return repr(text if len(text) <= 40 else text[:37] + "...")


def field_key(name: str) -> str:
    """The canonical key of a field name or alias; QueryError if unknown."""
    key = ALIASES.get(name.strip().lower())
    if key is None:
        raise QueryError(f"unknown field {_shown(name)}; use one of: {', '.join(sorted(FIELDS))} "
                         "(or a short name such as K, H, L1, theta, a_max, J_F)")
    return key


def parse_filter(text: str) -> list[Condition]:
    """``K>=1.4, variant=rod`` → conditions; QueryError says which part is wrong."""
    conditions: list[Condition] = []
    pos, text = 0, text or ""
    while pos < len(text):
        if not text[pos:].strip():
            break
        match = _CONDITION.match(text, pos)
        if match is None:
            raise QueryError(f"cannot read the condition at {_shown(text[pos:].strip())}; write FIELD OP VALUE "
                             f"with OP one of {' '.join(OPERATORS)}")
        key = field_key(match.group(1))
        op = match.group(2)
        raw, pos = _value(text, match.end())
        conditions.append(_condition(key, op, raw))
    return conditions


def _value(text: str, pos: int) -> tuple[str, int]:
    """The value starting at ``pos`` and the position after its separating comma."""
    if pos < len(text) and text[pos] == '"':
        out, i = [], pos + 1
        while i < len(text):
            ch = text[i]
            if ch == "\\" and i + 1 < len(text):
                out.append(text[i + 1])
                i += 2
                continue
            if ch == '"':
                rest = text[i + 1:]
                stripped = rest.lstrip()
                if stripped and not stripped.startswith(","):
                    raise QueryError(f"expected ',' after the quoted value {_shown(''.join(out))}")
                return "".join(out), len(text) - len(stripped) + (1 if stripped else 0)
            out.append(ch)
            i += 1
        raise QueryError(f"the quoted value starting at {_shown(text[pos:])} has no closing quote")
    end = text.find(",", pos)
    end = len(text) if end < 0 else end
    return text[pos:end].strip(), end + 1


def _condition(key: str, op: str, raw: str) -> Condition:
    kind = FIELDS[key][1]
    if kind == "num":
        if op == "~":
            raise QueryError(f"{key}: '~' (contains) is for text fields; use = < <= > >= !=")
        try:
            value = float(raw)
        except ValueError:
            raise QueryError(f"{key}: {_shown(raw)} is not a number") from None
        if value != value or value in (float("inf"), float("-inf")):
            raise QueryError(f"{key}: {_shown(raw)} is not a finite number")
        return Condition(key, op, value)
    if kind == "tag" and op not in ("=", "!=", "~"):
        raise QueryError("tag: use tag=TEXT, tag!=TEXT or tag~TEXT")
    return Condition(key, op, raw)


def _like(text: str) -> str:
    return "%" + text.replace("\\", "\\\\").replace("%", "\\%").replace("_", "\\_") + "%"


def condition_sql(c: Condition) -> tuple[str, list[object]]:
    """One condition as an SQL fragment with its parameters."""
    column, kind = FIELDS[c.field]
    if kind == "tag":
        if c.op == "~":
            return ("EXISTS (SELECT 1 FROM tags t WHERE t.entry_id = e.id AND t.tag LIKE ? ESCAPE '\\')",
                    [_like(str(c.value))])
        exists = "EXISTS (SELECT 1 FROM tags t WHERE t.entry_id = e.id AND t.tag = ?)"
        return (exists if c.op == "=" else "NOT " + exists), [c.value]
    if c.op == "~":
        return f"{column} LIKE ? ESCAPE '\\'", [_like(str(c.value))]
    return f"{column} {c.op} ?", [c.value]


def search_sql(text: str) -> tuple[str, list[object]]:
    """Free-text search in the name, notes and tags (contains, ignoring ASCII case)."""
    pattern = _like(text.strip())
    return ("(e.name LIKE ? ESCAPE '\\' OR e.notes LIKE ? ESCAPE '\\' OR EXISTS (SELECT 1 FROM tags t "
            "WHERE t.entry_id = e.id AND t.tag LIKE ? ESCAPE '\\'))", [pattern, pattern, pattern])


def sort_sql(field: str, descending: bool) -> str:
    """ORDER BY clause for a field (empty values last), ties broken by name."""
    key = field_key(field)
    column, kind = FIELDS[key]
    if kind == "tag":
        raise QueryError("tag: the list cannot be sorted by tag")
    direction = "DESC" if descending else "ASC"
    if key == "name":
        return f"ORDER BY e.name {direction}"
    return f"ORDER BY {column} {direction} NULLS LAST, e.name ASC"
