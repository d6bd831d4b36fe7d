"""The command line asks OpenBLAS for one thread before numpy loads (core.base.blas, issue 24):
its spinning worker threads cost every short command about 0.1 s of CPU."""
from __future__ import annotations

import os
import subprocess
import sys

import pytest

PROBE = ("import os, core.cli, numpy\n"
         "print(len(os.listdir('/proc/self/task')), os.environ.get('OPENBLAS_NUM_THREADS'))\n")


def _probe(**env: str) -> str:
    clean = {k: v for k, v in os.environ.items() if k != "OPENBLAS_NUM_THREADS"}
    done = subprocess.run([sys.executable, "-c", PROBE], capture_output=True, text=True,
                          env={**clean, **env}, timeout=60)
    assert done.returncode == 0, done.stderr
    return done.stdout.strip()


@pytest.mark.skipif(not os.path.isdir("/proc/self/task"), reason="counts threads in Linux's /proc")
def test_the_cli_runs_numpy_on_one_thread():
    assert _probe() == "1 1"


def test_a_users_choice_is_kept():
    assert _probe(OPENBLAS_NUM_THREADS="2").split()[1] == "2"
