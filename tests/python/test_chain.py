"""Case.valve / damper / brake / thermal / transient against the CLI's --json (issue 30).

Reference: the CLI of the same build on the same case; both build their dict with the same
library function, so the numbers must be equal to the last digit (no tolerance). Wall-clock keys
are left out.
"""

import os

import pytest

import rheomag
from conftest import SOURCE, VALVE, cli_json, run_cli, without_timing

DAMPER = os.path.join(SOURCE, "cases", "damper_piston.toml")
BRAKE = os.path.join(SOURCE, "cases", "brake_drum.toml")


def test_valve_equals_cli(valve_case):
    py = valve_case.valve(currents=[0.5, 1.0], flows=[1e-6, 2e-6])
    cli = cli_json("valve", VALVE, "--current", "0.5,1", "--flow", "1e-6,2e-6")
    assert without_timing(py) == without_timing(cli)


def test_damper_equals_cli():
    py = rheomag.Case.load(DAMPER).damper(currents=[1.0], velocities=[0.05, 0.1])
    cli = cli_json("damper", DAMPER, "--current", "1", "--velocity", "0.05,0.1")
    assert without_timing(py) == without_timing(cli)


def test_brake_equals_cli():
    py = rheomag.Case.load(BRAKE).brake(currents=[1.0], speeds=[10.0])
    cli = cli_json("brake", BRAKE, "--current", "1", "--speed", "10")
    assert without_timing(py) == without_timing(cli)


def test_thermal_equals_cli(valve_case):
    py = valve_case.thermal(current=0.8, flow=1e-6, duty=0.5)
    cli = cli_json("thermal", VALVE, "--current", "0.8", "--flow", "1e-6", "--duty", "0.5")
    assert without_timing(py) == without_timing(cli)
    assert abs(py["balance_error"]) < 1e-8


def test_transient_equals_cli_and_reports_progress(valve_case):
    events = []
    py = valve_case.transient(current=1.0, duration=0.02, steps=4, progress=events.append)
    cli = cli_json("transient", VALVE, "--current", "1", "--duration", "0.02", "--steps", "4",
                   "--quiet")
    assert without_timing(py) == without_timing(cli)
    assert len(events) >= 4  # one per accepted step
    assert all({"stage", "done", "total", "elapsed", "detail"} <= set(e) for e in events)


def test_transient_non_convergence_is_convergence_error(valve_case):
    args = ["--current", "1", "--duration", "0.02", "--steps", "2", "--newton-iterations", "1"]
    code, _, err = run_cli("transient", VALVE, *args, "--quiet")
    assert code == 3, err
    with pytest.raises(rheomag.ConvergenceError) as e:
        valve_case.transient(current=1.0, duration=0.02, steps=2, newton_iterations=1)
    assert err == "rheomag: solver did not converge: " + str(e.value) + "\n"


def refused_alike(cli_args, call):
    """The CLI exits 2 and `call()` raises ValueError, with the same message."""
    code, _, err = run_cli("transient", VALVE, *cli_args)
    assert code == 2
    with pytest.raises(ValueError) as e:
        call()
    assert err == "rheomag: error: " + str(e.value) + "\n"


def test_transient_input_error_has_the_cli_message(valve_case):
    refused_alike(["--duration", "0.02"], lambda: valve_case.transient(duration=0.02))


def test_quasi_static_transient_equals_cli(valve_case):
    """The reduction (no time stepping, no duration) gives the CLI's document to the last digit."""
    py = valve_case.transient(voltage=4.8, quasi_static=True)
    cli = cli_json("transient", VALVE, "--voltage", "4.8", "--quasi-static")
    assert py["model"] == "quasi_static"
    assert without_timing(py) == without_timing(cli)
    coarse = valve_case.transient(voltage=4.8, quasi_static=True, table_points=4)
    cli = cli_json("transient", VALVE, "--voltage", "4.8", "--quasi-static", "--table-points", "4")
    assert without_timing(coarse) == without_timing(cli)


def test_transient_without_duration_or_with_few_table_points_is_refused(valve_case):
    refused_alike(["--current", "1"], lambda: valve_case.transient(current=1.0))
    with pytest.raises(ValueError, match="--table-points"):
        valve_case.transient(current=1.0, quasi_static=True, table_points=3)
    refused_alike(["--current", "1", "--from", "1", "--quasi-static"],
                  lambda: valve_case.transient(current=1.0, from_current=1.0, quasi_static=True))
