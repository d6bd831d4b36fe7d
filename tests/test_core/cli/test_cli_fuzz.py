"""Fuzzing the ``shaper`` command line: every run either succeeds with finite output
or exits 2 with one line on stderr that names an option of the subcommand run.

Arguments are drawn for every core subcommand from its own options (read
from the real parser), mixing sensible values (so that many runs succeed and
their numbers are checked) with hostile ones: huge, tiny, negative, NaN,
infinite, subnormal, text, empty, Unicode, lists of the wrong length, design
files that are missing or are folders, and options that exclude each other.
Most runs call ``core.cli.main`` in this process; a few run the real command.

To keep the run short, a step that would be accepted but finer than 0.5° is
never drawn (the largest requests are timed in test_cli_limits.py instead).
"""
import os
import re
import tempfile

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from core.cli import CORE_COMMANDS, build_parser
from core.files.io import save_design
from core.linkage.spec import Spec

from cli_runner import shaper_in_process, shaper_process
from output_checks import error_names, finite_csv, finite_json
from sweeps import examples

pytestmark = pytest.mark.slow   # left out of the quick run: pytest -m "not slow"

FOLDER = tempfile.mkdtemp(prefix="shaper-fuzz-")
GOOD_FILE = os.path.join(FOLDER, "good.json")
ROD_FILE = os.path.join(FOLDER, "rod.json")
save_design(GOOD_FILE, Spec(), [40.0, 60.0], 2.0)
save_design(ROD_FILE, Spec(mode="dimensions", crank=120, frame=300, lever=600, variant="rod",
                           rod_input="ratio", rod_ratio=0.35), [30.0], 3.0)
BAD_FILE = os.path.join(FOLDER, "bad.json")
with open(BAD_FILE, "w") as handle:
    handle.write('{"format": "shaper-design", "version": 1, "spec": {"crank": "x"}}')


def _options() -> dict[str, dict[str, object]]:
    """Each computing subcommand's options: option string → its argparse action.

    ``library`` has actions of its own and keeps a database; test_cli_fuzz_library.py
    fuzzes it."""
    parser = build_parser()
    sub = next(a for a in parser._actions if a.dest == "command")
    options = {}
    for name in CORE_COMMANDS:
        actions = sub.choices[name]._actions
        if any(a.choices and isinstance(a.choices, dict) for a in actions):
            continue
        options[name] = {s: action for action in actions for s in action.option_strings}
    return options


OPTIONS = _options()
FUZZED = tuple(OPTIONS)

HOSTILE = ["0", "-0", "-1", "1e-320", "5e-324", "2.2e-308", "1e308", "-1e5", "1e9", "nan", "-nan",
           "NaN", "inf", "-inf", "Infinity", "", " ", "abc", "１００", "θ", "²", "1,2", "1,2,3",
           "1,2,3,4,5", ",", ",,", "0x10", "1_000", "1e", "-", "--", "chord", "sagitta", "height",
           "trailing", "leading", "\u202e12", "1" * 400, "9" * 400 + ".5", "\udcff", "0.0001",
           "0.00019", "1e-9", "-90", "360", "36001"]

finite = st.floats(allow_nan=False, allow_infinity=False)
any_float = st.floats().map(repr)
hostile = st.sampled_from(HOSTILE)


def sane(low, high):
    return st.floats(low, high).map(lambda v: f"{v:.6g}")


def number_list(element, low=1, high=5):
    return st.lists(element, min_size=low, max_size=high).map(",".join)


def not_fine_step(text: str) -> bool:
    try:
        value = float(text)
    except ValueError:
        return True
    return not (0.0002 <= value < 0.5)


# Sensible values per option; anything may also get a hostile or random one.
SANE = {
    "--crank": sane(40, 160), "--K": sane(1.05, 3.0), "--stroke": sane(150, 700),
    "--dims": st.one_of(number_list(sane(50, 800), 3, 4),
                        st.tuples(sane(60, 140), sane(250, 400), sane(560, 900)).map(",".join)),
    "--guide": st.sampled_from(["chord", "sagitta", "chord", "sagitta", "560", "600"]),
    "--rod": sane(150, 600), "--rod-ratio": sane(0.25, 1.5), "--rod-side": st.sampled_from(["trailing", "leading"]),
    "--rpm": sane(0.01, 1000), "--step": sane(0.5, 90), "--angles": number_list(sane(-720, 720)),
    "--lever-mass": sane(0, 100), "--lever-inertia": sane(0, 5), "--lever-cg": sane(-500, 900),
    "--ram-mass": sane(0, 200), "--ram-cg": st.tuples(sane(-50, 50), sane(-50, 50)).map(",".join),
    "--rod-mass": sane(0, 20), "--block-mass": sane(0, 10), "--crank-mass": sane(0, 50),
    "--cut-force": sane(0, 1e4), "--cut-height": sane(-100, 200), "--idle": sane(0, 0.49),
    "--delta": sane(0.0001, 0.5),
    "--design": st.sampled_from([GOOD_FILE, ROD_FILE, GOOD_FILE, ROD_FILE, os.path.join(FOLDER, "bad.json"),
                                 os.path.join(FOLDER, "missing.json"), FOLDER, ""]),
    "--csv": st.one_of(st.just("-"), st.integers(0, 50).map(lambda i: os.path.join(FOLDER, f"out{i}.csv")),
                       st.just("-"), st.sampled_from([FOLDER, os.path.join(FOLDER, "no", "x.csv")])),
}


def value_for(option: str, clean: bool) -> st.SearchStrategy[str]:
    """A sensible value when ``clean``, else sensible, hostile or any float. Output
    files are always drawn inside FOLDER (hostile ones among them)."""
    good = SANE.get(option, sane(0, 100))
    drawn = good if clean or option == "--csv" else st.one_of(good, hostile, hostile, any_float)
    return drawn.filter(not_fine_step) if option == "--step" else drawn


@st.composite
def command_lines(draw) -> list[str]:
    """argv for one core subcommand, in one of three moods: every value sensible
    (``clean``, to check the numbers of runs that succeed), every value sensible but
    one (``one``, which reaches the check of that value), or anything (``chaos``)."""
    command = draw(st.sampled_from(FUZZED))
    mood = draw(st.sampled_from(["clean", "one", "one", "chaos"]))
    options = OPTIONS[command]
    words: list[tuple[str, int]] = []        # (option, how many values)
    design = draw(st.sampled_from(["synth", "synth", "dims", "file", "none"]))
    if design == "synth" or (design == "dims" and "--dims" not in options):
        words += [("--crank", 1), ("--K", 1), ("--stroke", 1)]
    elif design == "dims":
        words.append(("--dims", 1))
    elif design == "file":
        words.append(("--design", 1))
    if command == "dynamics" and (mood != "chaos" or draw(st.booleans())):
        words += [(o, 1) for o in ("--lever-mass", "--lever-inertia", "--ram-mass", "--cut-force")]
    valued = sorted(o for o, a in options.items() if o.startswith("--") and a.nargs != 0)
    flags = sorted(o for o, a in options.items() if o.startswith("--") and a.nargs == 0
                   and o not in ("--help", "--version"))
    for option in draw(st.lists(st.sampled_from(valued), max_size=4 if mood == "chaos" else 2)):
        words.append((option, draw(st.integers(1, 3)) if options[option].nargs == "+" else 1))
    hostile_at = draw(st.integers(0, len(words) - 1)) if mood == "one" and words else -1
    argv = [command]
    for i, (option, count) in enumerate(words):
        argv.append(option)
        argv += [draw(value_for(option, clean=mood != "chaos" and i != hostile_at))
                 for _ in range(count)]
    argv += draw(st.lists(st.sampled_from(flags), max_size=2, unique=True)) if flags else []
    if mood == "chaos" and draw(st.integers(0, 5)) == 0:
        argv.insert(draw(st.integers(1, len(argv))),
                    draw(st.sampled_from(["--bogus", "stray", "-x", "--r", "--", "-1e5"])))
    return argv


@pytest.fixture(autouse=True, scope="module")
def inside_folder():
    """Run from FOLDER, so that nothing a command line names can land in the worktree."""
    here = os.getcwd()
    os.chdir(FOLDER)
    yield
    os.chdir(here)


# ---- checks ----------------------------------------------------------------------------------

NON_FINITE = re.compile(r"(?i)(?<![a-z])-?(nan|inf|infinity)(?![a-z])")


def check_finite_output(text: str) -> None:
    if not text.strip():
        return
    if text.lstrip().startswith("{"):
        finite_json(text)
    elif text.startswith("rpm,"):
        finite_csv(text)
    else:
        assert not NON_FINITE.search(text), text


def check_error_line(command: str, stderr: str) -> None:
    for option in error_names(stderr):
        assert option in OPTIONS[command], f"{command} has no option {option}: {stderr}"


def csv_target(argv: list[str]) -> str | None:
    targets = [argv[i + 1] for i, word in enumerate(argv[:-1]) if word == "--csv"]
    return targets[-1] if targets else None


def check_run(argv: list[str], status: int, stdout: str, stderr: str) -> None:
    if status == 0:
        assert stderr == "", stderr
        if any(word in ("-h", "--help") for word in argv):
            return
        check_finite_output(stdout)
        target = csv_target(argv)
        if target not in (None, "-") and os.path.isfile(target):
            with open(target, encoding="utf-8") as handle:
                check_finite_output(handle.read())
    else:
        assert status == 2, f"exit {status}: {stderr}"
        check_error_line(argv[0], stderr)


@settings(max_examples=examples(300), deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(argv=command_lines())
def test_fuzzed_command_lines_succeed_finitely_or_fail_in_one_line(argv):
    status, stdout, stderr = shaper_in_process(*argv)
    check_run(argv, status, stdout, stderr)


@settings(max_examples=examples(8), deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(argv=command_lines(), ascii_console=st.booleans())
def test_fuzzed_command_lines_as_real_processes(argv, ascii_console):
    check_run(argv, *shaper_process(*argv, ascii_console=ascii_console, cwd=FOLDER))


def test_the_fuzzer_reaches_success_and_every_subcommand():
    """The generator is not so hostile that nothing ever succeeds."""
    outcomes = {}

    # A fixed sequence of examples: whether the generator reaches every outcome must not
    # depend on the run (a random draw once missed a subcommand on CI).
    @settings(max_examples=200, deadline=None, database=None, derandomize=True,
              suppress_health_check=[HealthCheck.too_slow])
    @given(argv=command_lines())
    def sample(argv):
        status, _, _ = shaper_in_process(*argv)
        outcomes.setdefault(argv[0], set()).add(status)

    sample()
    assert set(outcomes) == set(FUZZED) and len(FUZZED) >= len(CORE_COMMANDS) - 1
    assert sum(0 in statuses for statuses in outcomes.values()) >= 3, outcomes


# ---- every option × every edge value, in an otherwise valid command line ----------------------

EDGES = ["0", "-0", "1e-320", "5e-324", "1e-9", "0.0002", "0.01", "1e6", "1e9", "1e308", "nan", "-inf"]
BASES = {
    "synth": ["synth", "--crank", "100", "--K", "1.4", "--stroke", "300", "--json"],
    "synth text": ["synth", "--crank", "100", "--K", "1.4", "--stroke", "300", "--rod", "300"],
    "analyze": ["analyze", "--crank", "100", "--K", "1.4", "--stroke", "300", "--rod-ratio", "0.4",
                "--json"],
    "curves": ["curves", "--crank", "100", "--K", "1.4", "--stroke", "300", "--rod-ratio", "0.4",
               "--step", "10"],
    "dynamics": ["dynamics", "--crank", "100", "--K", "1.4", "--stroke", "300", "--rod-ratio", "0.4",
                 "--lever-mass", "20", "--lever-inertia", "1.1", "--ram-mass", "70",
                 "--cut-force", "7000", "--step", "10", "--json",
                 "--csv", os.path.join(FOLDER, "edges.csv")],
    "dynamics text": ["dynamics", "--dims", "100,380,600", "--lever-mass", "20", "--lever-inertia",
                      "1.1", "--ram-mass", "70", "--cut-force", "7000"],
    "cam": ["cam", "--arm", "120", "--swing", "15", "--pressure", "40", "--rise", "60", "--dwell", "10",
            "--return", "60", "--crank", "100", "--K", "1.4", "--stroke", "300", "--step", "10",
            "--json", "--csv", os.path.join(FOLDER, "cam.csv")],
    "gear": ["gear", "--z1", "13", "--z2", "40", "--module", "6", "--centre", "162", "--json",
             "--csv", os.path.join(FOLDER, "gear.csv")],
    "gear shifts": ["gear", "--z1", "12", "--z2", "30", "--module", "2.5", "--x1", "0.3", "--x2", "-0.1"],
}


def with_value(base: list[str], option: str, value: str) -> list[str]:
    argv = list(base)
    if option in argv:
        argv[argv.index(option) + 1] = value
    else:
        argv += [option, value]
    return argv


@pytest.mark.parametrize("base", sorted(BASES))
def test_every_option_at_every_edge_value(base):
    """Exhaustive where the random fuzz is thin: each numeric edge (zero, subnormal,
    tiny, huge, NaN, −inf, the floors) in each option of a valid command line."""
    command = BASES[base][0]
    status, stdout, stderr = shaper_in_process(*BASES[base])
    assert status == 0, stderr
    valued = sorted(o for o, a in OPTIONS[command].items() if o.startswith("--") and a.nargs != 0
                    and o not in ("--design", "--csv"))
    failures = []
    for option in valued:
        for value in EDGES:
            if option == "--step" and not not_fine_step(value):
                continue
            argv = with_value(BASES[base], option, value)
            status, stdout, stderr = shaper_in_process(*argv)
            try:
                check_run(argv, status, stdout, stderr)
            except AssertionError as exc:
                failures.append(f"{' '.join(argv[1:])}: {str(exc)[:200]}")
    assert not failures, "\n".join(failures[:20])
