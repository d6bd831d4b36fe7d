"""A test that hangs with Python's GIL held ends the run, with its stack printed."""
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

pytestmark = pytest.mark.slow   # left out of the quick run: pytest -m "not slow"

HERE = Path(__file__).parent

HANGING_TEST = '''
import ctypes


def test_stuck_in_c_with_the_gil_held():
    # PyDLL keeps the GIL during the call, as a deadlock inside Qt's C++ code does.
    ctypes.PyDLL(None).sleep(120)
'''


@pytest.mark.skipif(not hasattr(signal, "alarm"), reason="SIGALRM is POSIX only")
def test_a_hang_holding_the_gil_is_ended_with_its_stack(tmp_path):
    (tmp_path / "test_stuck.py").write_text(HANGING_TEST)
    # the limits as short as keeps their order (pytest-timeout, then faulthandler's dump,
    # then the hard limit, 2 s later): the run waits for the last, a worker idle meanwhile
    env = dict(os.environ, PYTHONPATH=str(HERE), SHAPER_TEST_HARD_LIMIT_S="3")
    start = time.monotonic()
    run = subprocess.run(
        [sys.executable, "-m", "pytest", "-p", "hang_guard", "-p", "no:cacheprovider",
         "-o", "faulthandler_timeout=1", "-o", "timeout=0.5", "-o", "timeout_method=thread",
         "--rootdir", str(tmp_path), str(tmp_path / "test_stuck.py")],
        cwd=tmp_path, env=env, capture_output=True, text=True, timeout=100)
    took = time.monotonic() - start
    assert run.returncode == -signal.SIGALRM, (run.returncode, run.stdout[-2000:], run.stderr[-2000:])
    assert took < 60                     # ended by the guard, not by the 120 s call returning
    # faulthandler's dump names the stuck test's frame (pytest-timeout could not act).
    assert "test_stuck_in_c_with_the_gil_held" in run.stderr, run.stderr[-2000:]
