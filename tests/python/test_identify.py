"""Recording, simulate, fit, fit_family, diagnose against the CLI (issue 30).

A recording is simulated from the bundled bypass-cylinder rig (its README example's signals),
then fitted. Reference: the CLI of the same build; both run the same library functions on the
same data, so results must be equal to the last digit (no tolerance).
"""

import json
import os
import warnings

import numpy as np
import pytest

import rheomag
from conftest import SOURCE, cli_json, run_cli, without_timing

RIG = os.path.join(SOURCE, "cases", "rigs", "bypass_cylinder.toml")
SIGNALS = ["displacement=sine:amplitude=0.025,frequency=0.75", "current=steps:levels=0/0.5/1,period=2"]


@pytest.fixture(scope="module")
def recording(tmp_path_factory):
    """A recording written by the CLI's simulate (6 s at 200 Hz)."""
    path = str(tmp_path_factory.mktemp("rec") / "rig.csv")
    args = ["simulate", RIG, "--duration", "6", "--rate", "200", "--out", path]
    for s in SIGNALS:
        args += ["--signal", s]
    code, _, err = run_cli(*args)
    assert code == 0, err
    return path


def test_simulate_equals_cli(recording, tmp_path):
    rec = rheomag.simulate(RIG, signals=SIGNALS, duration=6, rate=200, out=str(tmp_path / "py.csv"))
    cli = rheomag.Recording.load(recording)
    assert rec.output == cli.output and rec.drive == cli.drive
    # The CLI's copy went through the CSV text: equal to the digits the CSV writes.
    py_written = rheomag.Recording.load(str(tmp_path / "py.csv"))
    for name, values in cli.columns.items():
        assert np.array_equal(py_written.columns[name], values), name
    assert np.array_equal(py_written.t, cli.t)
    assert len(rec.t) == 1200


def test_recording_columns_are_numpy(recording):
    rec = rheomag.Recording.load(recording)
    assert isinstance(rec.t, np.ndarray) and rec.t.shape == (1200,)
    assert set(rec.drive) <= set(rec.columns) and rec.output in rec.columns
    assert all(v.shape == rec.t.shape for v in rec.columns.values())


def test_black_box_fit_equals_cli(recording):
    py = rheomag.fit(recording, "arx:2,2,1", train="0:800", validate="800:1200")
    cli = cli_json("fit", recording, "--model", "arx:2,2,1", "--train", "0:800", "--validate",
                   "800:1200")
    assert without_timing(py) == without_timing(cli)


def test_grey_box_fit_equals_cli(recording):
    events = []
    py = rheomag.fit(recording, "bingham", progress=events.append)
    cli = cli_json("fit", recording, "--model", "bingham", "--quiet")
    assert without_timing(py) == without_timing(cli)


@pytest.fixture(scope="module")
def two_currents(tmp_path_factory):
    """Two recordings of the rig at 0 A and 1 A (4 s at 200 Hz), written by the CLI."""
    folder = tmp_path_factory.mktemp("family")
    paths = []
    for current in (0, 1):
        path = str(folder / f"i{current}.csv")
        code, _, err = run_cli("simulate", RIG, "--signal", SIGNALS[0], "--signal",
                               f"current=constant:value={current}", "--duration", "4",
                               "--rate", "200", "--out", path)
        assert code == 0, err
        paths.append(path)
    return paths


def test_fit_family_equals_cli(two_currents):
    py = rheomag.fit_family(two_currents, "bingham")
    cli = cli_json("fit-family", *two_currents, "--model", "bingham", "--quiet")
    assert without_timing(py) == without_timing(cli)


def test_fit_family_hold_equals_cli(two_currents):
    # Held at twice the value the free fit finds (inside the parameter's bounds).
    width = 2 * rheomag.fit_family(two_currents, "bingham")["params"]["transition"]
    py = rheomag.fit_family(two_currents, "bingham", hold={"transition": width})
    cli = cli_json("fit-family", *two_currents, "--model", "bingham", "--hold",
                   f"transition={width!r}", "--quiet")
    assert without_timing(py) == without_timing(cli)
    assert py["params"]["transition"] == width


def test_diagnose_equals_cli(two_currents):
    events = []
    py = rheomag.diagnose(two_currents[1], progress=events.append)
    cli = cli_json("diagnose", two_currents[1], "--quiet")
    assert without_timing(py) == without_timing(cli)
    assert events  # each stage is reported


def test_diagnose_against_a_reference_equals_cli(two_currents, tmp_path):
    # The 1 A recording against a Bingham model of both, with the 0 A recording as the reference
    # (`--reference`): the same comparison from both, each linear effect's change today minus
    # the reference's size.
    model = tmp_path / "both.json"
    model.write_text(json.dumps(cli_json("fit-family", *two_currents, "--model", "bingham",
                                         "--quiet")))
    py = rheomag.diagnose(two_currents[1], baseline=str(model), reference=two_currents[0])
    cli = cli_json("diagnose", two_currents[1], "--baseline", str(model), "--reference",
                   two_currents[0], "--quiet")
    assert without_timing(py) == without_timing(cli)
    ref = py["reference"]
    assert ref["recording"] == two_currents[0]
    for e in ref["changes"]:
        assert e["change"] == e["today"] - e["reference"]


def test_simulate_beyond_the_fitted_drive_warns_as_the_cli_notes(two_currents, tmp_path):
    # A model fitted at 0 A only, run on the 1 A recording: its field lies beyond the fitted
    # drive. Python warns (UserWarning) with the text of the CLI's stderr note; within the drive
    # (the 0 A recording itself) neither says anything.
    model = tmp_path / "at0.json"
    model.write_text(json.dumps(cli_json("fit", two_currents[0], "--model", "bingham", "--quiet")))
    code, _, err = run_cli("simulate", str(model), "--input", two_currents[1], "--out",
                           str(tmp_path / "cli.csv"))
    assert code == 0, err
    notes = [line for line in err.splitlines() if line.startswith("note: ")]
    assert len(notes) == 1 and "field: current up to 1 A, above the trained 0 A" in notes[0]
    with pytest.warns(UserWarning) as caught:
        rheomag.simulate(str(model), input=two_currents[1])
    assert [str(w.message) for w in caught] == [notes[0][len("note: "):]]
    code, _, err = run_cli("simulate", str(model), "--input", two_currents[0], "--out",
                           str(tmp_path / "same.csv"))
    assert code == 0 and "note: " not in err
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        rheomag.simulate(str(model), input=two_currents[0])


def test_fit_input_error_has_the_cli_message(recording):
    code, _, err = run_cli("fit", recording, "--model", "no-such-model")
    assert code == 2
    with pytest.raises(ValueError) as e:
        rheomag.fit(recording, "no-such-model")
    assert err == "rheomag: error: " + str(e.value) + "\n"


UTFSM = os.path.join(SOURCE, "..", "shared", "data", "utfsm", "25mm0x5Hz0A.csv")


@pytest.mark.skipif(not os.path.exists(UTFSM), reason="shared data absent")
def test_keep_inertance_equals_cli():
    # A slow real sine: by default the damper's inertance is held at 0 (it removes under 10 % of
    # the residual energy); keep_inertance fits it, as --keep-inertance does.
    held = rheomag.fit(UTFSM, "damper")
    assert held["inertance_check"]["held"]
    kept = rheomag.fit(UTFSM, "damper", keep_inertance=True)
    cli = cli_json("fit", UTFSM, "--model", "damper", "--keep-inertance", "--quiet")
    assert without_timing(kept) == without_timing(cli)
    assert "inertance_check" not in kept
    assert kept["params"]["inertance"] > 0.0
