"""Comparison: figures equal ``shaper analyze``/``shaper dynamics``, curves equal ``shaper curves``."""
import csv
import io
import json

import numpy as np
import pytest

from core.space.compare import Candidate, best_indices, compare, comparison_document, curves_csv, table_csv
from core.forces.masses import MassProperties
from core.base.errors import DesignError
from core.files.io import masses_to_dict, save_design
from core.linkage.spec import Spec
# What the commands write, in this process; test_cli.py runs the real command.
from cli_runner import shaper_run_in_process as shaper

LOADS = MassProperties(lever_mass_kg=20.0, lever_inertia_kg_m2=1.1, ram_mass_kg=70.0,
                       cut_force_N=7000.0, cut_height_mm=80.0)
DESIGNS = [("block 1.4", Spec(), LOADS),
           ("rod 1.6", Spec(time_ratio=1.6, variant="rod", rod_ratio=0.35), LOADS),
           ("leading", Spec(time_ratio=1.5, stroke=320.0, variant="rod", rod_input="length",
                            rod_length=180.0, rod_side="leading"), None)]


@pytest.fixture(scope="module")
def result():
    return compare([Candidate(*d) for d in DESIGNS], rpm=55.0, step_deg=2.0)


def test_figures_equal_shaper_analyze_and_dynamics(result, tmp_path):
    rows = {r.key: r for r in result.rows}
    for k, (label, spec, masses) in enumerate(DESIGNS):
        path = tmp_path / f"{k}.json"
        save_design(path, spec, [40.0], 1.0, extra={"forces": masses_to_dict(masses)} if masses else None)
        run = shaper("analyze", "--design", path, "--rpm", 55, "--json")
        assert run.returncode == 0, run.stderr
        analyzed = json.loads(run.stdout)
        speed = analyzed["speeds"][0]
        for key in ("K", "stroke_mm", "theta_deg", "crank_mm", "frame_mm", "lever_mm", "rod_mm",
                    "guide_mm", "pressure_angle_max_deg", "variant"):
            expected = analyzed[key]
            got = rows[key].values[k]
            assert got == expected if expected is None or isinstance(expected, str) \
                else got == pytest.approx(expected, rel=1e-12), key
        for key in ("v_work_max_m_s", "v_work_mean_m_s", "v_return_max_m_s", "a_max_m_s2"):
            assert rows[key].values[k] == pytest.approx(speed[key], rel=1e-12), key
        if masses is None:
            assert rows["max_torque_N_m"].values[k] is None
            assert result.crank_torque_N_m[k] is None
            continue
        run = shaper("dynamics", "--design", path, "--rpm", 55, "--json")
        assert run.returncode == 0, run.stderr
        dyn = json.loads(run.stdout)["speeds"][0]
        for key in ("mean_torque_N_m", "max_torque_N_m", "flywheel_inertia_kg_m2"):
            assert rows[key].values[k] == pytest.approx(dyn[key], rel=1e-12), key


def test_curves_equal_shaper_curves(result, tmp_path):
    for k, (label, spec, masses) in enumerate(DESIGNS):
        path = tmp_path / f"{k}.json"
        save_design(path, spec, [40.0], 1.0)
        run = shaper("curves", "--design", path, "--rpm", 55, "--step", 2, "--csv", "-")
        table = np.genfromtxt(io.StringIO(run.stdout), delimiter=",", names=True)
        np.testing.assert_allclose(result.crank_deg, table["crank_deg"])
        np.testing.assert_allclose(result.ram_x_mm[k], table["ram_x_mm"], rtol=1e-9, atol=1e-9)
        np.testing.assert_allclose(result.ram_v_m_s[k], table["ram_v_m_s"], rtol=1e-9, atol=1e-12)
        np.testing.assert_allclose(result.ram_a_m_s2[k], table["ram_a_m_s2"], rtol=1e-9, atol=1e-9)


def test_torque_mean_is_cut_work_over_two_pi(result):
    """Hand check: over a cycle the inertia and gravity work cancel; only the cut remains."""
    for k, (_, spec, masses) in enumerate(DESIGNS):
        torque = result.crank_torque_N_m[k]
        if torque is None:
            continue
        stroke = spec.design().stroke
        cut_work = masses.cut_force_N * (1 - 2 * masses.idle_fraction) * stroke / 1000.0
        rows = {r.key: r for r in result.rows}
        assert rows["mean_torque_N_m"].values[k] == pytest.approx(cut_work / (2 * np.pi), rel=1e-6)


def test_differences_and_best(result):
    rows = {r.key: r for r in result.rows}
    a = rows["a_max_m_s2"]
    assert a.differences[0] == 0.0
    assert a.differences[1] == pytest.approx(a.values[1] - a.values[0])
    assert a.best == (int(np.argmin(a.values)),)
    assert rows["K"].best == () and rows["K"].better is None
    # only two designs have loads; best J_F is the smaller of those two
    jf = rows["flywheel_inertia_kg_m2"]
    assert jf.values[2] is None and jf.best == (int(np.argmin(jf.values[:2])),)
    # the pressure angle exists for the two rod designs only
    assert rows["pressure_angle_max_deg"].values[0] is None


def test_best_rules():
    assert best_indices([3.0, 1.0, 1.0 + 1e-13], "lower") == (1, 2)
    assert best_indices([3.0, 1.0, 2.0], "higher") == (0,)
    assert best_indices([2.0, 2.0], "lower") == ()            # all equal: nothing to mark
    assert best_indices([None, 2.0], "lower") == ()           # a single value: nothing to compare
    assert best_indices([1.0, 2.0], None) == ()


def test_csv_and_json_exports(result):
    rows = list(csv.reader(io.StringIO(table_csv(result))))
    assert rows[0] == ["figure", "unit", "better", "block 1.4", "rod 1.6", "leading",
                       "rod 1.6 - block 1.4", "leading - block 1.4", "best"]
    by_key = {r[0]: r for r in rows[1:]}
    assert float(by_key["rpm"][3]) == 55.0
    a = next(r for r in result.rows if r.key == "a_max_m_s2")
    assert [float(v) for v in by_key["a_max_m_s2"][3:6]] == pytest.approx(list(a.values), rel=1e-9)
    assert by_key["a_max_m_s2"][8] == result.labels[a.best[0]]
    assert by_key["max_torque_N_m"][5] == ""                   # no loads, no value
    doc = comparison_document(result, curves=True)
    json.dumps(doc, allow_nan=False)
    assert doc["designs"] == list(result.labels) and doc["rpm"] == 55.0
    assert len(doc["curves"]["crank_deg"]) == result.crank_deg.size
    curves = list(csv.reader(io.StringIO(curves_csv(result))))
    assert len(curves) == 1 + 3 * result.crank_deg.size
    assert curves[1][0] == "block 1.4" and curves[-1][5] == ""


def test_bad_requests():
    with pytest.raises(DesignError):
        compare([Candidate("a", Spec())], 40.0)
    with pytest.raises(DesignError):
        compare([Candidate(str(i), Spec()) for i in range(7)], 40.0)
    with pytest.raises(DesignError):
        compare([Candidate("a", Spec()), Candidate("a", Spec())], 40.0)
    with pytest.raises(DesignError) as err:
        compare([Candidate("a", Spec()), Candidate("b", Spec())], -5.0)
    assert err.value.parameter == "rpm"
