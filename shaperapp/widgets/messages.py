"""One table from core's error fields to translated field names and messages.

Core speaks English with numbers in fixed phrases; here each phrase becomes a
translatable template, so the Chinese UI never shows an English sentence.
"""
from __future__ import annotations

import errno
import os
import re

from PySide6.QtCore import QCoreApplication

from core.base.errors import DesignError, FileFormatError
from core.base.errors import os_reason as core_os_reason
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


def failure_reason(error: Exception) -> str:
    """What a dialog shows for a failure it did not foresee: a DesignError in the UI's
    language (:func:`describe`), else the exception's own text, else its type, never a
    traceback (issue 33: a preview's error reached ``sys.excepthook``)."""
    if isinstance(error, FileFormatError):
        return describe_file_error(error)
    if isinstance(error, DesignError):
        return describe(error)
    if isinstance(error, OSError):
        return describe_os_error(error)
    return str(error) or type(error).__name__


def _file_templates() -> dict[str, str]:
    # core.base.errors.FILE_REASONS in the UI's language (%1 the file, %2, %3 … the values);
    # listed literally so pyside6-lupdate finds every template.
    return {
        "too_large": QCoreApplication.translate("messages", "%1 is larger than %2 MB, too large to be a design file"),
        "not_design": QCoreApplication.translate("messages", "%1 is not a shaper design file"),
        "version": QCoreApplication.translate("messages", "%1 has an unsupported version (%2); this program reads version %3"),
        "no_version": QCoreApplication.translate("messages", "%1 has no version; this program reads version %2"),
        "no_spec": QCoreApplication.translate("messages", "%1 holds no design (its 'spec' entry is missing)"),
        "invalid": QCoreApplication.translate("messages", "%1: invalid design (%2)"),
        "unreadable": QCoreApplication.translate("messages", "cannot read %1: %2"),
        "not_regular": QCoreApplication.translate("messages", "%1 is not a regular file"),
        "folder": QCoreApplication.translate("messages", "%1 is a folder, not a design file"),
        "special": QCoreApplication.translate("messages", "%1 is not a regular file (a device, pipe or socket)"),
        "not_utf8": QCoreApplication.translate("messages", "%1 is not a design file (not UTF-8 text)"),
        "too_deep": QCoreApplication.translate("messages", "%1 is not a design file (nested more than %2 levels deep)"),
        "not_json": QCoreApplication.translate("messages", "%1 is not a design file (not valid JSON)"),
        "constant": QCoreApplication.translate("messages", "%1 is not a design file (%2 is not a number a design may hold)"),
        "long_integer": QCoreApplication.translate("messages", "%1 is not a design file (an integer of %2 digits is too large)"),
        "huge_number": QCoreApplication.translate("messages", "%1 is not a design file (%2 is too large a number)"),
        "duplicate_key": QCoreApplication.translate("messages", "%1 is not a design file (the key %2 appears twice in one object)"),
        "spec_type": QCoreApplication.translate("messages", "%1: 'spec' must be an object of design fields"),
        "rpm_type": QCoreApplication.translate("messages", "%1: 'rpm' must be a list of crank speeds in r/min"),
        "rpm_value": QCoreApplication.translate("messages", "%1: crank speed %2 is not a number"),
        "step_type": QCoreApplication.translate("messages", "%1: 'step_deg' must be a number of degrees"),
    }


def os_reason(number: int | None, fallback: str, reading: bool = False) -> str:
    """Why a file could not be read or written, by the system's error number, in the UI's
    language (core.base.errors.os_reason's reasons); ``fallback`` (the system's own words) for
    another number."""
    reasons = {
        errno.ENOSPC: QCoreApplication.translate("messages", "the disk is full (no space left on the device)"),
        errno.EDQUOT: QCoreApplication.translate("messages", "the disk quota is exhausted"),
        errno.EACCES: QCoreApplication.translate("messages", "permission denied"),
        errno.EPERM: QCoreApplication.translate("messages", "permission denied"),
        errno.EROFS: QCoreApplication.translate("messages", "the file system is read-only"),
        errno.ENOENT: QCoreApplication.translate("messages", "the file does not exist") if reading else
        QCoreApplication.translate("messages", "the folder does not exist"),
        errno.ELOOP: QCoreApplication.translate("messages", "too many levels of symbolic links"),
        errno.ENAMETOOLONG: QCoreApplication.translate("messages", "the name is too long"),
        errno.ENOTDIR: QCoreApplication.translate("messages", "a part of the path is not a folder"),
        errno.EISDIR: QCoreApplication.translate("messages", "it is a folder"),
        errno.EIO: QCoreApplication.translate("messages", "an input/output error"),
    }
    return reasons.get(number, fallback) if number is not None else fallback


def describe_os_error(error: OSError) -> str:
    """Why a write failed (a save, an export), in the UI's language (see :func:`os_reason`).
    A reason the system or core gave (in English) is translated; one the GUI already
    wrote in the UI's language (image_export's "the folder … does not exist") is kept."""
    text = error.strerror or str(error)
    if error.errno is not None and text in (os.strerror(error.errno), core_os_reason(error)):
        return os_reason(error.errno, text)
    return text


def describe_file_error(error: FileFormatError) -> str:
    """Why a design file (or library entry) was refused, in the current UI language.

    Built from the error's reason and values (``core.base.errors.FILE_REASONS``), never from
    core's English sentence; an invalid design's DesignError is described as the form
    would (:func:`describe`). An error without a reason keeps its own text."""
    template = _file_templates().get(error.reason)
    if template is None:
        return str(error)
    name = error.name if error.entry is None else \
        QCoreApplication.translate("messages", "library entry “%1”").replace("%1", error.entry)
    values = list(error.values)
    if error.reason == "invalid" and isinstance(error.cause, DesignError):
        values = [describe(error.cause)]
    elif error.reason == "unreadable":
        values = [os_reason(error.errno, values[0] if values else "", reading=True)]
    # one pass, so a value holding "%2" is never substituted again
    return re.sub(r"%(\d)", lambda m: name if m.group(1) == "1" else
                  (values[int(m.group(1)) - 2] if int(m.group(1)) - 2 < len(values) else ""), template)


def describe_damage(damage: str) -> str:
    """Why a library entry cannot be read (``core.library.rows.Damage``), in the current
    UI language; a plain text (from an older caller) is kept as it is."""
    kind = getattr(damage, "kind", None)
    templates = {    # core.library.rows.DAMAGE_TEXTS, listed literally for pyside6-lupdate
        "empty": QCoreApplication.translate("messages", "%1 is empty"),
        "not_text": QCoreApplication.translate("messages", "%1 is not text"),
        "not_integer": QCoreApplication.translate("messages", "%1 is not a whole number"),
        "not_number": QCoreApplication.translate("messages", "%1 is not a number"),
        "not_finite": QCoreApplication.translate("messages", "%1 is not a finite number"),
        "no_document": QCoreApplication.translate("messages", "there is no design document"),
        "document_not_utf8": QCoreApplication.translate("messages", "the design document is not UTF-8 text"),
        "document_refused": QCoreApplication.translate("messages", "its design document cannot be opened (%1)"),
        "not_one_line": QCoreApplication.translate("messages", "%1 is not one line of text (it holds a control character or a noncharacter)"),
    }
    if kind not in templates:
        return str(damage)
    cause = damage.cause
    if kind == "document_refused":
        value = describe_file_error(cause) if isinstance(cause, FileFormatError) else \
            failure_reason(cause) if isinstance(cause, Exception) else ""
    else:
        value = damage.key
    text = templates[kind].replace("%1", value, 1)
    if damage.table:
        tables = {"speeds": QCoreApplication.translate("messages", "crank speeds"),
                  "tags": QCoreApplication.translate("messages", "tags")}
        table = tables.get(damage.table, damage.table)
        text = re.sub(r"%([12])", lambda m: table if m.group(1) == "1" else text,
                      QCoreApplication.translate("messages", "%1: %2"))
    return text

