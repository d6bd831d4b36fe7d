"""``shaper``: the whole computation without a screen.

One module per subcommand (``cmd_*.py``), each with ``configure(parser)`` and
``run(args)``; this module only builds the parser and turns every failure
into one line on stderr. Bad input exits with status 2 and names the option;
nothing ever prints a traceback.

Subcommands whose code lives outside ``core`` (the report needs Qt) are
found through the ``shaper.commands`` entry-point group, so ``core`` itself
never imports Qt.

Only the subcommand named on the command line is imported: ``shaper curves``
never loads the library, the sweep or the entry points (``importlib.metadata``),
which is a good part of a short command's start-up; ``shaper report`` loads its
own entry point only, not the drawing's (ezdxf) and the course's. ``shaper --help``
and an unknown word load them all, as before.
"""
from __future__ import annotations

import argparse
import difflib
import os
import re
import sys
from importlib import import_module
from types import ModuleType
from typing import Sequence

from core.base.blas import limit_blas_threads

limit_blas_threads()        # before numpy, which .common imports

from core.base.errors import DesignError, FileFormatError  # noqa: E402
from .common import Parser, UsageError, VersionAction, design_error_text, fail  # noqa: E402
from .notes import flush_notes  # noqa: E402
from .common import _NEGATIVE_NUMBER as _NEGATIVE  # noqa: E402  (argparse's idea of a number)
from .output import GuardedStdout, OutputError, StdoutError, install_safe_output  # noqa: E402

# Order is the order of ``shaper --help``.
CORE_COMMANDS = ("design", "synth", "curves", "analyze", "dynamics", "table", "sweep", "optimize", "cam", "gear",
                 "library")


def _command_modules(command: str | None = None) -> dict[str, ModuleType]:
    """The subcommands' modules: only ``command``'s when it is one of CORE_COMMANDS or an
    entry point's name, else every core command and every entry point's."""
    if command in CORE_COMMANDS:
        return {command: import_module(f"{__name__}.cmd_{command}")}
    from importlib import metadata
    try:
        entries = metadata.entry_points(group="shaper.commands")
    except Exception:  # a broken installation must not stop the core commands
        entries = ()
    named = [entry for entry in entries if entry.name == command]
    if named:           # ``shaper report``: the report's module alone, not the sheets' and the course's
        try:
            return {command: import_module(named[0].value)}
        except ImportError:
            pass        # as below: the command is then unknown, the others still listed
    modules = {name: import_module(f"{__name__}.cmd_{name}") for name in CORE_COMMANDS}
    for entry in entries:
        if entry.name not in modules:
            try:
                modules[entry.name] = import_module(entry.value)
            except ImportError:
                continue
    return modules


def build_parser(modules: dict[str, ModuleType] | None = None) -> argparse.ArgumentParser:
    modules = _command_modules() if modules is None else modules
    parser = Parser(prog="shaper",
                    description="Shaper quick-return mechanism (crank, slotted lever, ram): "
                                "synthesis, kinematics, forces and files, without a screen.",
                    epilog="Run 'shaper COMMAND --help' for the options and an example of each command.")
    parser.add_argument("--version", action=VersionAction)
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", parser_class=Parser)
    for name, module in modules.items():
        p = sub.add_parser(name, help=module.HELP, description=module.DESCRIPTION,
                           epilog="example:\n  " + "\n  ".join(module.EXAMPLES),
                           formatter_class=argparse.RawDescriptionHelpFormatter)
        module.configure(p)
        p.set_defaults(_run=module.run)
    return parser


def _command_parser(parser: argparse.ArgumentParser,
                    argv: Sequence[str]) -> tuple[str, argparse.ArgumentParser]:
    """The (sub)command named in ``argv`` ("library add") and its parser."""
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            for i, word in enumerate(argv):
                if word in action.choices:
                    name, sub = _command_parser(action.choices[word], argv[i + 1:])
                    return f"{word} {name}".strip(), sub
    return "", parser


def _options(parser: argparse.ArgumentParser, argv: Sequence[str]) -> tuple[str, list[str]]:
    """The (sub)command named in ``argv`` ("library add") and its option strings."""
    name, sub = _command_parser(parser, argv)
    return name, [s for action in sub._actions for s in action.option_strings]


def _stray_word(word: str, parser: argparse.ArgumentParser, argv: Sequence[str]) -> str:
    """argparse's "unrecognized arguments: 60" said as the option it follows, which took
    what it takes and left ``word`` over ('--rpm: takes one value, so '60' is left over'),
    or, when no option comes before it, as the word itself."""
    command, sub = _command_parser(parser, argv)
    hint = f"see 'shaper {command} --help'".replace("  ", " ")
    before = list(argv[:len(argv) - 1 - list(reversed(argv)).index(word)]) if word in argv else []
    # after "--" every word is positional: no option before it took the word
    option = None if "--" in before else next((w.split("=", 1)[0] for w in reversed(before)
                                              if w.startswith("-") and not _NEGATIVE.match(w)), None)
    action = next((a for a in sub._actions if option in a.option_strings), None) if option else None
    if action is None or option is None:
        return f"{word!r}: not an argument of 'shaper {command}'; {hint}".replace("  ", " ")
    count = action.nargs
    takes = ("no value" if count == 0 else "one value" if count in (None, "?") else
             f"{count} values" if isinstance(count, int) else "values")
    return f"{option}: takes {takes}, so {word!r} is left over; {hint}"


def close_match(word: str, choices: Sequence[str]) -> str | None:
    """The choice ``word`` was probably meant to be: one differing only in letter case,
    else the closest by spelling (difflib), else None."""
    same = [c for c in choices if c.lower() == word.lower()]
    if same:
        return same[0]
    found = difflib.get_close_matches(word, choices, n=1, cutoff=0.6)
    return found[0] if found else None


def with_suggestion(message: str, parser: argparse.ArgumentParser, argv: Sequence[str]) -> str:
    """argparse's message about a mistyped option or choice, naming it first and adding
    what was probably meant: '--k: unknown option; did you mean --K?'."""
    unknown = re.match(r"unrecognized arguments: (.*)$", message)
    if unknown:
        word = next((w for w in unknown.group(1).split() if w.startswith("-") and not _NEGATIVE.match(w)), "")
        name = word.split("=", 1)[0]
        if not name:        # a value left over; blank when it is an empty word ('')
            words = unknown.group(1).split()
            return _stray_word(words[0] if words else "", parser, argv)
        command, options = _options(parser, list(argv))
        match = close_match(name, options)
        hint = f"did you mean {match}?" if match else f"see 'shaper {command} --help'".replace("  ", " ")
        return f"{name}: unknown option; {hint}"
    choice = re.match(r"(argument [^:]+: invalid choice: '([^']*)' \(choose from (.*)\))$", message)
    if choice:
        options = [c.strip().strip("'") for c in choice.group(3).split(",")]
        match = close_match(choice.group(2), options)
        if match:
            return f"{choice.group(1)}; did you mean {match}?"
    return message


def _command_word(words: Sequence[str]) -> str | None:
    """The subcommand ``words`` name: the first word that is not an option (``shaper``
    itself has no option that takes a value)."""
    return next((w for w in words if not w.startswith("-")), None)


def run(argv: Sequence[str] | None) -> int:
    words = list(sys.argv[1:] if argv is None else argv)
    parser = build_parser(_command_modules(_command_word(words)))
    try:
        args = parser.parse_args(words)
    except UsageError as exc:
        raise UsageError(with_suggestion(str(exc), parser, words)) from None
    if args.command is None:
        parser.print_help()
        return 0
    return args._run(args)


def main(argv: Sequence[str] | None = None) -> int:
    install_safe_output()
    stdout = sys.stdout
    sys.stdout = GuardedStdout(stdout)  # type: ignore[assignment]
    flush_notes(False)          # none left from an earlier run in this process
    try:
        status = run(argv)
        sys.stdout.flush()
        flush_notes(True)
        return status
    except UsageError as exc:
        return fail(str(exc))
    except DesignError as exc:
        return fail(design_error_text(exc))
    except FileFormatError as exc:
        return fail(f"--design: {exc}")
    except StdoutError as exc:
        _silence_stdout()
        return fail(str(exc))
    except OutputError as exc:
        return fail(str(exc))
    except BrokenPipeError:
        # The reader went away (``shaper curves | head``): nothing more can be written.
        _silence_stdout()
        return 0
    except MemoryError:
        return fail("not enough memory for this request; ask for fewer crank angles or speeds")
    except KeyboardInterrupt:
        return fail("interrupted", status=130)
    except Exception as exc:  # never a traceback; the one line says what broke
        return fail(f"internal error ({type(exc).__name__}: {exc}); please report it", status=1)
    finally:
        flush_notes(False)      # a refusal's: not said (it is one line)
        if isinstance(sys.stdout, GuardedStdout):
            sys.stdout = stdout


def _silence_stdout() -> None:
    """Point stdout at /dev/null, so that the interpreter's final flush of what is still
    buffered cannot fail a second time and print a traceback-like warning at exit."""
    try:
        fd = sys.stdout.fileno()
    except (AttributeError, ValueError, OSError):
        return          # not a real descriptor (tests capture into a StringIO)
    try:
        null = os.open(os.devnull, os.O_WRONLY)
        os.dup2(null, fd)
        os.close(null)
    except OSError:
        pass


if __name__ == "__main__":
    sys.exit(main())
