"""One table from core's error fields to translated field names and messages.

Core speaks English with numbers in fixed phrases; here each phrase becomes a
translatable template, so the Chinese UI never shows an English sentence.
"""
from __future__ import annotations

import re

from PySide6.QtCore import QCoreApplication

from core.base.errors import DesignError
from shaperapp.widgets import cam_messages

# Error text in the one weight every script has: a bold Latin run beside regular CJK
# glyphs (fonts without a semi-bold CJK face) looked like two kinds of message.
ERROR_TEXT_STYLE = "color: #b71c1c;"


def field_name(parameter: str) -> str:
    names = {
        "crank": QCoreApplication.translate("messages", "Crank length L1"),
        "time_ratio": QCoreApplication.translate("messages", "Time ratio K"),
        "stroke": QCoreApplication.translate("messages", "Stroke H"),
        "frame": QCoreApplication.translate("messages", "Frame distance L2"),
        "lever": QCoreApplication.translate("messages", "Lever length L3"),
        "guide": QCoreApplication.translate("messages", "Ram guide"),
        "rod": QCoreApplication.translate("messages", "Rod length L4"),
        "rod_ratio": QCoreApplication.translate("messages", "Rod ratio L4/L3"),
        "rod_side": QCoreApplication.translate("messages", "Rod side"),
        "rpm": QCoreApplication.translate("messages", "Crank speeds"),
        "step": QCoreApplication.translate("messages", "Angle step"),
        "lever_mass_kg": QCoreApplication.translate("messages", "Lever mass"),
        "lever_cg_mm": QCoreApplication.translate("messages", "Lever centre of mass"),
        "lever_inertia_kg_m2": QCoreApplication.translate("messages", "Lever moment of inertia"),
        "ram_mass_kg": QCoreApplication.translate("messages", "Ram mass"),
        "ram_cg_mm": QCoreApplication.translate("messages", "Ram centre-of-mass offset"),
        "rod_mass_kg": QCoreApplication.translate("messages", "Rod mass"),
        "crank_mass_kg": QCoreApplication.translate("messages", "Crank mass"),
        "block_mass_kg": QCoreApplication.translate("messages", "Block mass"),
        "cut_force_N": QCoreApplication.translate("messages", "Cutting force P"),
        "cut_height_mm": QCoreApplication.translate("messages", "Tool height below guide"),
        "idle_fraction": QCoreApplication.translate("messages", "Idle margin"),
        "delta": QCoreApplication.translate("messages", "Speed fluctuation δ"),
        "gravity": QCoreApplication.translate("messages", "Gravity"),
        "lever_weight_N": QCoreApplication.translate("messages", "Lever weight G4"),
        "ram_weight_N": QCoreApplication.translate("messages", "Ram weight G6"),
        "guide_length_mm": QCoreApplication.translate("messages", "Ram guide length"),
        "rotors": QCoreApplication.translate("messages", "Rotating parts"),
        "rotor_inertia_kg_m2": QCoreApplication.translate("messages", "Rotating part J"),
        "rotor_ratio": QCoreApplication.translate("messages", "Rotating part speed ratio"),
        "design": QCoreApplication.translate("messages", "Design"),
        "arm": QCoreApplication.translate("messages", "Follower arm l"),
        "swing": QCoreApplication.translate("messages", "Follower swing ψmax"),
        "pressure": QCoreApplication.translate("messages", "Allowed pressure angle, rise"),
        "return_pressure": QCoreApplication.translate("messages", "Allowed pressure angle, return"),
        "rise": QCoreApplication.translate("messages", "Rise angle"),
        "dwell": QCoreApplication.translate("messages", "Outer dwell angle"),
        "return": QCoreApplication.translate("messages", "Return angle"),
        "rise_law": QCoreApplication.translate("messages", "Rise law"),
        "return_law": QCoreApplication.translate("messages", "Return law"),
        "roller": QCoreApplication.translate("messages", "Roller radius"),
        "base": QCoreApplication.translate("messages", "Base radius r0"),
        "distance": QCoreApplication.translate("messages", "Centre distance a"),
        "phase": QCoreApplication.translate("messages", "Phase of the rise"),
        "hub": QCoreApplication.translate("messages", "Hub radius"),
        "boss": QCoreApplication.translate("messages", "Pivot boss radius"),
        "clearance": QCoreApplication.translate("messages", "Least clearance"),
        "mode": QCoreApplication.translate("messages", "Input"),
        "variant": QCoreApplication.translate("messages", "Ram drive"),
        "guide_rule": QCoreApplication.translate("messages", "Ram guide"),
        "guide_height": QCoreApplication.translate("messages", "Guide height"),
        "rod_input": QCoreApplication.translate("messages", "Rod given as"),
        "rod_length": QCoreApplication.translate("messages", "Rod length L4"),
        "forces": QCoreApplication.translate("messages", "Loads"),
        "cam": QCoreApplication.translate("messages", "Feed cam"),
    }
    # a cam file's keys carry their unit (arm_mm, swing_deg): the same fields as the options
    return names.get(parameter) or names.get(re.sub(r"_(mm|deg)$", "", parameter), parameter)


# (pattern on core's English ``allowed`` text, translatable template with %1, %2 …); the
# cam's are in cam_messages, and _PATTERNS holds both
_OWN_PATTERNS: tuple[tuple[str, str], ...] = (
    (r"must be > (\S+) and ≤ (\S+)(?: (.+))?$", "must be greater than %1 and at most %2 %3"),
    (r"must be ≥ (\S+) and ≤ (\S+)(?: (.+))?$", "must be at least %1 and at most %2 %3"),
    (r"must be ≥ (\S+) and < (\S+)(?: (.+))?$", "must be at least %1 and less than %2 %3"),
    (r"must be > (\S+) and < (\S+)(?: (.+))?$", "must be greater than %1 and less than %2 %3"),
    (r"must be a pair \(dx, dy\) in mm$", "must be a pair (dx, dy) in mm"),
    (r"must be a number$", "must be a number"),
    (r"must be a finite number$", "must be a number"),      # one wording for both
    (r"must be > (\S+) to reach the guide line over the whole cycle$",
     "must be more than %1 to reach the guide line over the whole cycle"),
    (r"cannot be computed for these inputs$", "cannot be computed for these inputs; try other values"),
    (r"must be ≥ (\S+) mm for this crank and K, so that the crank pin stays on the lever$",
     "must be at least %1 mm for this crank and K, so that the crank pin stays on the lever"),
    (r"must be shorter than the frame O2O4 \((\S+) mm\)$",
     "must be shorter than the frame O2O4 (%1 mm)"),
    (r"must be ≥ L2 \+ L1 = (\S+) mm, so that the crank pin stays on the lever$",
     "must be at least L2 + L1 = %1 mm, so that the crank pin stays on the lever"),
    (r"must be > L2 \+ L1 = (\S+) mm above the lever pivot, so that the ram clears the crank$",
     "must be more than L2 + L1 = %1 mm above the lever pivot, so that the ram clears the crank"),
    (r"must be > (\S+) mm for this crank and K, so that the ram guide its rule places clears the crank$",
     "must be more than %1 mm for this crank and K, so that the ram guide its rule places clears the crank"),
    (r"must be > (\S+) mm, so that the ram guide its rule places clears the crank \(L2 \+ L1 = (\S+) mm above "
     r"the lever pivot\)$",
     "must be more than %1 mm, so that the ram guide its rule places clears the crank (L2 + L1 = %2 mm above "
     "the lever pivot)"),
    (r"must be ≥ (\S+) mm for this crank and K, so that the block on the lever tip reaches the guide height "
     r"(\S+) mm$",
     "must be at least %1 mm for this crank and K, so that the block on the lever tip reaches the guide height %2 mm"),
    (r"must be ≥ the guide height (\S+) mm, so that the block on the lever tip reaches the guide \(and the "
     r"crank pin stays on the lever: L2 \+ L1 = (\S+) mm\)$",
     "must be at least the guide height %1 mm, so that the block on the lever tip reaches the guide (and the "
     "crank pin stays on the lever: L2 + L1 = %2 mm)"),
    (r"must be > L2 \+ L1 = (\S+) mm, so that the crank pin stays on the lever and a ram guide fits between "
     r"L2 \+ L1 and the lever tip$",
     "must be more than L2 + L1 = %1 mm, so that the crank pin stays on the lever and a ram guide fits between "
     "L2 + L1 and the lever tip"),
    (r"must be > (\S+) mm for this crank and K, so that the crank pin stays on the lever and a ram guide fits "
     r"between L2 \+ L1 and the lever tip$",
     "must be more than %1 mm for this crank and K, so that the crank pin stays on the lever and a ram guide fits "
     "between L2 + L1 and the lever tip"),
    (r"must be > L2 \+ L1 = (\S+) mm and ≤ the lever length (\S+) mm, so that the ram clears the crank and the "
     r"block on the lever tip reaches the guide$",
     "must be more than L2 + L1 = %1 mm and at most the lever length %2 mm, so that the ram clears the crank and "
     "the block on the lever tip reaches the guide"),
    (r"must be > (\S+) mm to reach the guide line over the whole cycle$",
     "must be more than %1 mm to reach the guide line over the whole cycle"),
    (r"the rod passes a dead-centre position against the lever; lengthen it to at least (\S+) mm or move the "
     r"guide line$",
     "the rod passes a dead-centre position against the lever; lengthen it to at least %1 mm or move the guide line"),
    (r"the rod passes a dead-centre position against the lever; raise L4/L3 to at least (\S+) or move the "
     r"guide line$",
     "the rod passes a dead-centre position against the lever; raise L4/L3 to at least %1 or move the guide line"),
    (r"the rod passes a dead-centre position against the lever at every length up to (\S+) mm; move the guide "
     r"line$",
     "the rod passes a dead-centre position against the lever at every length up to %1 mm; move the guide line"),
    (r"must be ≥ (\S+) for this crank and stroke, so that the frame and the lever stay ≤ (\S+) mm$",
     "must be at least %1 for this crank and stroke, so that the frame and the lever stay at most %2 mm"),
    (r"no K up to (\S+) keeps the frame and the lever ≤ (\S+) mm for this crank and stroke: shorten them$",
     "no K up to %1 keeps the frame and the lever at most %2 mm for this crank and stroke: shorten them"),
    (r"must be ≤ (\S+) mm \(0\.866·L2\), so that the time ratio K stays ≤ (\S+)$",
     "must be at most %1 mm (0.866·L2), so that the time ratio K stays at most %2"),
    (r"give 1 to (\S+) crank speeds$", "give 1 to %1 crank speeds"),
    (r"gives more than (\S+) angles; use a larger step$", "gives more than %1 angles; use a larger step"),
    (r"gives (\S+) samples \(angles × speeds\), more than (\S+); use a larger step or fewer speeds$",
     "gives %1 samples (angles × speeds), more than %2; use a larger step or fewer speeds"),
    (r"gives (\S+) samples \(angles × speeds\) with (\S+) speeds?, more than a design file holds \((\S+)\); "
     r"use a step of at least (\S+)°$",
     "gives %1 samples (angles × speeds) with %2 speeds, more than a design file holds (%3); use a step of at least %4°"),
    (r"must be given either as a length or as a ratio L4/L3, not both$",
     "must be given either as a length or as a ratio L4/L3, not both"),
    # what a design file can hold wrong (core.files.design_file, Spec.from_dict, core.cam.file)
    (r"is not a design field$", "is not a design field"),
    (r"is not a load input$", "is not a load input"),
    (r"is not a cam field$", "is not a cam field"),
    (r"must be text$", "must be text"),
    (r"must be true or false$", "must be true or false"),
    (r"must be a pair \[dx, dy\] in mm$", "must be a pair (dx, dy) in mm"),
    (r"must be an object of load inputs$", "must be an object of load inputs"),
    (r"must be an object of cam inputs$", "must be an object of cam inputs"),
    (r"must be one of (.+)$", "must be one of %1"),
)
_PATTERNS = _OWN_PATTERNS + cam_messages.PATTERNS
_ADVICE_PATTERNS = cam_messages.ADVICE_PATTERNS


def _translated_templates() -> dict[str, str]:
    # Listed literally so pyside6-lupdate finds every template.
    return {
        **cam_messages.templates(),
        "%1; %2": QCoreApplication.translate("messages", "%1; %2"),
        "must be greater than %1 and at most %2 %3": QCoreApplication.translate("messages", "must be greater than %1 and at most %2 %3"),
        "must be at least %1 and at most %2 %3": QCoreApplication.translate("messages", "must be at least %1 and at most %2 %3"),
        "must be at least %1 and less than %2 %3": QCoreApplication.translate("messages", "must be at least %1 and less than %2 %3"),
        "must be greater than %1 and less than %2 %3": QCoreApplication.translate("messages", "must be greater than %1 and less than %2 %3"),
        "must be a pair (dx, dy) in mm": QCoreApplication.translate("messages", "must be a pair (dx, dy) in mm"),
        "must be a number": QCoreApplication.translate("messages", "must be a number"),
        "must be more than %1 to reach the guide line over the whole cycle":
            QCoreApplication.translate("messages", "must be more than %1 to reach the guide line over the whole cycle"),
        "cannot be computed for these inputs; try other values":
            QCoreApplication.translate("messages", "cannot be computed for these inputs; try other values"),
        "must be at least %1 mm for this crank and K, so that the crank pin stays on the lever":
            QCoreApplication.translate("messages", "must be at least %1 mm for this crank and K, so that the crank pin stays on the lever"),
        "must be shorter than the frame O2O4 (%1 mm)": QCoreApplication.translate("messages", "must be shorter than the frame O2O4 (%1 mm)"),
        "must be at least L2 + L1 = %1 mm, so that the crank pin stays on the lever":
            QCoreApplication.translate("messages", "must be at least L2 + L1 = %1 mm, so that the crank pin stays on the lever"),
        "must be more than L2 + L1 = %1 mm above the lever pivot, so that the ram clears the crank":
            QCoreApplication.translate("messages", "must be more than L2 + L1 = %1 mm above the lever pivot, so that the ram clears the crank"),
        "must be more than %1 mm for this crank and K, so that the ram guide its rule places clears the crank":
            QCoreApplication.translate("messages", "must be more than %1 mm for this crank and K, so that the ram guide its rule places clears the crank"),
        "must be more than %1 mm, so that the ram guide its rule places clears the crank (L2 + L1 = %2 mm above the lever pivot)":
            QCoreApplication.translate("messages", "must be more than %1 mm, so that the ram guide its rule places clears the crank (L2 + L1 = %2 mm above the lever pivot)"),
        "must be at least %1 mm for this crank and K, so that the block on the lever tip reaches the guide height %2 mm":
            QCoreApplication.translate("messages", "must be at least %1 mm for this crank and K, so that the block on the lever tip reaches the guide height %2 mm"),
        "must be at least the guide height %1 mm, so that the block on the lever tip reaches the guide (and the crank pin stays on the lever: L2 + L1 = %2 mm)":
            QCoreApplication.translate("messages", "must be at least the guide height %1 mm, so that the block on the lever tip reaches the guide (and the crank pin stays on the lever: L2 + L1 = %2 mm)"),
        "must be more than L2 + L1 = %1 mm, so that the crank pin stays on the lever and a ram guide fits between L2 + L1 and the lever tip":
            QCoreApplication.translate("messages", "must be more than L2 + L1 = %1 mm, so that the crank pin stays on the lever and a ram guide fits between L2 + L1 and the lever tip"),
        "must be more than %1 mm for this crank and K, so that the crank pin stays on the lever and a ram guide fits between L2 + L1 and the lever tip":
            QCoreApplication.translate("messages", "must be more than %1 mm for this crank and K, so that the crank pin stays on the lever and a ram guide fits between L2 + L1 and the lever tip"),
        "must be more than L2 + L1 = %1 mm and at most the lever length %2 mm, so that the ram clears the crank and the block on the lever tip reaches the guide":
            QCoreApplication.translate("messages", "must be more than L2 + L1 = %1 mm and at most the lever length %2 mm, so that the ram clears the crank and the block on the lever tip reaches the guide"),
        "must be more than %1 mm to reach the guide line over the whole cycle":
            QCoreApplication.translate("messages", "must be more than %1 mm to reach the guide line over the whole cycle"),
        "the rod passes a dead-centre position against the lever; lengthen it to at least %1 mm or move the guide line":
            QCoreApplication.translate("messages", "the rod passes a dead-centre position against the lever; lengthen it to at least %1 mm or move the guide line"),
        "the rod passes a dead-centre position against the lever; raise L4/L3 to at least %1 or move the guide line":
            QCoreApplication.translate("messages", "the rod passes a dead-centre position against the lever; raise L4/L3 to at least %1 or move the guide line"),
        "the rod passes a dead-centre position against the lever at every length up to %1 mm; move the guide line":
            QCoreApplication.translate("messages", "the rod passes a dead-centre position against the lever at every length up to %1 mm; move the guide line"),
        "must be at least %1 for this crank and stroke, so that the frame and the lever stay at most %2 mm":
            QCoreApplication.translate("messages", "must be at least %1 for this crank and stroke, so that the frame and the lever stay at most %2 mm"),
        "no K up to %1 keeps the frame and the lever at most %2 mm for this crank and stroke: shorten them":
            QCoreApplication.translate("messages", "no K up to %1 keeps the frame and the lever at most %2 mm for this crank and stroke: shorten them"),
        "must be at most %1 mm (0.866·L2), so that the time ratio K stays at most %2":
            QCoreApplication.translate("messages", "must be at most %1 mm (0.866·L2), so that the time ratio K stays at most %2"),
        "give 1 to %1 crank speeds": QCoreApplication.translate("messages", "give 1 to %1 crank speeds"),
        "gives more than %1 angles; use a larger step": QCoreApplication.translate("messages", "gives more than %1 angles; use a larger step"),
        "gives %1 samples (angles × speeds), more than %2; use a larger step or fewer speeds":
            QCoreApplication.translate("messages", "gives %1 samples (angles × speeds), more than %2; use a larger step or fewer speeds"),
        "gives %1 samples (angles × speeds) with %2 speeds, more than a design file holds (%3); use a step of at least %4°":
            QCoreApplication.translate("messages", "gives %1 samples (angles × speeds) with %2 speeds, more than a design file holds (%3); use a step of at least %4°"),
        "must be given either as a length or as a ratio L4/L3, not both":
            QCoreApplication.translate("messages", "must be given either as a length or as a ratio L4/L3, not both"),
        "is not a design field": QCoreApplication.translate("messages", "is not a design field"),
        "is not a load input": QCoreApplication.translate("messages", "is not a load input"),
        "is not a cam field": QCoreApplication.translate("messages", "is not a cam field"),
        "must be text": QCoreApplication.translate("messages", "must be text"),
        "must be true or false": QCoreApplication.translate("messages", "must be true or false"),
        "must be an object of load inputs": QCoreApplication.translate("messages", "must be an object of load inputs"),
        "must be an object of cam inputs": QCoreApplication.translate("messages", "must be an object of cam inputs"),
        "must be one of %1": QCoreApplication.translate("messages", "must be one of %1"),
    }


def describe(error: DesignError, name: str | None = None) -> str:
    """'Field: what is allowed' in the current UI language (``name``: the field's name
    when the caller has its own, as the Gear tab has for its fields)."""
    body = allowed_text(error.allowed)
    field = field_name(error.parameter) if name is None else name
    return QCoreApplication.translate("messages", "%1: %2").replace("%1", field).replace("%2", body)


def allowed_text(allowed: str, patterns: tuple[tuple[str, str], ...] = (),
                 templates: dict[str, str] | None = None) -> str:
    """Core's English ``allowed`` text in the UI's language: the first of ``patterns``
    (with its ``templates``), then of this module's, that matches; else a statement and its
    advice after the last "; ", each matched (the advice by _ADVICE_PATTERNS: one advice
    serves many statements); else the text as it is."""
    table = {**_translated_templates(), **(templates or {})}
    whole = _matched(allowed, patterns + _PATTERNS, table)
    if whole is not None:
        return whole
    head, sep, tail = allowed.rpartition("; ")
    if sep:
        said, advice = _matched(head, patterns + _PATTERNS, table), _matched(tail, _ADVICE_PATTERNS, table)
        if said is not None and advice is not None:
            return table["%1; %2"].replace("%1", said, 1).replace("%2", advice, 1)
    return allowed


def _matched(text: str, patterns: tuple[tuple[str, str], ...], table: dict[str, str]) -> str | None:
    """``text`` by the template of the first of ``patterns`` that matches it, or None."""
    for pattern, template in patterns:
        match = re.match(pattern, text)
        if match:
            body = table[template]
            for i, group in enumerate(match.groups(), start=1):
                body = body.replace(f"%{i}", group or "")
            return body.strip()
    return None
