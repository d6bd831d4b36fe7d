"""``shaper sweep``, ``curves`` and ``dynamics`` keep freed memory in the process
(core.cli.allocator, issue 24)."""
import platform
import subprocess
import sys

import pytest

from core.cli import allocator, cmd_sweep, main, streaming

GLIBC = platform.libc_ver()[0] == "glibc"

# mallopt returns 0 for a value it refuses, so a refused setting shows in the result.
PROBE = ("from core.cli.allocator import keep_freed_memory\n"
         "print(keep_freed_memory())\n")


@pytest.mark.skipif(not GLIBC, reason="the thresholds are glibc's")
def test_glibc_takes_both_thresholds():
    """Run in a fresh process, so that this test run's allocator is left alone."""
    done = subprocess.run([sys.executable, "-c", PROBE], capture_output=True, text=True,
                          timeout=60)
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == "True"


def test_a_refused_threshold_is_reported(monkeypatch):
    """An allocator that refuses a setting (mallopt returns 0) gives False, not an error."""
    class Refusing:
        gnu_get_libc_version = None

        class mallopt:  # noqa: N801 - stands in for the C function
            argtypes = restype = None

            def __new__(cls, parameter, value):
                return 0
    monkeypatch.setattr(allocator.ctypes, "CDLL", lambda name: Refusing)
    assert allocator.keep_freed_memory() is False


def test_no_glibc_does_nothing(monkeypatch):
    class Musl:
        mallopt = None                      # no gnu_get_libc_version
    monkeypatch.setattr(allocator.ctypes, "CDLL", lambda name: Musl)
    assert allocator.keep_freed_memory() is False


def test_sweep_keeps_freed_memory(monkeypatch, tmp_path):
    calls = []
    monkeypatch.setattr(cmd_sweep, "keep_freed_memory", lambda: calls.append(1) or True)
    out = tmp_path / "sweep.csv"
    assert main(["sweep", "--crank", "100", "--K", "1.46", "--stroke", "312", "--vary",
                 "crank=90:110:3", "--rpm", "40", "--csv", str(out)]) == 0
    assert calls == [1] and len(out.read_text().splitlines()) == 4


def test_streamed_tables_keep_freed_memory(monkeypatch, tmp_path):
    """shaper curves and dynamics stream their tables block by block through write_table."""
    calls = []
    monkeypatch.setattr(streaming, "keep_freed_memory", lambda: calls.append(1) or True)
    out = tmp_path / "curves.csv"
    assert main(["curves", "--crank", "100", "--K", "1.4", "--stroke", "300", "--step", "10",
                 "--csv", str(out)]) == 0
    assert calls == [1] and len(out.read_text().splitlines()) == 1 + 2 * 37
