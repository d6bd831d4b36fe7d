"""Run the installed ``shaper`` console script (or ``python -m core`` if absent)."""
import shutil
import subprocess
import sys


def shaper(*args, input_text=None, cwd=None):
    exe = shutil.which("shaper")
    cmd = [exe] if exe else [sys.executable, "-m", "core"]
    return subprocess.run(cmd + [str(a) for a in args], capture_output=True, text=True,
                          input=input_text, cwd=cwd, timeout=120)
