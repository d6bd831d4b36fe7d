"""Every failing gear check and every pointed tip is advised with a value to type, and the
advice works when followed as printed (issue: advice with a direction but no amount).

Each test reads the advice's first move from the text a student reads, types the printed
value, and designs the pair: it is not refused, and the check passes; 1 % less of the
printed change fails again, so the value is the least (to its rounding). On 1de6048 the
advice named a direction only ('raise x1', 'a smaller a′', 'give a smaller shift'): there
is no value to read, and the tests fail there on ``first_move``'s assertion."""
from __future__ import annotations

import re
from dataclasses import replace

import pytest

from hypothesis import HealthCheck, assume, example, given, note, settings, strategies as st

from core.base.errors import DesignError
from core.gear import GearPairInputs, design_pair, pair_checks
from core.gear.margins import check_margins
from core.gear.pair import probe_pair

from sweeps import examples
from test_gear_advice import pairs                    # the pairs whose advice's directions are tested there

NO_MOVE = "no change of one shift or of a′ makes it pass: try other teeth"
SHRINK = 0.99


def checks_of(pair) -> dict:
    return {c.name: c for c in pair_checks(pair)}


def first_move(advice: str) -> tuple[str, tuple[float, ...]]:
    """The first change the advice names, with the values it says to type: ('x1', (v,)),
    ('centre', (mm,)) or ('transfer', (x1, x2))."""
    move = advice.split(": ", 1)[1].split(" or ")[0]
    if m := re.match(r"(?:raise|lower) (x1|x2) to [≥≤] (\S+)", move):
        return m.group(1), (float(m.group(2)),)
    if m := re.match(r"(?:raise|lower) a′ to [≥≤] (\S+) mm", move):
        return "centre", (float(m.group(1)),)
    if m := re.match(r"x1 = (\S+) and x2 = (\S+) \(a′ about the same\)", move):
        return "transfer", (float(m.group(1)), float(m.group(2)))
    raise AssertionError(f"no value to type in {advice!r}")


def followed(pair, name: str, values: tuple[float, ...], share: float = 1.0) -> GearPairInputs:
    """The inputs typed after ``share`` of the change to ``values`` along ``name``."""
    p, x1, x2 = pair.inputs, pair.gear1.shift, pair.gear2.shift
    if name == "x1":
        return replace(p, x1=x1 + share * (values[0] - x1), x2=x2, centre_mm=None)
    if name == "x2":
        return replace(p, x1=x1, x2=x2 + share * (values[0] - x2), centre_mm=None)
    if name == "centre":
        return replace(p, x1=None, x2=None, centre_mm=pair.centre_mm + share * (values[0] - pair.centre_mm))
    if share == 1.0:
        return replace(p, x1=values[0], x2=values[1], centre_mm=None)
    return replace(p, x1=x1 + share * (values[0] - x1), x2=x2 + share * (values[1] - x2), centre_mm=None)


def passes(inputs: GearPairInputs, check: str) -> bool:
    """Whether ``inputs`` design and ``check`` passes: the verdict ``pair_checks`` gives
    (each ``Check.ok`` is its margin's, ``core.gear.checks``) of the pair ``design_pair``
    gives, or False where it refuses. Read through ``probe_pair`` and the margins, which
    refuse the same inputs and give the same pair but search no value to type: neither the
    refusal's (a pointed tip's ``tip_bound``) nor each failing check's advice. Those
    searches were 13-26 s of ``_assert_none_smaller``'s 800 designs an example."""
    try:
        return check_margins(probe_pair(inputs))[check].ok
    except DesignError:
        return False


def make(d: dict) -> GearPairInputs:
    kwargs = {k: d[k] for k in ("z1", "z2", "module_mm", "pressure_angle_deg", "addendum", "clearance")}
    if d["mode"] == "given":
        kwargs.update(x1=d["x1"], x2=d["x2"])
    elif d["mode"] == "centre":
        kwargs.update(centre_mm=d["module_mm"] * ((d["z1"] + d["z2"]) / 2.0 + d["y"]))
    return GearPairInputs(**kwargs)


STANDARD = dict(pressure_angle_deg=20.0, addendum=1.0, clearance=0.25)
TAB = dict(z1=13, z2=40, module_mm=6.0, mode="centre", x1=0.0, x2=0.0, **STANDARD)


# Slow sweeps (tests/sweeps.py): each example designs the pair along every helpful change
# (3 ms a failing check, 4-11 s for 250); CI draws a share, HYPOTHESIS_PROFILE=thorough all 250.
@pytest.mark.slow
@settings(max_examples=examples(250), deadline=None)
@given(pairs)
@example(dict(TAB, y=2.0))                                   # the Gear tab's pair at a′ = 171 mm
@example(dict(TAB, z1=10, y=-3.0))                           # the 10/40 at a′ = 162 mm
@example(dict(TAB, mode="given", x1=0.9, x2=0.5, y=0.0))     # ε too small with typed shifts
@example(dict(TAB, mode="given", x1=0.0, x2=0.0, y=0.0))     # interference at the pinion's root
@example(dict(TAB, z1=10, z2=14, module_mm=5.0, mode="auto", y=0.0))   # the rule's pair: ε < 1.2
def test_the_first_advised_move_as_printed_makes_the_check_pass(d):
    try:
        pair = design_pair(make(d))
    except DesignError:
        assume(False)
        return
    failing = [c for c in pair_checks(pair) if not c.ok and not c.name.startswith("undercut")]
    assume(failing)
    for check in failing:
        if check.advice.endswith(NO_MOVE):
            assert not check.moves
            note(f"{check.name}: {check.advice}")
            continue
        name, values = first_move(check.advice)
        typed = followed(pair, name, values)
        after = design_pair(typed)                 # not refused: a DesignError fails the test
        assert checks_of(after)[check.name].ok, (check.advice, typed)
        assert not passes(followed(pair, name, values, SHRINK), check.name), (check.advice, "not the least")


def test_a_move_that_breaks_another_check_says_so_and_comes_last():
    """ε too small at x1 = 0.9, x2 = 0.5: lowering x2 alone thins the pinion's tip; the
    advice says so, and a move that breaks nothing is named first."""
    pair = design_pair(GearPairInputs(z1=13, z2=40, module_mm=6.0, x1=0.9, x2=0.5))
    check = checks_of(pair)["contact"]
    assert not check.ok
    for move in check.moves:
        name, values = move.name, tuple(float(v) for v in move.to)
        after = checks_of(design_pair(followed(pair, name, values)))
        broken = {n for n, c in after.items() if not c.ok and checks_of(pair)[n].ok and n != "contact"}
        assert set(move.breaks) == broken
    assert [bool(m.breaks) for m in check.moves] == sorted(bool(m.breaks) for m in check.moves)
    assert any(m.breaks for m in check.moves) and "(but then the tip of gear 1 is too thin)" in check.advice


pointed = st.builds(
    dict, z1=st.integers(5, 40), z2=st.integers(5, 120), module_mm=st.sampled_from([1.0, 2.0, 6.0]),
    mode=st.sampled_from(["given", "centre"]), x1=st.floats(0.3, 3.0), x2=st.floats(-0.5, 3.0),
    y=st.floats(1.0, 8.0))


@pytest.mark.slow
@settings(max_examples=examples(250), deadline=None, suppress_health_check=[HealthCheck.filter_too_much])
@given(pointed)
@example(dict(z1=13, z2=40, module_mm=6.0, mode="centre", x1=0.0, x2=0.0, y=41.0 / 6.0 - 0.5))  # a′ = 200 mm (report test)
@example(dict(z1=13, z2=40, module_mm=6.0, mode="given", x1=1.5, x2=0.0, y=0.0))
@example(dict(z1=13, z2=21, module_mm=2.0, mode="given", x1=-0.9461272910525702, x2=2.8154224494177633, y=0.0,
              rack=dict(pressure_angle_deg=17.802305639051898, addendum=1.0763935887716758, clearance=0.25)))  # no flank
@example(dict(z1=15, z2=6, module_mm=2.0, mode="auto", x1=0.0, x2=0.0, y=0.0,
              rack=dict(pressure_angle_deg=12.513408553490448, addendum=1.4743192032882475, clearance=0.25)))  # the rule's
def test_a_pointed_tip_is_refused_with_the_value_that_mends_it(d):
    """On the GB/T 1356 rack (and two others, for the rule's teeth and a tip left no flank): the refusal names the value (x_k, a′ or z_k) at which the tip
    is thick enough; typed, the pair designs and the tip check passes, and 1 % less of the
    change (one tooth fewer) is refused or leaves the tip too thin."""
    inputs = make(dict(d, **d.get("rack", STANDARD)))
    try:
        design_pair(inputs)
        assume(False)
        return
    except DesignError as exc:
        error = exc
    assume("pointed" in error.allowed or "no flank" in error.allowed)
    m = re.search(r"(?:tip of gear|leaves gear) (\d)", error.allowed)
    k = int(m.group(1))
    if m := re.search(r"no smaller (x\d|centre distance) found that gives a tip", error.allowed):
        _assert_none_smaller(inputs, m.group(1), k)
        return
    m = re.search(r"give (x\d|a′|z\d) [≤≥] (\S+?),? (?:mm, )?for a tip", error.allowed)
    assert m, f"no value to type in {error.allowed!r}"
    name, value = m.group(1), float(m.group(2))
    field = {"a′": "centre_mm"}.get(name, name)
    before = getattr(inputs, field)
    assert before is not None, f"advises {name}, which was not typed: {error.allowed}"
    typed = replace(inputs, **{field: int(value) if field.startswith("z") else value})
    assert check_margins(design_pair(typed))[f"tip{k}"].ok, (error.allowed, typed)   # a refusal fails
    if field.startswith("z"):
        less = replace(inputs, **{field: int(value) - 1})
    else:
        less = replace(inputs, **{field: before + SHRINK * (value - before)})
    assert not passes(less, f"tip{k}"), (error.allowed, "not the least")


def _assert_none_smaller(inputs: GearPairInputs, name: str, k: int) -> None:
    """'No smaller x_k (a′) found that gives a tip thick enough', checked on 800 values down
    to the range's end (x_k to −5; a′ to a cos α), not by the advice's own search: any value
    that passes lies in a window narrower than 2 % of the way to it (the search's known
    limit: a window inside one refusal, narrower than its step, is not seen)."""
    now = inputs.centre_mm if name == "centre distance" else getattr(inputs, name)
    low = inputs.module_mm * (inputs.z1 + inputs.z2) / 2.0 * 0.9396926 if name == "centre distance" else -5.0
    values = [low + (now - low) * i / 800 for i in range(1, 800)]
    field = "centre_mm" if name == "centre distance" else name
    ok = [v for v in values if passes(replace(inputs, **{field: v}), f"tip{k}")]
    assert not ok or max(ok) - min(ok) < 0.02 * (now - max(ok)), (name, min(ok), max(ok))
