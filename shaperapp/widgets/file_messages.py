"""Why a file could not be read or written, and what a dialog shows for a failure, in the UI's
language: a design file or library entry refused (core's reasons, ``FILE_REASONS``), a
damaged library entry, an OS error by its number. Beside ``messages`` (the design's fields
and ranges), whose ``describe`` an invalid design's reason is told with; one translation
context with it ("messages")."""
from __future__ import annotations

import errno
import os
import re

from PySide6.QtCore import QCoreApplication

from core.base.errors import DesignError, FileFormatError
from core.base.errors import os_reason as core_os_reason

from .messages import describe


def defaulted_text(name: str, defaulted: tuple[tuple[str, str], ...]) -> str:
    """What an opened design lacked and the values taken for it (``core.files.design_file.
    defaulted_keys``), said once where it was opened: a design never changes without a word."""
    taken = ", ".join(f"{key} = {value}" for key, value in defaulted)
    return QCoreApplication.translate("messages", "%1 does not give %2; these were taken.").replace(
        "%1", name, 1).replace("%2", taken, 1)


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
        from .gear_messages import gear_refusal          # the gear pair's own words, where it is the pair
        values = [gear_refusal(error.cause) or describe(error.cause)]
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
        "too_fine": QCoreApplication.translate("messages", "too fine: %1 samples, limit %2; 'shaper library export' with --step %3 writes it at a step a design file holds"),
    }
    if kind not in templates:
        return str(damage)
    cause = damage.cause
    if kind == "too_fine":          # whole, stored before the design file's sample limit
        return re.sub(r"%([123])", lambda m: (str(cause.samples), str(cause.limit), f"{cause.coarsest:g}")[
            int(m.group(1)) - 1], templates[kind])
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

