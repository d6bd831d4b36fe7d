"""The Results pane's flywheel rows with the other rotating parts (Loads › Rotating parts),
as `shaper dynamics` prints them (its own row function, ``speed_rows``): the flywheel needed
J_F − J_c, then J_F − J_c − J_e (net). The pane had one row, "J_F less mechanism's own",
whose number subtracted J_c too: 1831 kg·m² beside J_F 1838 and J_e 0.93 at 40 r/min, with
J_c = 5.5 kg·m² (0.02 kg·m² at 15 times the crank speed, 1 kg·m² at the crank's)."""
from __future__ import annotations

import pytest

from core.cli.cmd_dynamics import speed_rows
from shaperapp.results.panel import MetricsPanel

CLI_LABELS = {"flywheel J_F": "Flywheel J_F on crank shaft, kg·m²",
              "flywheel needed J_F − J_c": "Flywheel needed J_F − J_c, kg·m²",
              "flywheel J_F − J_c − J_e (net)": "J_F − J_c − J_e (net), kg·m²",
              "flywheel J_F − J_e (net)": "J_F less mechanism's own, kg·m²"}


def flywheel_rows(panel: MetricsPanel) -> dict[str, list[str]]:
    table = panel.tables()[3]
    panel.table_text(0, 0, forces=True)          # fills the forces table (it waits to be seen)
    return {table.verticalHeaderItem(r).text().replace("\n", " "): [table.text(r, c) for c in range(table.columnCount())]
            for r in range(table.rowCount())}


@pytest.mark.parametrize("rotors, needed", [(((0.02, 15.0), (1.0, 1.0)), ["1832", "811.3"]),
                                            ((), None), (((500.0, 2.0),), ["none needed (J_c ≥ J_F)"] * 2)])
def test_the_flywheel_rows_are_shaper_dynamics_rows(qtbot, rotors, needed):
    from shaperapp.design.model import DesignModel
    model = DesignModel()               # the default design at 40 and 60 r/min, the default loads
    panel = MetricsPanel(model)
    qtbot.addWidget(panel)
    panel.show()
    model.set_masses(rotors=rotors)
    summary = model.dynamics_summary
    shown = flywheel_rows(panel)
    j_c = summary.rotor_inertia_kg_m2 if rotors else None
    for column, speed in enumerate(summary.speeds):
        for label, text in speed_rows(speed, j_c):
            if label in CLI_LABELS and not text.startswith("none needed"):
                assert shown[CLI_LABELS[label]][column] == text.removesuffix(" kg·m²"), label
    if needed is None:
        assert "Flywheel needed J_F − J_c, kg·m²" not in shown
    else:
        assert shown["Flywheel needed J_F − J_c, kg·m²"] == needed
        assert "J_F less mechanism's own, kg·m²" not in shown
