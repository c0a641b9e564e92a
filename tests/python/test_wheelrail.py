"""A wheel/rail (module 1) file from Python: patches as dicts with their fields."""

import json
import shutil
import subprocess

import numpy as np
import pytest

import rollcontact as rc
from conftest import EXAMPLES, REPO_EXAMPLES


def test_manchester_benchmark_case_from_python(cli, tmp_path):
    if not (EXAMPLES / "mbench_a22_right.inp").exists():
        pytest.skip("CONTACT examples not found")
    for name in ("MBench_UIC60_v3.prr", "MBench_S1002_v3.prw"):
        shutil.copy(EXAMPLES / name, tmp_path)
    lines = (EXAMPLES / "mbench_a22_right.inp").read_text().splitlines()
    first = "\n".join(lines[:26]) + "\n 0 MODULE\n"  # case 1 only
    (tmp_path / "case1.inp").write_text(first)
    cases = rc.run(tmp_path / "case1.inp", tmp_path / "py")
    subprocess.run([cli, "run", "-q", "-o", str(tmp_path / "cli"), str(tmp_path / "case1.inp")],
                   check=True)
    ref = json.loads((tmp_path / "cli" / "case1.json").read_text())["cases"][0]
    (case,) = cases
    assert case["module"] == 1 and case["solved"]
    assert case["force_tr"] == ref["force_tr"]
    assert case["force_tr"][2] == pytest.approx(10000.0, abs=1.0)
    patch = case["patches"][0]
    assert patch["fn"] == ref["patches"][0]["fn"]
    g = patch["grid"]
    assert patch["pn"].shape == (g["my"], g["mx"])
    assert patch["pn"].sum() * g["dx"] * g["dy"] == pytest.approx(patch["fn"], rel=1e-9)
    assert np.isfinite(patch["contact_angle"])
    # The rigid slip the patch's problem posed: ξ − φ·y and η + φ·x up to the spin's offset.
    x, y = np.meshgrid(g["x"], g["y"])
    assert np.ptp(patch["wx"] + patch["phi"] * y) == pytest.approx(0.0, abs=1e-12)
    assert np.ptp(patch["wy"] - patch["phi"] * x) == pytest.approx(0.0, abs=1e-12)


def test_placed_profiles_touch_at_the_contact(tmp_path):
    if not (EXAMPLES / "mbench_a22_right.inp").exists():
        pytest.skip("CONTACT examples not found")
    for name in ("MBench_UIC60_v3.prr", "MBench_S1002_v3.prw"):
        shutil.copy(EXAMPLES / name, tmp_path)
    lines = (EXAMPLES / "mbench_a22_right.inp").read_text().splitlines()
    for side in (0, 1):
        text = list(lines[:26])
        text[12] = " " + str(side) + text[12][2:]  # the C digit: left (0) or right (1)
        (tmp_path / f"c{side}.inp").write_text("\n".join(text) + "\n 0 MODULE\n")
        (case,) = rc.run(tmp_path / f"c{side}.inp", tmp_path)
        assert case["side"] == ("left" if side == 0 else "right")
        rail, wheel = rc.plot.placed_profiles(case)
        y, z = case["patches"][0]["reference_tr"][1:]
        # The contact reference point lies on both placed surfaces, within the approach of the
        # bodies (pen ~ 0.03 mm) and the profiles' point spacing.
        for surf in (rail, wheel):
            order = np.argsort(surf[0])
            assert abs(np.interp(y, surf[0][order], surf[1][order]) - z) < 0.1
        ax = rc.plot.wheelrail(case)
        ax.figure.savefig(tmp_path / f"wr{side}.png", dpi=80)
        assert (tmp_path / f"wr{side}.png").stat().st_size > 5000


def test_wheelrail_case_from_a_python_dict(cli, tmp_path):
    # The benchmark wheel as a dict (docs/case-files.md), solved from Python, and its TOML text
    # run by the CLI: the same forces; a sweep over the lateral position shifts the contact
    # towards the flange.
    if not (EXAMPLES / "mbench_a22_right.inp").exists():
        pytest.skip("CONTACT examples not found")
    for name in ("MBench_UIC60_v3.prr", "MBench_S1002_v3.prw"):
        shutil.copy(EXAMPLES / name, tmp_path)
    case = {
        "friction": {"law": "coulomb", "static": 0.3, "kinetic": 0.3},
        "material": {"body1": {"poisson": 0.28, "shear_modulus_MPa": 82000.0},
                     "body2": {"poisson": 0.28, "shear_modulus_MPa": 82000.0}},
        "wheel_rail": {
            "side": "right",
            "vertical_force_N": 10000.0,
            "discretisation": {"element_size_mm": [0.5, 0.5]},
            "track": {"gauge_height_mm": 14.0, "gauge_width_mm": 1435.0},
            "rail": {"file": "MBench_UIC60_v3.prr"},
            "wheelset": {"flange_back_distance_mm": 1360.0, "flange_back_position_mm": -70.0,
                         "nominal_radius_mm": 460.0},
            "wheel": {"file": "MBench_S1002_v3.prw"},
            "position": {"y_mm": 0.0},
            "velocity": {"forward_mm_per_s": 2000.0, "pitch_rad_per_s": -2000.0 / 460.0},
        },
    }
    r = rc.solve(case, base_dir=tmp_path)
    assert r["module"] == 1 and r["converged"]
    assert r["force_tr"][2] == pytest.approx(10000.0, abs=1.0)
    (tmp_path / "case.toml").write_text(rc.to_toml([case]))
    subprocess.run([cli, "run", "-q", str(tmp_path / "case.toml")], check=True)
    ref = json.loads((tmp_path / "case.json").read_text())["cases"][0]
    assert r["force_tr"] == ref["force_tr"]
    (t,) = rc.run(tmp_path / "case.toml", tmp_path / "py")  # a TOML file run from Python
    assert t["force_tr"] == ref["force_tr"]
    assert t["side"] == "right" and len(t["rail_profile"]["y"]) > 100
    # The same case in CONTACT's input format, run by the CLI: the same forces.
    (tmp_path / "inp").mkdir()
    rc.write_inp(case, tmp_path / "inp" / "case.inp", base_dir=tmp_path)
    text = (tmp_path / "inp" / "case.inp").read_text()
    assert "'../MBench_UIC60_v3.prr'" in text and "  1  MODULE" in text
    subprocess.run([cli, "run", "-q", str(tmp_path / "inp" / "case.inp")], check=True)
    written = json.loads((tmp_path / "inp" / "case.json").read_text())["cases"][0]
    assert written["force_tr"] == ref["force_tr"]
    ys = [rc.set_value(case, "wheel_rail.position.y_mm", y) for y in (0.0, 2.0, 4.0)]
    solver = rc.Solver()
    lateral = [solver.solve(c, base_dir=tmp_path)["patches"][0]["reference_tr"][1] for c in ys]
    assert lateral[0] > lateral[1] > lateral[2]  # the contact moves towards the flange


def test_conformal_patch_from_python(tmp_path):
    """examples/conformal_flange_root.inp: case 2 (D=4) carries its curved reference, one row per
    grid row, and its track force is the BAR force turned by the contact angle."""
    shutil.copytree(REPO_EXAMPLES / "profiles", tmp_path / "profiles")
    shutil.copy(REPO_EXAMPLES / "conformal_flange_root.inp", tmp_path)
    planar, conformal = rc.run(tmp_path / "conformal_flange_root.inp", tmp_path)
    assert "conformal" not in planar["patches"][0]
    patch = conformal["patches"][0]
    c = patch["conformal"]
    assert len(c["row_alpha"]) == patch["grid"]["my"] == len(c["row_y"])
    fx, fs, fn = c["bar_force"]
    d = patch["contact_angle"]
    assert conformal["force_tr"][1] == pytest.approx(fs * np.cos(d) - fn * np.sin(d), rel=1e-12)
    assert conformal["force_tr"][2] == pytest.approx(fn * np.cos(d) + fs * np.sin(d), rel=1e-12)
    # The tilde normal force is the pressure integrated on the curvilinear grid.
    g = patch["grid"]
    assert patch["pn"].sum() * g["dx"] * g["dy"] == pytest.approx(c["tilde_force"][2], rel=1e-9)
    # The rows turn monotonically with the flange root, through the reference angle.
    assert np.all(np.diff(c["row_alpha"]) > 0)
    assert min(c["row_alpha"]) < d < max(c["row_alpha"])
    ax = rc.plot.wheelrail(conformal)  # the curved reference drawn over the profiles
    ax.figure.savefig(tmp_path / "conformal.png", dpi=80)
    assert (tmp_path / "conformal.png").stat().st_size > 5000


def test_unvalidated_features_on_request(tmp_path):
    """mbench_a22_varfric case 3 (patches the D_TURN rule turned): refused by default, solved
    with a warning with unvalidated=True (`rollcontact run --unvalidated`)."""
    if not (EXAMPLES / "mbench_a22_varfric.inp").exists():
        pytest.skip("CONTACT examples not found")
    for name in ("MBench_UIC60_v3.prr", "MBench_S1002_v3.prw", "mbench_a22_varfric.inp"):
        shutil.copy(EXAMPLES / name, tmp_path)
    plain = rc.run(tmp_path / "mbench_a22_varfric.inp", tmp_path / "plain")
    assert not plain[2]["solved"] and "not supported yet" in plain[2]["error"]
    assert all(c["solved"] for k, c in enumerate(plain) if k != 2)
    solved = rc.run(tmp_path / "mbench_a22_varfric.inp", tmp_path / "all", unvalidated=True)
    case = solved[2]
    assert case["solved"] and len(case["patches"]) == 2
    assert any("not validated against CONTACT" in w for w in case["warnings"])
    assert case["force_tr"][2] == pytest.approx(10000.0, abs=1.0)
