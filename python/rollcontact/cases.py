"""Cases as Python dicts and their TOML text (the schema of docs/case-files.md)."""

import copy
import json
import math


def hertz_case(fn_N, semi_axes_mm, creepage_x=0.0, creepage_y=0.0, spin_rad_per_mm=0.0,
               elements=(41, 41), scale=1.1, mu=0.3, poisson=0.28, shear_modulus_MPa=82000.0,
               problem="steady_rolling", velocity_mm_per_s=10000.0):
    """A Hertzian contact between identical bodies: normal force, semi-axes (a, b) [mm],
    creepages (or shifts [mm] for problem="shift"), Coulomb friction mu."""
    body = {"poisson": poisson, "shear_modulus_MPa": shear_modulus_MPa}
    case = {
        "normal": {"force_N": float(fn_N)},
        "material": {"body1": dict(body), "body2": dict(body)},
        "friction": {"law": "coulomb", "static": mu, "kinetic": mu},
        "grid": {"hertz": {"elements": list(elements), "semi_axes_mm": list(semi_axes_mm),
                           "scale": scale}},
    }
    if problem != "none":
        shift = problem == "shift"
        t = {"problem": problem}
        t["shift_x_mm" if shift else "creepage_x"] = creepage_x
        t["shift_y_mm" if shift else "creepage_y"] = creepage_y
        t["rotation_rad" if shift else "spin_rad_per_mm"] = spin_rad_per_mm
        if problem in ("steady_rolling", "transient_rolling"):
            dx = 2.0 * scale * semi_axes_mm[0] / elements[0]
            t["rolling"] = {"step_mm": dx, "velocity_mm_per_s": velocity_mm_per_s}
        case["tangential"] = t
    return case


def set_value(case, key, value):
    """A copy of `case` with the dotted key ("tangential.creepage_x") set to value."""
    out = copy.deepcopy(case)
    node = out
    parts = key.split(".")
    for p in parts[:-1]:
        node = node.setdefault(p, {})
    node[parts[-1]] = value
    return out


def _value(v):
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        if not math.isfinite(v):
            raise ValueError(f"not a finite number: {v}")
        return repr(v)
    if isinstance(v, str):
        return json.dumps(v)
    if isinstance(v, dict):
        return "{ " + ", ".join(f"{k} = {_value(x)}" for k, x in v.items()) + " }"
    if hasattr(v, "tolist"):  # NumPy arrays and scalars
        return _value(v.tolist())
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(_value(x) for x in v) + "]"
    raise TypeError(f"cannot write {type(v).__name__} to TOML")


def _table(lines, path, table):
    scalars = {k: v for k, v in table.items() if not isinstance(v, dict)}
    for k, v in scalars.items():
        lines.append(f"{k} = {_value(v)}")
    for k, v in table.items():
        if isinstance(v, dict):
            lines.append("")
            lines.append(f"[{path}.{k}]")
            _table(lines, f"{path}.{k}", v)


def to_toml(cases):
    """TOML text of a list of case dicts (one [[case]] each)."""
    lines = ["version = 1"]
    for case in cases:
        lines += ["", "[[case]]"]
        _table(lines, "case", case)
    return "\n".join(lines) + "\n"
