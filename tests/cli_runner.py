"""Run the installed ``shaper`` console script (or ``python -m core`` if absent)."""
import shutil
import subprocess
import sys


def shaper(*args, input_text=None, cwd=None):
    exe = shutil.which("shaper")
    cmd = [exe] if exe else [sys.executable, "-m", "core"]
    return subprocess.run(cmd + [str(a) for a in args], capture_output=True, text=True,
                          input=input_text, cwd=cwd, timeout=120)


def shaper_in_process(*args):
    """``core.cli.main(args)`` in this process with stdout and stderr captured:
    (exit status, stdout, stderr). Much faster than a subprocess, for fuzzing.
    argparse's own exits (--help, --version) count as their status. A ``--lang zh`` run
    sets this process's language: it is set back to English, the tests' own, so that a
    later test in the same process (any order, any xdist worker) does not read Chinese."""
    import contextlib
    import io

    from core.cli import main

    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        try:
            status = main([str(a) for a in args])
        except SystemExit as exc:
            status = exc.code if isinstance(exc.code, int) else (0 if exc.code is None else 2)
        finally:
            if "shaperapp.widgets.i18n" in sys.modules:
                sys.modules["shaperapp.widgets.i18n"].set_language("en")
    return status, out.getvalue(), err.getvalue()


def shaper_process(*args, ascii_console: bool = False, cwd=None):
    """``python -m core ARGS`` as a real process, its console UTF-8 or (``ascii_console``)
    ASCII, whose output must then be ASCII: (exit status, stdout, stderr)."""
    import os
    env = dict(os.environ, PYTHONIOENCODING="ascii" if ascii_console else "utf-8")
    done = subprocess.run([sys.executable, "-m", "core", *[str(a) for a in args]], capture_output=True,
                          env=env, cwd=cwd, timeout=120)
    if ascii_console:
        assert done.stdout.isascii() and done.stderr.isascii()
    return (done.returncode, done.stdout.decode("utf-8", "replace"),
            done.stderr.decode("utf-8", "replace"))


def shaper_run_in_process(*args) -> subprocess.CompletedProcess:
    """:func:`shaper_in_process` answering as :func:`shaper` does (``returncode``, ``stdout``,
    ``stderr``), for tests of what a command writes rather than of its process: a report or
    a course in this process costs no second start of Python, Qt and scipy (about 2.5 s of
    CPU). The language is set back as :func:`shaper_in_process` sets it back."""
    status, out, err = shaper_in_process(*args)
    return subprocess.CompletedProcess([str(a) for a in args], status, out, err)
