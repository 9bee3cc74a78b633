"""Case.solve_3d against `rheomag solve --3d --json` and against the 2D solve.

References:
- the CLI of the same build on the same case: both build the dict with the same library function
  (results_json_3d), so every number must be the same double (TetGen and CHOLMOD are
  deterministic on one thread);
- the 2D axisymmetric solve of the same case, itself checked against xfemm
  (docs/validation.md): the bundled valve's 3D wedge matches it within 1 % in each gap's B_avg
  and in the flux linkage (docs/magnetostatics3d.md; measured +0.35 % and -0.49 %).
"""

import os

import pytest

import rheomag
from conftest import VALVE, cli_json, without_timing


@pytest.fixture(scope="module")
def solved_3d(tmp_path_factory):
    """The reference valve solved in 3D (its default TetGen wedge), with the .vtu written and
    the progress events kept."""
    vtk = str(tmp_path_factory.mktemp("solve3d") / "valve3d.vtu")
    events = []
    document = rheomag.Case.load(VALVE).solve_3d(vtk=vtk, progress=events.append)
    return document, vtk, events


def test_solve_3d_equals_cli(solved_3d):
    py, vtk, _ = solved_3d
    cli = cli_json("solve", VALVE, "--3d")
    assert py["vtk"] == vtk
    py = {k: v for k, v in py.items() if k != "vtk"}
    assert without_timing(py) == without_timing(cli)
    assert py["dimension"] == cli["dimension"]


def test_solve_3d_agrees_with_the_2d_solve(solved_3d, valve_case):
    py, _, _ = solved_3d
    two_d = valve_case.solve()
    assert len(py["gaps"]) == len(two_d.gaps)
    for gap_3d, gap_2d in zip(py["gaps"], two_d.gaps):
        assert gap_3d["B_avg"] == pytest.approx(gap_2d.B_avg, rel=0.01)
    assert py["flux_linkage"] == pytest.approx(two_d.flux_linkage, rel=0.01)


def test_solve_3d_writes_the_vtu_and_reports_progress(solved_3d):
    _, vtk, events = solved_3d
    with open(vtk, "rb") as f:
        head = f.read(200)
    assert b"<VTKFile" in head
    assert os.path.getsize(vtk) > 100_000  # a wedge of about 1e5 tetrahedra with its fields
    stages = {e["stage"] for e in events}
    assert {"mesh", "solve"} <= stages


@pytest.mark.parametrize(
    "kwargs, names",
    [
        ({"mesher": "hexahedra"}, "mesher"),
        ({"linear_solver": "lu"}, "linear_solver"),
        ({"current": float("nan")}, "current"),
        ({"max_memory": "lots"}, "max_memory"),
    ],
)
def test_solve_3d_bad_input_is_a_value_error_naming_the_argument(valve_case, kwargs, names):
    with pytest.raises(ValueError, match=names):
        valve_case.solve_3d(**kwargs)
