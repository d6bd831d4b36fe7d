"""One domain exception for every bad input, so front ends can name the field.

The CLI maps ``parameter`` to an option name, the GUI to a form field and a
translated message; neither has to parse the text.
"""
from __future__ import annotations

import errno
import math
import os


class DesignError(ValueError):
    """A parameter is outside the range the mechanism can be built with.

    ``parameter`` is the core name (``crank``, ``time_ratio``, ``stroke`` …),
    ``value`` the offending value and ``allowed`` a human-readable range.
    """

    def __init__(self, parameter: str, value: object, allowed: str) -> None:
        self.parameter = parameter
        self.value = value
        self.allowed = allowed
        super().__init__(f"{parameter} = {_fmt(value)}: {allowed}")


# Why a design file is refused: core's English sentence for each reason ({name} the file,
# {0}, {1} … the values). A front end in another language keys its own sentences on the
# reason (shaperapp/widgets/messages.py), so it never has to parse this text.
FILE_REASONS = {
    "too_large": "{name} is larger than {0} MB, too large to be a design file",
    "not_design": "{name} is not a shaper design file",
    "version": "{name} has an unsupported version ({0}); this program reads version {1}",
    "no_version": "{name} has an unsupported version (missing); this program reads version {0}",
    "no_spec": "{name} holds no design (its 'spec' entry is missing)",
    "invalid": "{name}: invalid design ({0})",
    "unreadable": "cannot read {name}: {0}",
    "not_regular": "{name} is not a regular file",
    "folder": "{name} is a folder, not a design file",
    "special": "{name} is not a regular file (a device, pipe or socket)",
    "not_utf8": "{name} is not a design file (not UTF-8 text)",
    "too_deep": "{name} is not a design file (nested more than {0} levels deep)",
    "not_json": "{name} is not a design file (not valid JSON)",
    "constant": "{name} is not a design file ({0} is not a number a design may hold)",
    "long_integer": "{name} is not a design file (an integer of {0} digits is too large)",
    "huge_number": "{name} is not a design file ({0} is too large a number)",
    "duplicate_key": "{name} is not a design file (the key {0} appears twice in one object)",
    "spec_type": "{name}: 'spec' must be an object of design fields",
    "rpm_type": "{name}: 'rpm' must be a list of crank speeds in r/min",
    "rpm_value": "{name}: crank speed {0} is not a number",
    "step_type": "{name}: 'step_deg' must be a number of degrees",
}


class FileFormatError(ValueError):
    """A design file that cannot be read; the current design stays untouched.

    ``reason`` is a key of ``FILE_REASONS``, ``name`` the file as the user named it,
    ``entry`` the design library entry's name when the document is one, ``values`` what
    the sentence quotes, ``cause`` the DesignError of an invalid design and ``errno``
    the system's error number of an unreadable file: a front end can say it all in its
    own language. ``str()`` is the English sentence (the CLI's). A single text that is
    not a reason is kept as the message, with ``reason`` empty.
    """

    def __init__(self, reason: str, name: str = "", *values: object, entry: str | None = None,
                 cause: Exception | None = None, errno: int | None = None) -> None:
        self.reason = reason if reason in FILE_REASONS else ""
        self.name = name
        self.values = tuple(str(v) for v in values)
        self.entry = entry
        self.cause = cause
        self.errno = errno
        super().__init__(FILE_REASONS[reason].format(*self.values, name=name) if self.reason else reason)


# errno → a plain reason; anything else keeps the system's own wording.
_REASONS = {
    errno.ENOSPC: "the disk is full (no space left on the device)",
    errno.EDQUOT: "the disk quota is exhausted",
    errno.EACCES: "permission denied",
    errno.EPERM: "permission denied",
    errno.EROFS: "the file system is read-only",
    errno.ENOENT: "the folder does not exist",
    errno.ENOTDIR: "a part of the path is not a folder",
    errno.EISDIR: "it is a folder",
    errno.ELOOP: "too many levels of symbolic links",
    errno.ENAMETOOLONG: "the name is too long",
}


def os_reason(exc: OSError) -> str:
    """A short plain reason for an OSError, without the file name."""
    return _REASONS.get(exc.errno, exc.strerror or str(exc))  # type: ignore[arg-type]


class WriteError(OSError):
    """A file could not be written. ``filename`` is the path the user gave (never a
    temporary file) and ``strerror`` a plain reason, e.g. that the disk is full."""

    def __init__(self, path: str | os.PathLike, cause: OSError) -> None:
        super().__init__(cause.errno, os_reason(cause), os.fspath(path))

    def __str__(self) -> str:
        return f"cannot write {self.filename or repr(self.filename)}: {self.strerror}"


MAX_VALUE_TEXT = 60      # characters of a value quoted in a message


def long_integer_text(value: int) -> str | None:
    """An integer too long to quote (more than 15 digits: 1e300 in a file became a
    301-digit int, and the cut message lost its reason) as 1e+300, or as "a 400-digit
    integer" beyond a float's range; None for a short one, quoted as it is."""
    digits = len(str(abs(value))) if abs(value) < 10 ** 4000 else None
    if digits is not None and digits <= 15:
        return None
    try:
        return f"{value:.6g}"
    except OverflowError:
        return f"a {digits or 'more than 4000'}-digit integer"


def _fmt(value: object) -> str:
    if isinstance(value, float):
        return f"{value:.6g}"
    if type(value) is int:
        return long_integer_text(value) or str(value)
    text = repr(value) if isinstance(value, str) else str(value)
    return text if len(text) <= MAX_VALUE_TEXT else text[:MAX_VALUE_TEXT - 3] + "..."


def require_finite(parameter: str, value: object) -> float:
    try:
        number = float(value)  # type: ignore[arg-type]
    except (TypeError, ValueError):
        raise DesignError(parameter, value, "must be a number") from None
    if not math.isfinite(number):
        raise DesignError(parameter, value, "must be a finite number")
    return number


def require_range(parameter: str, value: object, low: float, high: float,
                  unit: str = "", low_open: bool = True, high_open: bool = False) -> float:
    """Check ``low < value <= high`` (openness selectable) and return it as float."""
    number = require_finite(parameter, value)
    too_low = number <= low if low_open else number < low
    too_high = number >= high if high_open else number > high
    if too_low or too_high:
        raise DesignError(parameter, number, range_text(low, high, unit, low_open, high_open))
    return number


def range_text(low: float, high: float, unit: str = "", low_open: bool = True,
               high_open: bool = False) -> str:
    """The ``allowed`` text of a range check, e.g. "must be > 1 and ≤ 5"."""
    left = ">" if low_open else "≥"
    right = "<" if high_open else "≤"
    unit_text = f" {unit}" if unit else ""
    return f"must be {left} {low:g} and {right} {high:g}{unit_text}"
