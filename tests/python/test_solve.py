"""Case.load / with_ / solve against `rheomag solve --json` (issue 30).

Reference: the CLI of the same build on the same case. Both call the same library function
(results_json), so every number must be the same double: equality, no tolerance (a difference
in the last printed digit fails).
"""

import math
import os
import threading
import warnings

import numpy as np
import pytest

import rheomag
from conftest import SOURCE, VALVE, cli_error, cli_json, run_cli, without_timing


def test_solve_equals_cli(valve_case):
    py = valve_case.solve().json()
    cli = cli_json("solve", VALVE)
    assert without_timing(py) == without_timing(cli)
    assert py["version"] == cli["version"]


def test_solve_at_a_current_equals_cli(valve_case):
    py = valve_case.solve(current=0.5).json()
    cli = cli_json("solve", VALVE, "--current", "0.5")
    assert without_timing(py) == without_timing(cli)


def test_solution_properties_are_the_json_numbers(valve_case):
    s = valve_case.solve()
    j = s.json()
    assert s.flux_linkage == j["flux_linkage"]
    assert s.inductance == j["inductance"]
    assert s.energy == j["energy"]
    assert [g.B_avg for g in s.gaps] == [g["B_avg"] for g in j["gaps"]]
    assert [g.name for g in s.gaps] == [g["name"] for g in j["gaps"]]


def test_gap_flux_density_vocabulary(valve_case):
    """The names of docs/quantities.md: B_max_midline is the mid-line peak (the fixed B_max),
    B_max_area the corner peak (B_area_max), and the corner peak is the larger."""
    s = valve_case.solve()
    for g, j in zip(s.gaps, s.json()["gaps"]):
        assert g.B_max_midline == j["B_max_midline"] == j["B_max"]
        assert g.B_max_area == j["B_max_area"] == j["B_area_max"]
        assert g.B_avg <= g.B_max_area and g.B_max_midline <= g.B_max_area


def test_gap_profiles(valve_case):
    s = valve_case.solve()
    for g in s.gaps:
        assert isinstance(g.B, np.ndarray) and g.B.shape == g.s.shape == g.B_n.shape
        assert g.B.shape[0] > 100
        assert np.all(np.diff(g.s) > 0)
        # The mid-line's mean |B| from the profile against the solver's own mid-line statistic
        # (same line, same sample count; the two end points may fall in the neighbouring steel
        # here, 2 of 201 samples): within 2 %.
        stats = g.stats["midline"]["B"]["average"]
        assert abs(np.mean(g.B) - stats) <= 0.02 * stats
        assert np.all(np.abs(g.B_n) <= g.B + 1e-12)


def test_mesh_arrays(valve_case):
    s = valve_case.solve()
    m = s.mesh
    j = s.json()
    assert m.nodes.shape == (j["nodes"], 2)
    assert m.triangles.shape == (j["elements"], 6)  # the case's order 2
    assert m.triangles.min() == 0 and m.triangles.max() < m.nodes.shape[0]
    assert m.B.shape == (j["elements"], 2)
    # |B| per element is the norm of the element's (B_r, B_z) (to rounding: 1e-12 relative).
    assert np.allclose(np.hypot(m.B[:, 0], m.B[:, 1]), m.B_abs, rtol=1e-12, atol=0)
    assert len(m.region) == j["elements"]
    assert max(m.region) < len(m.region_names)


def test_with_edits_are_the_key_api_in_si(valve_case):
    wider = valve_case.with_({"geometry.gap_width": 1.2e-3, "geometry.turns": 400})
    assert wider["geometry.gap_width"] == pytest.approx(1.2e-3, rel=1e-15)
    assert wider["geometry.turns"] == 400
    assert valve_case["geometry.gap_width"] == pytest.approx(1.0e-3, rel=1e-15)  # unchanged
    # A wider gap and fewer turns: less flux through the gap (a broken edit leaves it equal).
    assert wider.solve().gaps[0].B_avg < valve_case.solve().gaps[0].B_avg


def test_unknown_key_is_a_value_error_with_a_suggestion(valve_case):
    with pytest.raises(ValueError, match="gap_width"):
        valve_case.with_({"geometry.gap_widht": 1e-3})


def test_input_error_has_the_cli_message(tmp_path):
    missing = str(tmp_path / "missing.toml")
    with pytest.raises(ValueError) as e:
        rheomag.Case.load(missing)
    assert str(e.value) == cli_error("solve", missing)
    bad = tmp_path / "bad.toml"
    bad.write_text('[case]\nname = "x"\nunits = "furlong"\n')
    with pytest.raises(ValueError) as e:
        rheomag.Case.load(str(bad))
    assert str(e.value) == cli_error("solve", str(bad))


def test_a_femm_table_smoothed_as_femm_does_warns_as_the_cli_does(tmp_path):
    # pot_core.fem with two H values of its iron table swapped: FEMM smooths the table, and so
    # does the reader; Python gets the CLI's stderr warning as a UserWarning.
    text = open(os.path.join(SOURCE, "tests", "data", "pot_core.fem"), newline="").read()
    text = text.replace("1.51721\t1587.7793", "1.51721\tSWAP").replace(
        "1.54452\t1998.8957", "1.54452\t1587.7793").replace("1.51721\tSWAP", "1.51721\t1998.8957")
    model = tmp_path / "swapped.fem"
    model.write_text(text, newline="")
    with pytest.warns(UserWarning) as caught:
        rheomag.Case.load(str(model))
    messages = [str(w.message) for w in caught]
    assert len(messages) == 1 and "smoothed as FEMM does" in messages[0], messages
    with warnings.catch_warnings():  # a warning filtered as an error raises it
        warnings.simplefilter("error")
        with pytest.raises(UserWarning):
            rheomag.Case.load(str(model))
    code, _, err = run_cli("mesh", str(model))
    assert code == 0, err
    assert "rheomag: warning: " + messages[0][len("rheomag: "):] in err


def test_two_threads_equal_sequential(valve_case):
    currents = [0.4, 1.0]
    sequential = [without_timing(valve_case.solve(current=i).json()) for i in currents]
    parallel = [None, None]

    def solve(k):
        parallel[k] = without_timing(valve_case.solve(current=currents[k]).json())

    threads = [threading.Thread(target=solve, args=(k,)) for k in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert parallel == sequential
    assert sequential[0] != sequential[1]


def test_version():
    code, out, _ = run_cli("--version")
    assert code == 0
    assert rheomag.__version__.split("+")[0] in out
    assert rheomag.__version__.split("+")[1] in out


def test_current_must_be_finite(valve_case):
    with pytest.raises(ValueError, match="finite"):
        valve_case.solve(current=math.nan)
