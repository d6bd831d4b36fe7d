"""``.ci/run``'s system-package step, with ldconfig, id and apt-get replaced by stubs.

The stubs stand in for a fresh machine: ``ldconfig -p`` prints a cache we
choose, ``apt-get`` records how it was called. ``SHAPER_CI_SYSTEM_ONLY=1``
stops the script before it installs Python packages and runs pytest.
"""
import os
import stat
import subprocess
from pathlib import Path

import pytest

pytestmark = pytest.mark.slow   # left out of the quick run: pytest -m "not slow"

SCRIPT = Path(__file__).resolve().parents[1] / ".ci" / "run"
SONAMES = ("libEGL.so.1", "libGL.so.1", "libxkbcommon.so.0", "libfontconfig.so.1",
           "libglib-2.0.so.0", "libdbus-1.so.3")


LIBRARY_PACKAGES = ("libegl1", "libgl1", "libxkbcommon0", "libfontconfig1", "libglib2.0-0", "libdbus-1-3")


def installed(calls: list[str]) -> list[str]:
    """The package names of apt-get's install calls."""
    return [w for c in calls if c.split()[0] == "install" for w in c.split()[1:] if not w.startswith("-")]


def stub(folder: Path, name: str, body: str) -> None:
    path = folder / name
    path.write_text("#!/bin/sh\n" + body + "\n")
    path.chmod(path.stat().st_mode | stat.S_IXUSR)


def run_ci(tmp_path: Path, sonames, filler: int = 0) -> tuple[subprocess.CompletedProcess, list[str]]:
    """Run the system step with a linker cache holding ``sonames`` (followed by ``filler``
    unrelated lines); return the process and apt-get's calls."""
    bin_dir = tmp_path / "bin"
    bin_dir.mkdir(exist_ok=True)
    cache = tmp_path / "cache.txt"
    lines = [f"{len(sonames) + filler} libs found in cache `/etc/ld.so.cache'"]
    lines += [f"\t{s} (libc6,x86-64) => /lib/x86_64-linux-gnu/{s}" for s in sonames]
    lines += [f"\tlibfiller{i}.so.{i} (libc6,x86-64) => /lib/libfiller{i}.so.{i}" for i in range(filler)]
    cache.write_text("\n".join(lines) + "\n")
    calls = tmp_path / "apt.log"
    calls.write_text("")
    stub(bin_dir, "ldconfig", f'cat "{cache}"')
    stub(bin_dir, "id", 'echo 0')
    stub(bin_dir, "apt-get", f'echo "$*" >> "{calls}"')
    env = dict(os.environ, PATH=f"{bin_dir}:{os.environ['PATH']}", SHAPER_CI_SYSTEM_ONLY="1")
    out = subprocess.run(["bash", str(SCRIPT)], capture_output=True, text=True, env=env, timeout=60)
    return out, [line for line in calls.read_text().splitlines() if line]


def test_nothing_is_installed_when_every_library_is_there(tmp_path):
    # A large cache with the libraries first, read 30 times: with `ldconfig -p | grep -q`
    # under pipefail, grep stops at the first match, ldconfig dies of SIGPIPE writing the
    # rest and the present library counts as missing (that old check misfired 30 of 30).
    # The fonts and poppler are looked up on this machine's disk, not in the stub cache:
    # on a machine without them their packages are rightly installed, so only the
    # library packages (the stubbed part) must never be.
    for _ in range(30):
        out, calls = run_ci(tmp_path, SONAMES, filler=20_000)
        assert out.returncode == 0, out.stderr
        assert not set(installed(calls)) & set(LIBRARY_PACKAGES), out.stdout


def test_only_the_missing_package_is_installed_without_upgrades(tmp_path):
    out, calls = run_ci(tmp_path, [s for s in SONAMES if s != "libGL.so.1"])
    assert out.returncode == 0, out.stderr
    installs = [c for c in calls if c.split()[0] == "install"]
    assert len(installs) == 1
    words = installs[0].split()
    assert "--no-upgrade" in words
    assert [w for w in installed(calls) if w in LIBRARY_PACKAGES] == ["libgl1"]
    assert not any(c.split()[0] in ("upgrade", "dist-upgrade", "full-upgrade") for c in calls)


@pytest.mark.parametrize("decoy", ["libGL.so.1.7.0", "libGLX.so.1"])
def test_a_similar_name_does_not_count_as_the_library(tmp_path, decoy):
    out, calls = run_ci(tmp_path, [s for s in SONAMES if s != "libGL.so.1"] + [decoy])
    assert [w for w in installed(calls) if w in LIBRARY_PACKAGES] == ["libgl1"]
