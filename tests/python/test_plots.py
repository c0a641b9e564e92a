"""Plots: each kind writes a non-empty PNG, and what is drawn is the solution's data."""

import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import numpy as np  # noqa: E402
import pytest  # noqa: E402

import rollcontact as rc  # noqa: E402
from conftest import REPO_EXAMPLES  # noqa: E402


@pytest.fixture(scope="module")
def result():
    return rc.solve(rc.hertz_case(fn_N=10000.0, semi_axes_mm=(3.0, 3.0), elements=(31, 31),
                                  creepage_x=1e-3))


@pytest.mark.parametrize("what", ["pressure", "traction", "slip"])
def test_fields_write_png_and_plot_the_solution(result, what, tmp_path):
    ax = rc.plot.field(result, what)
    path = tmp_path / f"{what}.png"
    ax.figure.savefig(path, dpi=80)
    assert path.stat().st_size > 5000
    drawn = np.asarray(ax.collections[0].get_array()).reshape(result["pn"].shape)
    expected = {"pressure": result["pn"],
                "traction": np.hypot(result["px"], result["py"]),
                "slip": np.hypot(result["sx"], result["sy"])}[what]
    assert np.array_equal(drawn, expected)
    assert "[mm]" in ax.get_xlabel() and "[mm]" in ax.get_ylabel()
    # The colour bar is labelled with the quantity and its unit.
    assert "[" in ax.figure.axes[-1].get_ylabel()


def test_creep_curve_plots_the_sweep(tmp_path):
    base = rc.hertz_case(fn_N=10000.0, semi_axes_mm=(3.0, 3.0), elements=(21, 21))
    sweep = rc.sweep(base, "tangential.creepage_x", [0.0, 5e-4, 1e-3, 3e-3])
    ax = rc.plot.creep_curve(sweep)
    xy = ax.lines[0].get_xydata()
    assert np.allclose(xy[:, 0], [r["creep_x"] for r in sweep])
    assert np.allclose(xy[:, 1], [r["fx"] / r["fn"] for r in sweep])
    ax.figure.savefig(tmp_path / "curve.png", dpi=80)
    assert (tmp_path / "curve.png").stat().st_size > 5000


def test_profiles_and_traction_profile_draw(tmp_path, result):
    y = np.linspace(-30, 30, 61)
    ax = rc.plot.profiles((y, y**2 / 600.0), (y, -(y**2) / 1000.0 - 0.5), [(0.0, 0.0)])
    assert len(ax.lines) == 3
    ax = rc.plot.traction_profile(result, mu=0.3)
    iy = np.unravel_index(np.argmax(result["pn"]), result["pn"].shape)[0]
    assert np.array_equal(ax.lines[0].get_ydata(), result["px"][iy])


def test_module_command_line(tmp_path):
    inp = REPO_EXAMPLES / "steady_rolling.inp"
    run = subprocess.run([sys.executable, "-m", "rollcontact", "run", str(inp), "-o",
                          str(tmp_path)], capture_output=True, text=True, check=True)
    assert "case 1: FN 10000" in run.stdout
    png = tmp_path / "p.png"
    subprocess.run([sys.executable, "-m", "rollcontact", "plot", str(inp), "--what", "pressure",
                    "-o", str(png)], check=True, capture_output=True)
    assert png.stat().st_size > 5000


def test_cli_plot_command(cli, tmp_path):
    # `rollcontact plot` from the C++ CLI, on the .json a run wrote (its input is solved again).
    inp = tmp_path / "steady.inp"
    inp.write_text((REPO_EXAMPLES / "steady_rolling.inp").read_text())
    subprocess.run([cli, "run", "-q", str(inp)], check=True)
    png = tmp_path / "slip.png"
    subprocess.run([cli, "plot", str(tmp_path / "steady.json"), "--what", "slip", "-o", str(png)],
                   check=True, capture_output=True)
    assert png.stat().st_size > 5000
