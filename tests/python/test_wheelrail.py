"""A wheel/rail (module 1) file from Python: patches as dicts with their fields."""

import json
import shutil
import subprocess

import numpy as np
import pytest

import rollcontact as rc
from conftest import EXAMPLES


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
