"""Issue 7, items 2, 3, 5 and 6 on the command line: floors, the sample cap, streaming,
progress, memory, undefined values, output failures and option names in messages."""
import errno
import io
import math
import os
import pty
import select
import stat
import subprocess
import sys

import numpy as np
import pytest

from core.forces.dynamics import solve_dynamics
from core.forces.masses import MIN_DELTA, MassProperties

from core.files.dynamics_io import dynamics_csv
from core.base.errors import DesignError
from core.forces.flywheel import summarize
from core.linkage.geometry import synthesize
from core.files.io import curves_csv, save_design, table_csv
from core.linkage.kinematics import (MAX_SAMPLES, MAX_SPEEDS, MIN_RPM, MIN_STEP_DEG, angle_count,
                             check_request, crank_angles, solve)
from core.linkage.spec import Spec

from cli_runner import shaper, shaper_in_process
from output_checks import finite_csv, finite_json, read_fifo_in_background

pytestmark = pytest.mark.slow   # left out of the quick run: pytest -m "not slow"

SEED = ["--crank", "100", "--K", "1.4", "--stroke", "300"]
LOADS = ["--lever-mass", "20", "--lever-inertia", "1.1", "--ram-mass", "70", "--cut-force", "7000"]


def one_error_line(status, stderr, option):
    assert status == 2, stderr
    lines = stderr.splitlines()
    assert len(lines) == 1 and lines[0].startswith("shaper: error: "), stderr
    assert "Traceback" not in stderr
    assert lines[0].startswith(f"shaper: error: {option}"), lines[0]
    return lines[0]


# ---- item 2: floors, nothing infinite or undefined -------------------------------------

@pytest.mark.parametrize("rpm", ["5e-324", "1e-320", "0.0099", "0", "-0", "-1e5"])
def test_crank_speed_below_the_floor_is_refused(rpm):
    status, out, err = shaper_in_process("curves", *SEED, "--angles", "0,90", "--rpm", rpm)
    assert "0.01" in one_error_line(status, err, "--rpm") and out == ""


@pytest.mark.parametrize("step", ["5e-324", "1e-320", "0.00019", "-0", "90.5", "nan"])
def test_angle_step_below_the_floor_is_refused(step):
    status, out, err = shaper_in_process("curves", *SEED, "--rpm", "40", "--step", step)
    one_error_line(status, err, "--step")


@pytest.mark.parametrize("command", [["curves", "--step", "30", "--rpm", "0.01", "1000"],
                                     ["analyze", "--rpm", "0.01", "1000", "--json"],
                                     ["dynamics", *LOADS, "--rpm", "0.01", "1000", "--json"],
                                     ["dynamics", *LOADS, "--rpm", "0.01", "--delta", str(MIN_DELTA),
                                      "--cut-force", "1e9", "--step", "30", "--csv", "-"]])
def test_the_slowest_and_fastest_speeds_give_finite_output(command):
    status, out, err = shaper_in_process(command[0], *SEED, "--rod-ratio", "0.3", *command[1:])
    assert status == 0 and err == "", err
    if "--json" in command:
        finite_json(out)
    else:
        header, rows = finite_csv(out)
        assert rows


def test_time_at_the_slowest_speed_is_phi_over_omega():
    motion = solve(synthesize(100, 1.4, 300), crank_angles(90), [MIN_RPM])
    assert motion.time[0, -1] == pytest.approx(60.0 / MIN_RPM)      # one turn: 6000 s


def test_delta_below_its_floor_is_refused_and_the_flywheel_stays_finite():
    with pytest.raises(DesignError) as info:
        MassProperties(delta=5e-324)
    assert info.value.parameter == "delta"
    design = synthesize(100, 1.4, 300, rod_ratio=0.3)
    masses = MassProperties(lever_mass_kg=1e6, lever_inertia_kg_m2=1e6, ram_mass_kg=1e6,
                            cut_force_N=1e9, delta=MIN_DELTA)
    for s in summarize(design, [MIN_RPM, 1000.0], masses).speeds:
        assert all(math.isfinite(v) for v in (s.flywheel_inertia_kg_m2, s.energy_fluctuation_J,
                                              s.max_torque_N_m, s.mean_power_W))


def test_nan_is_written_as_an_empty_cell():
    text = table_csv(("a_mm", "b_mm"), np.array([[1.5, np.nan], [np.nan, -2.0]]))
    assert text == "a_mm,b_mm\n1.5,\n,-2\n"


def test_guide_offset_without_guide_force_is_an_empty_cell():
    # No gravity and no cut: the block variant's guide carries no force at all, so the
    # line of action of its reaction is undefined at every angle.
    status, out, err = shaper_in_process("dynamics", *SEED, "--lever-mass", "20", "--lever-inertia",
                                         "1.1", "--ram-mass", "70", "--cut-force", "0",
                                         "--no-gravity", "--step", "15", "--csv", "-")
    assert status == 0, err
    header, rows = finite_csv(out)
    column = header.index("guide_offset_mm")
    normal = header.index("guide_normal_N")
    assert all(row[column] == "" and float(row[normal]) == 0.0 for row in rows)
    empty = [i for i, name in enumerate(header) if any(row[i] == "" for row in rows)]
    assert empty == [column]


def test_guide_offset_is_a_number_where_the_guide_carries_force():
    status, out, err = shaper_in_process("dynamics", *SEED, *LOADS, "--rod-ratio", "0.3",
                                         "--step", "15", "--csv", "-")
    header, rows = finite_csv(out)
    column = header.index("guide_offset_mm")
    assert status == 0 and all(row[column] != "" for row in rows)


# ---- item 3: the sample cap, streaming, progress, memory -----------------------------------

def test_check_request_is_the_cap_on_angles_times_speeds():
    assert check_request(MAX_SAMPLES, 1) == MAX_SAMPLES
    assert check_request(MAX_SAMPLES // MAX_SPEEDS, MAX_SPEEDS) <= MAX_SAMPLES
    with pytest.raises(DesignError) as info:
        check_request(MAX_SAMPLES // 2 + 1, 2, "step", 0.0004)
    assert info.value.parameter == "step" and info.value.value == 0.0004
    with pytest.raises(DesignError):
        check_request(1001, 10, limit=10_000)
    with pytest.raises(DesignError):
        solve(synthesize(100, 1.4, 300), np.zeros(MAX_SAMPLES // 4 + 1), [40] * 4)


def test_the_finest_step_is_within_the_cap_for_one_speed():
    assert angle_count(MIN_STEP_DEG) <= MAX_SAMPLES < 2 * angle_count(MIN_STEP_DEG)


@pytest.mark.parametrize("step", [90, 7, 1, 0.7, 1 / 3, 0.3, 0.01])
def test_angle_count_is_the_size_of_crank_angles(step):
    assert angle_count(step) == crank_angles(step).size


def test_a_request_over_the_cap_is_refused_before_anything_is_computed():
    status, out, err = shaper_in_process("curves", *SEED, "--step", str(MIN_STEP_DEG))
    line = one_error_line(status, err, "--step")
    assert str(MAX_SAMPLES) in line and "(got 0.0002)" in line and out == ""
    status, out, err = shaper_in_process("dynamics", *SEED, *LOADS, "--step", "0.0003",
                                         "--rpm", "30", "60", "--csv", "-")
    one_error_line(status, err, "--step")


@pytest.mark.parametrize("variant", [[], ["--rod-ratio", "0.3", "--rod-side", "leading"]])
def test_streamed_tables_equal_the_whole_table(monkeypatch, variant):
    monkeypatch.setattr("core.cli.streaming.CHUNK_ANGLES", 7)    # many blocks, ragged last one
    spec = Spec(variant="rod", rod_input="ratio", rod_ratio=0.3, rod_side="leading") if variant else Spec()
    design, phi = spec.design(), crank_angles(2.5)
    status, out, err = shaper_in_process("curves", *SEED, *variant, "--step", "2.5", "--rpm", "40", "77")
    assert status == 0 and out == curves_csv(solve(design, phi, [40, 77]))
    masses = MassProperties(lever_mass_kg=20, lever_inertia_kg_m2=1.1, ram_mass_kg=70, cut_force_N=7000)
    status, out, err = shaper_in_process("dynamics", *SEED, *variant, *LOADS, "--step", "2.5",
                                         "--rpm", "40", "77", "--csv", "-")
    assert status == 0 and out == dynamics_csv(solve_dynamics(design, phi, [40, 77], masses))


def test_memory_error_is_one_line(monkeypatch):
    def exhausted(*args, **kwargs):
        raise MemoryError()
    monkeypatch.setattr("core.linkage.kinematics.solve", exhausted)   # imported by cmd_curves when it runs
    status, out, err = shaper_in_process("curves", *SEED, "--step", "10")
    assert status == 2 and err.count("\n") == 1 and "not enough memory" in err


MEASURE = r"""
import resource, subprocess, sys, time
start = time.perf_counter()
done = subprocess.run(sys.argv[1:], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
elapsed = time.perf_counter() - start
print(done.returncode, elapsed, resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss, repr(done.stderr))
"""


def test_the_largest_request_streams_in_bounded_memory():
    # The widest table (dynamics, rod variant: 21 columns) at the finest step for one
    # speed: 1 800 001 rows, about 400 MB of CSV. Computed whole, it took several GB.
    command = [sys.executable, "-m", "core", "dynamics", *SEED, *LOADS, "--rod-ratio", "0.3",
               "--rod-mass", "5", "--step", str(MIN_STEP_DEG), "--rpm", "40", "--csv", "-"]
    done = subprocess.run([sys.executable, "-c", MEASURE, *command], capture_output=True,
                          text=True, timeout=600)
    status, elapsed, peak_kb, stderr = done.stdout.split(maxsplit=3)
    assert status == "0" and stderr.strip() == "''"      # no progress: stderr is not a terminal
    assert int(peak_kb) < 500 * 1024, f"peak RSS {int(peak_kb) / 1024:.0f} MB in {elapsed} s"


def test_progress_is_shown_on_a_terminal_for_a_long_run():
    """The run is made to last past the progress line's one-second delay by its reader,
    not by its size: the CSV goes to a pipe nobody reads for 1.5 s, so the command waits
    on a full pipe (it used to rely on a request just over a second long, which faster
    formatting made too short)."""
    import threading
    import time
    master, slave = pty.openpty()
    received = []
    try:
        child = subprocess.Popen([sys.executable, "-m", "core", "curves", *SEED, "--step", "0.01",
                                  "--rpm", "30", "60", "--csv", "-"],
                                 stdin=subprocess.DEVNULL, stdout=subprocess.PIPE, stderr=slave)
        os.close(slave)

        def slow_reader() -> None:
            time.sleep(1.5)
            received.append(len(child.stdout.read()))
        reader = threading.Thread(target=slow_reader)
        reader.start()
        seen = b""
        while True:
            ready, _, _ = select.select([master], [], [], 120)
            if not ready:
                break
            try:
                chunk = os.read(master, 4096)
            except OSError:       # EIO: the child closed the terminal
                break
            if not chunk:
                break
            seen += chunk
        assert child.wait(timeout=120) == 0
        reader.join(timeout=120)
    finally:
        os.close(master)
    text = seen.decode()
    percents = [int(p.split()[-1].rstrip("%")) for p in text.split("\r") if p.endswith("%")]
    assert percents and percents == sorted(percents) and "shaper: computing curves" in text
    assert text.endswith("\r") and text.split("\r")[-2].strip() == ""   # the line is erased
    assert received and received[0] > 0


def test_progress_waits_a_second_and_needs_a_terminal():
    from core.cli.streaming import Progress

    class Terminal(io.StringIO):
        def isatty(self):
            return True

    quick = Terminal()
    with Progress("x", 10, delay=1.0, stream=quick) as bar:
        bar.update(5)
    assert quick.getvalue() == ""
    slow = Terminal()
    with Progress("x", 10, delay=0.0, stream=slow) as bar:
        bar.update(5)
    assert slow.getvalue().startswith("\rshaper: x  50%") and slow.getvalue().endswith("\r")
    pipe = io.StringIO()
    with Progress("x", 10, delay=0.0, stream=pipe) as bar:
        bar.update(5)
    assert pipe.getvalue() == ""


# ---- item 5 on the command line: outputs that are not plain files -------------------------

class FullDisk(io.StringIO):
    def write(self, text):
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))

    def flush(self):
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))


@pytest.mark.parametrize("command, prefix", [
    (["analyze", *SEED], "shaper: error: cannot write to standard output"),
    (["analyze", *SEED, "--json"], "shaper: error: cannot write to standard output"),
    (["synth", *SEED], "shaper: error: cannot write to standard output"),
    (["curves", *SEED, "--step", "1"], "shaper: error: --csv: cannot write to standard output"),
    (["dynamics", *SEED, *LOADS, "--csv", "-"], "shaper: error: --csv: cannot write to standard output"),
])
def test_a_full_stdout_is_one_clear_line(monkeypatch, command, prefix):
    from core.cli import main
    err = io.StringIO()
    monkeypatch.setattr(sys, "stdout", FullDisk())
    monkeypatch.setattr(sys, "stderr", err)
    assert main(command) == 2
    assert err.getvalue().count("\n") == 1
    assert err.getvalue().startswith(prefix) and "disk is full" in err.getvalue()


def test_a_closed_stdout_is_one_line():
    out = subprocess.run(["bash", "-c", f'exec "{sys.executable}" -m core analyze "$@" >&-', "_", *SEED],
                         capture_output=True, text=True, timeout=60)
    assert out.returncode == 2
    assert out.stderr == "shaper: error: cannot write to standard output: it is closed\n"


def test_a_reader_that_leaves_early_is_not_an_error():
    child = subprocess.Popen([sys.executable, "-m", "core", "curves", *SEED, "--step", "0.01"],
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    child.stdout.readline()
    child.stdout.close()
    assert child.wait(timeout=60) == 0
    assert child.stderr.read() == b""


def test_csv_into_a_fifo_is_written_and_the_fifo_stays(tmp_path):
    fifo = tmp_path / "pipe"
    os.mkfifo(fifo)
    reader, received = read_fifo_in_background(fifo)
    out = shaper("curves", *SEED, "--angles", "0,90", "--rpm", "40", "--csv", fifo)
    reader.join(timeout=60)
    assert out.returncode == 0, out.stderr
    assert received and received[0].startswith("rpm,crank_deg") and received[0].count("\n") == 3
    assert stat.S_ISFIFO(os.lstat(fifo).st_mode)


def test_csv_through_a_symlink_keeps_the_link_and_the_mode(tmp_path):
    real = tmp_path / "real.csv"
    real.write_text("old\n")
    real.chmod(0o640)
    link = tmp_path / "link.csv"
    link.symlink_to(real)
    out = shaper("curves", *SEED, "--angles", "0", "--rpm", "40", "--csv", link)
    assert out.returncode == 0, out.stderr
    assert link.is_symlink() and real.read_text().startswith("rpm,")
    assert stat.S_IMODE(real.stat().st_mode) == 0o640
    assert sorted(p.name for p in tmp_path.iterdir()) == ["link.csv", "real.csv"]


def test_csv_errors_name_the_users_path_not_a_temp_file(tmp_path):
    status, out, err = shaper_in_process("curves", *SEED, "--csv", tmp_path)
    line = one_error_line(status, err, "--csv")
    assert line == f"shaper: error: --csv: cannot write {tmp_path}: it is a folder"
    status, out, err = shaper_in_process("curves", *SEED, "--csv", tmp_path / "no" / "x.csv")
    assert one_error_line(status, err, "--csv").endswith(
        f"{tmp_path / 'no' / 'x.csv'}: the folder does not exist")


# ---- item 6: every message names an option of the subcommand that ran -------------------------

@pytest.mark.parametrize("words, option", [
    (["curves", "--dims", "100,99,500"], "--dims (L1)"),
    (["curves", "--dims", "100,0.0001,500"], "--dims (L2)"),
    (["analyze", "--dims", "100,300,350"], "--dims (L3)"),
    (["analyze", "--dims", "100,300,500,1"], "--dims (L4)"),
    (["analyze", "--dims", "100,300,500", "--rod", "1"], "--rod"),
    (["synth", "--crank", "100", "--K", "1.000000000001", "--stroke", "300"], "--K"),
    (["synth", "--crank", "100", "--K", "1.4", "--stroke", "100"], "--stroke"),
    (["synth", "--crank", "100", "--K", "1.4", "--stroke", "300", "--guide", "5"], "--guide"),
])
def test_design_errors_name_the_option_that_holds_the_value(words, option):
    status, out, err = shaper_in_process(*words)
    line = one_error_line(status, err, option)
    if words[0] == "synth":
        assert "--dims" not in line


def test_a_design_file_with_a_bad_override_names_the_override(tmp_path):
    path = tmp_path / "d.json"
    save_design(path, Spec(mode="dimensions", crank=100, frame=300, lever=500), [40.0], 1.0)
    status, out, err = shaper_in_process("synth", "--design", path, "--guide", "5")
    one_error_line(status, err, "--guide")
    status, out, err = shaper_in_process("curves", "--design", path, "--rod", "1")
    one_error_line(status, err, "--rod")


def test_the_sample_cap_message_is_translated_for_the_gui(qtbot):
    from shaperapp.widgets import i18n
    from shaperapp.widgets.messages import describe

    with pytest.raises(DesignError) as info:
        check_request(angle_count(0.0005), 4, "step", 0.0005)
    try:
        assert i18n.set_language("zh_CN")
        text = describe(info.value)
        assert "2000000" in text and str(4 * angle_count(0.0005)) in text and "步长" in text
    finally:
        i18n.set_language("en")


def test_rod_side_without_a_rod_is_refused_not_ignored():
    status, out, err = shaper_in_process("synth", *SEED, "--rod-side", "leading")
    one_error_line(status, err, "--rod-side")
    status, out, err = shaper_in_process("synth", *SEED, "--rod-side", "leading", "--rod-ratio", "0.4")
    assert status == 0 and "leading" in out


@pytest.mark.parametrize("argv, option, typed", [
    (["table", *SEED, "--positions", "0"], "--positions", "0"),
    (["table", *SEED, "--positions", "-3"], "--positions", "-3"),
    (["table", *SEED, "--positions", "1e9"], "--positions", "1000000000"),
    (["table", *SEED, "--positions", "2.5"], "--positions", "2.5"),
    (["analyze", "--crank", "0", "--K", "1.4", "--stroke", "300"], "--crank", "0"),
    (["analyze", *SEED, "--rpm", "0"], "--rpm", "0"),
])
def test_the_message_echoes_a_number_as_it_was_typed(argv, option, typed):
    """"got 0", not the float's "got 0.0" (a whole number typed reads as one)."""
    status, out, err = shaper_in_process(*argv)
    line = one_error_line(status, err, option)
    assert line.endswith(f"(got {typed})"), line
