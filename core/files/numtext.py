"""Numbers as CSV text, a whole array at once: each value exactly as ``"%.10g" % value``.

Why: formatting the cells one by one with Python's ``%`` operator took about
0.15 s for ``shaper curves``' 72 002 rows, most of that command's time, and
most of ``shaper sweep``'s after the computing. Here the ten significant digits
come from integer arithmetic in numpy and the text is assembled from a table
of layouts (sign, where the point goes, how many digits remain once trailing
zeros are dropped), so the Python interpreter never visits a cell.

The text must stay byte-identical to ``%.10g`` (a correctly rounded decimal
conversion). The scaled value ``|x|·10^(9−e)`` is computed with one rounding
(the power of ten is exact up to 10²²), so its error is below 2·10⁻⁶; a value
whose rounding that error could change (within 10⁻⁵ of a tie), whose exponent
estimate is off, or that is very large, very small or infinite, is formatted
by Python instead, together with the rest of its row. NaN is an empty cell.
"""
from __future__ import annotations

import numpy as np

DIGITS = 10                   # significant digits, as "%.10g"
_TIE_MARGIN = 1e-5            # scaled values this close to a tie are left to Python
_MAX_POWER = 22               # 10.0**k is exact for 0 <= k <= 22
_POW10 = np.array([10.0 ** k for k in range(_MAX_POWER + 1)])


def _groups(width: int) -> tuple[np.ndarray, np.ndarray]:
    """Every number of ``width`` digits, leading zeros kept: its ASCII bytes read as one
    word (native byte order, so that writing the word back gives the same bytes), and
    its count of trailing zeros."""
    n = np.arange(10 ** width)
    places = 10 ** np.arange(width - 1, -1, -1)
    text = np.ascontiguousarray((n[:, None] // places % 10 + ord("0")).astype(np.uint8))
    trailing = sum((n % p == 0).astype(np.int64) for p in places[::-1][1:]) + (n == 0)
    return text.view(np.uint32 if width == 4 else np.uint16)[:, 0], trailing


_FOUR, _TRAILING4 = _groups(4)
_TWO, _TRAILING2 = _groups(2)

# Per cell, the bytes a layout picks from: the ten digits, then these.
_POINT, _ZERO, _MINUS, _E, _ESIGN, _E1, _E0, _SEP, _PAD = range(DIGITS, DIGITS + 9)
_EXT = _PAD + 1
_WIDTH = 17                   # the longest cell: "-0.0001234567891," or "-1.234567891e-05,"
# Layout modes: fixed notation for exponents -4 … 9 (mode e + 4), then these.
_EXPONENT, _ZERO_MODE, _EMPTY = 14, 15, 16
_MODES = 17
_COLUMN = np.arange(_WIDTH, dtype=np.uint8)       # bytes: the slot mask is made of bytes
_BLOCK_CELLS = 65_536         # cells formatted at once: a few MB of temporaries, in cache


def _layout(negative: bool, mode: int, significant: int) -> list[int]:
    """The ext positions of one cell's text (its separator included)."""
    sign = [_MINUS] if negative else []
    digits = list(range(significant))
    if mode == _EMPTY:
        return [_SEP]
    if mode == _ZERO_MODE:
        return sign + [_ZERO, _SEP]
    if mode == _EXPONENT:
        fraction = [_POINT] + digits[1:] if significant > 1 else []
        return sign + [0] + fraction + [_E, _ESIGN, _E1, _E0, _SEP]
    exponent = mode - 4
    if exponent < 0:
        return sign + [_ZERO, _POINT] + [_ZERO] * (-exponent - 1) + digits + [_SEP]
    whole = list(range(exponent + 1))
    fraction = [_POINT] + digits[exponent + 1:] if significant > exponent + 1 else []
    return sign + whole + fraction + [_SEP]


def _layouts() -> tuple[np.ndarray, np.ndarray]:
    """Every layout, as flat ext positions padded to _WIDTH, and its length; indexed by
    (negative · _MODES + mode) · DIGITS + significant − 1."""
    table = np.full((2 * _MODES * DIGITS, _WIDTH), _PAD, dtype=np.intp)
    length = np.zeros(2 * _MODES * DIGITS, dtype=np.intp)
    for negative in (0, 1):
        for mode in range(_MODES):
            for significant in range(1, DIGITS + 1):
                key = (negative * _MODES + mode) * DIGITS + significant - 1
                cells = _layout(bool(negative), mode, significant)
                table[key, :len(cells)] = cells
                length[key] = len(cells)
    return table, length


_TABLE, _LENGTH = _layouts()
_LENGTH8 = _LENGTH.astype(np.uint8)


def _separators(columns: int) -> np.ndarray:
    """The byte after each cell of a row: commas, then the newline."""
    row = np.full(columns, ord(","), dtype=np.uint8)
    row[-1] = ord("\n")
    return row


def _python_row(values: np.ndarray) -> str:
    """One row as Python's own "%.10g" writes it: the reference, and the way for a row
    holding a value the vectorized path leaves out."""
    return ",".join("" if v != v else "%.10g" % v for v in values.tolist()) + "\n"


def g10_rows(data: np.ndarray) -> str:
    """The rows of ``data`` (rows × columns) as CSV lines: each value as ``"%.10g"``,
    NaN as an empty cell, cells joined by commas, each row ended by a newline."""
    data = np.ascontiguousarray(data, dtype=float)
    if data.size == 0:
        return "".join(_python_row(row) for row in data)
    rows, columns = data.shape
    if data.size > _BLOCK_CELLS:     # its temporaries take about 200 bytes a cell: in blocks
        step = max(1, _BLOCK_CELLS // columns)
        return "".join([g10_rows(data[start:start + step]) for start in range(0, rows, step)])
    x = data.ravel()
    size = x.size
    magnitude = np.abs(x)
    negative = np.signbit(x)
    nan = np.isnan(x)
    zero = magnitude == 0.0
    finite = np.isfinite(x) & ~zero
    with np.errstate(divide="ignore", invalid="ignore"):
        exponent = np.floor(np.log10(np.where(finite, magnitude, 1.0))).astype(np.int64)
    power = (DIGITS - 1) - exponent
    usable = finite & (np.abs(power) <= _MAX_POWER)
    scale = _POW10[np.where(usable, np.abs(power), 0)]
    scaled = np.where(power >= 0, magnitude * scale, magnitude / scale)
    scaled[~usable] = 10.0 ** (DIGITS - 1)
    whole = np.floor(scaled)
    python = ~(nan | zero | usable) \
        | (scaled < 10.0 ** (DIGITS - 1)) | (scaled >= 10.0 ** DIGITS) \
        | (np.abs(scaled - whole - 0.5) < _TIE_MARGIN)
    mantissa = np.rint(scaled)
    carry = mantissa == 10.0 ** DIGITS          # 9 999 999 999.5 and up rounds to 10^10
    mantissa[carry] = 10.0 ** (DIGITS - 1)
    exponent += carry
    # The ten digits looked up four, four and two at a time (as words, not byte by byte).
    # The mantissa is a whole number below 10^10, exact in a double; so are these
    # quotients (a quotient's rounding error, about 10^-16 of it, cannot reach the
    # next whole number) and differences, and floating-point division is several
    # times faster than numpy's 64-bit integer division.
    mantissa[~usable] = 10.0 ** (DIGITS - 1)
    high = np.floor(mantissa / 1e6)
    rest = mantissa - high * 1e6
    middle = np.floor(rest / 100.0)
    low = (rest - middle * 100.0).astype(np.intp)
    high, middle = high.astype(np.intp), middle.astype(np.intp)
    trailing = np.where(low != 0, _TRAILING2[low],
                        np.where(middle != 0, 2 + _TRAILING4[middle], 6 + _TRAILING4[high]))
    significant = DIGITS - trailing
    mode = np.where((exponent >= -4) & (exponent < DIGITS), exponent + 4, _EXPONENT)
    mode[zero] = _ZERO_MODE
    mode[nan | python] = _EMPTY
    key = (((negative & ~nan & ~python) * _MODES + mode) * DIGITS + significant - 1).astype(np.int16)

    # The cells' bytes are assembled sorted by layout, so that each layout fills a
    # contiguous block of fixed-width slots; then the slots are put back in order.
    order = np.argsort(key, kind="stable")
    high, middle, low = (np.take(a, order) for a in (high, middle, low))
    ext = np.empty((size, _EXT), dtype=np.uint8)
    ext[:, 0:4].view(np.uint32)[:, 0] = _FOUR[high]
    ext[:, 4:8].view(np.uint32)[:, 0] = _FOUR[middle]
    ext[:, 8:10].view(np.uint16)[:, 0] = _TWO[low]
    ext[:, _POINT], ext[:, _ZERO], ext[:, _MINUS] = ord("."), ord("0"), ord("-")
    # The exponent's bytes only where a layout shows them (few cells, if any).
    if (mode == _EXPONENT).any():
        rows_shown = np.flatnonzero(mode[order] == _EXPONENT)
        power10 = exponent[order[rows_shown]]
        shown = np.minimum(np.abs(power10), 99)
        ext[rows_shown, _E] = ord("e")
        ext[rows_shown, _ESIGN] = np.where(power10 < 0, ord("-"), ord("+"))
        ext[rows_shown, _E1] = shown // 10 + ord("0")
        ext[rows_shown, _E0] = shown % 10 + ord("0")
    ext[:, _SEP] = np.tile(_separators(columns), rows).take(order)
    counts = np.bincount(key, minlength=_LENGTH.size)
    slots = np.empty((size, _WIDTH), dtype=np.uint8)
    first = 0
    for layout in np.flatnonzero(counts).tolist():
        last = first + int(counts[layout])
        width = int(_LENGTH[layout])
        slots[first:last, :width] = ext[first:last].take(_TABLE[layout, :width], axis=1)
        first = last
    inverse = np.empty_like(order)
    inverse[order] = np.arange(size)
    slots = np.take(slots.view(f"V{_WIDTH}")[:, 0], inverse).view(np.uint8).reshape(size, _WIDTH)
    length = _LENGTH[key]
    text = slots[_COLUMN < _LENGTH8[key][:, None]].tobytes().decode("ascii")
    if not python.any():
        return text
    # Rows holding a value left to Python: their whole line is Python's.
    row_ends = np.cumsum(length.reshape(rows, columns).sum(axis=1))
    pieces, start = [], 0
    for row in np.flatnonzero(python.reshape(rows, columns).any(axis=1)).tolist():
        pieces.append(text[start:row_ends[row - 1] if row else 0])
        pieces.append(_python_row(data[row]))
        start = int(row_ends[row])
    pieces.append(text[start:])
    return "".join(pieces)
