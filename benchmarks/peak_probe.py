"""Run a ``shaper`` command in a fresh process that reports its own peak resident size.

The peak is the process's own high-water mark (VmHWM), which a new program image starts
afresh. ru_maxrss is not: Linux carries the parent's peak into a forked child across exec,
so under a large test process every case read 1875 MB.
"""
import subprocess
import sys

PROBE = ("import sys\n"
         "from core.cli import main\n"
         "status = main(sys.argv[1:])\n"
         "peak = next(l for l in open('/proc/self/status') if l.startswith('VmHWM:'))\n"
         "print('PEAK_KB', peak.split()[1], file=sys.stderr)\n"
         "sys.exit(status)\n")


def peak_mb_of(*args: str, timeout: float = 600) -> float:
    """Peak resident MB of ``shaper *args`` (which must succeed)."""
    done = subprocess.run([sys.executable, "-c", PROBE, *args], capture_output=True, text=True,
                          timeout=timeout)
    assert done.returncode == 0, done.stderr
    line = next(l for l in done.stderr.splitlines() if l.startswith("PEAK_KB"))
    return int(line.split()[1]) / 1024.0
