"""Solving from Python: the same numbers as the CLI, arrays with the grid's shape, units and
coordinates, results that own no copies."""

import json
import subprocess

import numpy as np
import pytest

import rollcontact as rc
from conftest import EXAMPLES, REPO_EXAMPLES


def test_creep_curve_from_python_equals_the_cli(cli, tmp_path):
    # A longitudinal creep curve (steady rolling, Hertzian circle) swept from Python, and the
    # same cases as a TOML file run by the CLI: the same problems through the same solver.
    base = rc.hertz_case(fn_N=10000.0, semi_axes_mm=(3.0, 3.0), elements=(25, 25))
    creepages = [0.0, 2e-4, 5e-4, 1e-3, 2e-3, 4e-3]
    curve = rc.sweep(base, "tangential.creepage_x", creepages)
    cases = [rc.set_value(base, "tangential.creepage_x", c) for c in creepages]
    (tmp_path / "curve.toml").write_text(rc.to_toml(cases))
    subprocess.run([cli, "run", "-q", str(tmp_path / "curve.toml")], check=True)
    totals = [c["totals"] for c in json.loads((tmp_path / "curve.json").read_text())["cases"]]
    assert len(totals) == len(curve)
    for ours, theirs in zip(curve, totals):
        assert ours["converged"]
        assert ours["fx"] == pytest.approx(theirs["fx"], rel=1e-12, abs=1e-9)
        assert ours["fn"] == pytest.approx(theirs["fn"], rel=1e-12)
    # The physics of the curve: zero force at zero creepage, rising towards mu*FN (saturation).
    fx = np.array([r["fx"] for r in curve]) / -3000.0  # FX/(mu FN), force on body 1
    assert abs(fx[0]) < 1e-6
    assert np.all(np.diff(fx) > 0) and 0.95 < fx[-1] <= 1.0 + 1e-9


def test_arrays_have_the_grid_shape_units_and_coordinates():
    r = rc.solve(rc.hertz_case(fn_N=5000.0, semi_axes_mm=(4.0, 2.5), elements=(30, 20),
                               creepage_x=5e-4))
    g = r["grid"]
    assert (g["mx"], g["my"]) == (30, 20)
    for name in ("pn", "px", "py", "sx", "sy", "ux", "uy", "un", "h", "state"):
        assert r[name].shape == (20, 30), name
    # Element centres [mm], spaced dx, dy, over the symmetric potential contact.
    assert np.allclose(np.diff(g["x"]), g["dx"]) and np.allclose(np.diff(g["y"]), g["dy"])
    assert g["x"][0] == pytest.approx(-g["x"][-1]) and g["y"][0] == pytest.approx(-g["y"][-1])
    # Pressures [N/mm2] integrate to FN [N]; tractions to FX; the pressure peaks at the centre.
    area = g["dx"] * g["dy"]
    assert r["pn"].sum() * area == pytest.approx(r["fn"], rel=1e-9)
    assert r["px"].sum() * area == pytest.approx(r["fx"], rel=1e-9, abs=1e-9)
    iy, ix = np.unravel_index(np.argmax(r["pn"]), r["pn"].shape)
    assert abs(g["x"][ix]) <= g["dx"] and abs(g["y"][iy]) <= g["dy"]
    # Element division agrees with the pressure; no copies of the solution's fields.
    assert np.array_equal(r["state"] > 0, r["pn"] > 0)
    assert not r["pn"].flags["OWNDATA"]


def test_inp_files_run_from_python_like_the_cli(cli, tmp_path):
    inp = REPO_EXAMPLES / "steady_rolling.inp"
    cases = rc.run(inp, tmp_path / "py")
    subprocess.run([cli, "run", "-q", "-o", str(tmp_path / "cli"), str(inp)], check=True)
    ref = json.loads((tmp_path / "cli" / "steady_rolling.json").read_text())["cases"]
    assert [c["fx"] for c in cases] == [c["totals"]["fx"] for c in ref]
    assert (tmp_path / "py" / "steady_rolling.out").exists()


def test_bad_input_raises_with_file_and_line(tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text("version = 1\n[[case]]\n[case.normal]\nforce_N = -5.0\n")
    with pytest.raises(ValueError, match="bad.toml"):
        rc.run(bad, tmp_path)


def test_fields_of_the_extended_physics(tmp_path):
    """Temperatures (H >= 1) and the local friction coefficient (falling friction) come back
    as fields next to the tractions, with CONTACT's maximum temperature."""
    if not (EXAMPLES / "ertz_temperature.inp").exists():
        pytest.skip("CONTACT's examples not found")
    examples = EXAMPLES
    heat = rc.run(str(examples / "ertz_temperature.inp"), output_dir=str(tmp_path))
    c1 = heat[0]
    assert c1["temp1"].shape == c1["pn"].shape
    assert abs(c1["max_temp1"] - 166.8) < 0.1  # CONTACT's MAX(T1,T2) of case 1
    assert np.nanmax(c1["temp1"]) >= c1["max_temp1"] - 1e-9
    veldep = rc.run(str(examples / "veldep_fric.inp"), output_dir=str(tmp_path))
    mu = veldep[0]["mu"]
    assert mu.shape == veldep[0]["pn"].shape
    inside = veldep[0]["pn"] > 0
    assert np.all(mu[inside] <= 0.30 + 1e-12) and np.all(mu[inside] >= 0.18 - 1e-12)
    assert "temp1" not in veldep[0]
