"""rollcontact: rolling and sliding contact between elastic bodies (CONTACT-compatible).

Units throughout: mm, N, N/mm2 (MPa), s, rad.

    import rollcontact as rc
    cases = rc.run("case.inp")                 # like `rollcontact run`, one dict per case
    r = rc.solve(rc.hertz_case(fn_N=1e4, semi_axes_mm=(3.0, 3.0), creepage_x=1e-3))
    r["fx"], r["pn"].shape, r["grid"]["x"]     # totals [N], fields (my, mx), centres [mm]
    curve = rc.sweep(case, "tangential.creepage_x", [0, 1e-4, 2e-4])
    rc.write_inp([case], "case.inp")           # the same cases in CONTACT's input format
    rc.plot.field(r, "pressure").figure.savefig("p.png")

A case is a dict with the tables of a TOML case file (docs/case-files.md: normal, tangential,
friction, material, grid, geometry, solver ...). Results are dicts: totals (fn, fx, fy, mz [N,
N mm], pen [mm], pmax [N/mm2], creep_x, creep_y, spin, ...), statistics, converged, message,
grid (mx, my, dx, dy and the element centres x, y [mm]) and the fields pn, px, py [N/mm2],
ux, uy, un [mm], sx, sy (relative slip [-]), h [mm] and state (0 exterior, 1 adhesion, 2 slip,
3 plastic) as NumPy arrays of shape (my, mx): row iy, column ix.
"""

from ._rollcontact import CreepLookupTable, Error, InputError, __version__
from ._rollcontact import Solver as _CoreSolver
from ._rollcontact import run_file as _run_file
from ._rollcontact import write_inp_from_toml as _write_inp_from_toml
from .cases import hertz_case, set_value, to_toml

__all__ = ["run", "solve", "sweep", "write_inp", "Solver", "hertz_case", "to_toml", "set_value",
           "CreepLookupTable", "Error", "InputError", "__version__"]


def run(path, output_dir=None, unvalidated=False):
    """Solve every case of a CONTACT .inp or a TOML case file as `rollcontact run` does.

    Writes <name>.out and <name>.json next to the input (or into output_dir) and returns one
    dict per case: module-3 cases with their totals and fields, wheel/rail cases (module 1) with
    force_tr, force_ws [N], z_ws [mm] and a list of patches, each a module-3-like dict plus its
    reference point, contact angle and creepages. Cases that could not be solved have
    solved = False and the reason in error. unvalidated=True also solves the wheel/rail
    features not yet validated against CONTACT (wheel slices, ...), each with a warning, as
    `rollcontact run --unvalidated` does.
    """
    return _run_file(str(path), "" if output_dir is None else str(output_dir), bool(unvalidated))


class Solver:
    """Solves cases one after another, keeping influence operators and the sequence state
    (previous tractions) between calls: use one for a sweep."""

    def __init__(self):
        self._core = _CoreSolver()

    def solve(self, case, base_dir="."):
        """Solve one case (a dict as in docs/case-files.md, or TOML text) and return its dict.

        A case with a "wheel_rail" table is a wheel/rail case (module 1); its profile files are
        found relative to base_dir."""
        text = case if isinstance(case, str) else to_toml([case])
        results = self._core.solve_toml(text, "python", str(base_dir))
        return results[0] if len(results) == 1 else results


def solve(case, base_dir="."):
    """Solve one case (dict or TOML text) with a fresh solver; returns the result dict."""
    return Solver().solve(case, base_dir)


def sweep(case, key, values):
    """Solve `case` once per value of the dotted key (e.g. "tangential.creepage_x") with one
    solver, returning the list of result dicts in the order of `values`."""
    solver = Solver()
    return [solver.solve(set_value(case, key, v)) for v in values]


def write_inp(cases, path, base_dir="."):
    """Write cases (a dict, a list of dicts, or TOML text) as a CONTACT .inp file at path, every
    value explicit (`rollcontact convert case.toml case.inp`): to run them in CONTACT or keep them
    in its format. Profile files are found relative to base_dir and named relative to path's
    folder; profiles given as points are written as tables beside the .inp file."""
    if isinstance(cases, dict):
        cases = [cases]
    text = cases if isinstance(cases, str) else to_toml(cases)
    _write_inp_from_toml(text, str(path), str(base_dir))


from . import plot  # noqa: E402  (matplotlib is imported only when a plot is made)
