"""Plots of rollcontact results with matplotlib (imported on first use).

Each function draws into `ax` (a new figure when None) and returns the Axes; save with
ax.figure.savefig("fig.png", dpi=150). Axes carry units, colour bars their quantity, and the
adhesion/slip boundary is drawn where there is one.
"""

import numpy as np

_FIELDS = {
    "pressure": ("pn", "normal pressure p$_n$ [N/mm$^2$]"),
    "traction": (None, "tangential traction |p$_t$| [N/mm$^2$]"),
    "slip": (None, "relative slip |s| [-]"),
}


def _axes(ax):
    if ax is not None:
        return ax
    import matplotlib

    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt

    _, ax = plt.subplots(figsize=(6.4, 4.8), constrained_layout=True)
    return ax


def _edges(centres, step):
    return np.concatenate([centres - 0.5 * step, [centres[-1] + 0.5 * step]])


def field(result, what="pressure", ax=None, title=None):
    """A field over the grid: 'pressure', 'traction' (magnitude, with arrows) or 'slip', with
    the contact edge (black) and the adhesion/slip boundary (white dashed)."""
    if what not in _FIELDS:
        raise ValueError(f"what must be one of {sorted(_FIELDS)}, not {what!r}")
    ax = _axes(ax)
    g = result["grid"]
    x, y = g["x"], g["y"]
    if what == "pressure":
        values = result["pn"]
    elif what == "traction":
        values = np.hypot(result["px"], result["py"])
    else:
        values = np.hypot(result["sx"], result["sy"])
    mesh = ax.pcolormesh(_edges(x, g["dx"]), _edges(y, g["dy"]), values, cmap="viridis",
                         shading="flat")
    ax.figure.colorbar(mesh, ax=ax, label=_FIELDS[what][1])
    state = result["state"]
    if state.max() > 0 and len(x) > 1 and len(y) > 1:
        ax.contour(x, y, (state > 0).astype(float), levels=[0.5], colors="k", linewidths=1.0)
        if (state == 1).any() and (state == 2).any():
            ax.contour(x, y, (state == 2).astype(float), levels=[0.5], colors="w",
                       linewidths=1.0, linestyles="--")
    if what == "traction":
        step = max(1, len(x) // 20)
        inside = state[::step, ::step] > 0  # arrows in the contact only
        px = np.ma.masked_where(~inside, result["px"][::step, ::step])
        py = np.ma.masked_where(~inside, result["py"][::step, ::step])
        ax.quiver(x[::step], y[::step], px, py, color="w", width=0.003)
    ax.set_xlabel("x [mm] (rolling direction)")
    ax.set_ylabel("y [mm]")
    ax.set_aspect("equal")
    ax.set_title(title or f"{_FIELDS[what][1].split(' [')[0]}, F$_n$ = {result['fn']:.4g} N")
    return ax


def traction_profile(result, row=None, ax=None, mu=None, title=None):
    """p_x, p_y along one grid row (default: the row through the maximum pressure), with the
    traction bound mu·p_n when mu is given."""
    ax = _axes(ax)
    pn = result["pn"]
    iy = int(np.unravel_index(np.argmax(pn), pn.shape)[0]) if row is None else int(row)
    x = result["grid"]["x"]
    ax.plot(x, result["px"][iy], label="p$_x$")
    ax.plot(x, result["py"][iy], label="p$_y$")
    if mu is not None:
        ax.plot(x, mu * pn[iy], "k--", label="$\\mu$ p$_n$")
        ax.plot(x, -mu * pn[iy], "k--")
    ax.set_xlabel("x [mm]")
    ax.set_ylabel("traction [N/mm$^2$]")
    ax.legend()
    ax.set_title(title or f"tractions along row {iy + 1} (y = {result['grid']['y'][iy]:.3g} mm)")
    return ax


def creep_curve(results, x="creep_x", y="fx", ax=None, normalise=True, title=None):
    """A creep-force curve of a sweep: y (default F_x, divided by F_n when normalise) against
    x (default the longitudinal creepage)."""
    ax = _axes(ax)
    xs = np.array([r[x] for r in results])
    ys = np.array([r[y] / r["fn"] if normalise else r[y] for r in results])
    ax.plot(xs, ys, "o-")
    ax.set_xlabel({"creep_x": "creepage $\\xi$ [-]", "creep_y": "creepage $\\eta$ [-]",
                   "spin": "spin $\\varphi$ [rad/mm]"}.get(x, x))
    ax.set_ylabel(f"{y.upper()}/F$_n$ [-]" if normalise else f"{y.upper()} [N]")
    ax.grid(True, alpha=0.3)
    ax.set_title(title or "creep-force curve")
    return ax


def profiles(rail, wheel=None, contact_points=None, ax=None, title=None):
    """Rail and wheel profiles, each a pair (y, z) of arrays [mm] (z downwards, as CONTACT), and
    optionally contact points [(y, z), ...] in the same frame."""
    ax = _axes(ax)
    ax.plot(rail[0], rail[1], "k-", label="rail")
    if wheel is not None:
        ax.plot(wheel[0], wheel[1], "b-", label="wheel")
    if contact_points:
        pts = np.asarray(contact_points, dtype=float)
        ax.plot(pts[:, 0], pts[:, 1], "ro", label="contact")
    ax.invert_yaxis()  # z downwards
    ax.set_xlabel("y [mm]")
    ax.set_ylabel("z [mm] (downwards)")
    ax.set_aspect("equal")
    ax.legend()
    ax.set_title(title or "profiles")
    return ax


def placed_profiles(case):
    """The rail and wheel profiles of a wheel/rail result (rc.run on a module-1 file) placed in
    track coordinates with the solution's markers: ((y_rail, z_rail), (y_wheel, z_wheel)) [mm],
    z downwards. A left wheel's profiles are mirrored as the track is."""
    side = -1.0 if case.get("side") == "left" else 1.0

    def place(points, marker, yaw=0.0):
        yp = side * np.asarray(points["y"]) * np.cos(yaw)
        zp = np.asarray(points["z"])
        a = marker["roll"]
        return (marker["y"] + np.cos(a) * yp - np.sin(a) * zp,
                marker["z"] + np.sin(a) * yp + np.cos(a) * zp)

    rail = place(case["rail_profile"], case["rail_marker"])
    wheel = place(case["wheel_profile"], case["wheel_marker"], case["wheel_marker"]["yaw"])
    return rail, wheel


def wheelrail(case, ax=None, margin_mm=40.0, title=None):
    """A wheel/rail result: the placed rail and wheel profiles around the contact, with each
    patch's reference point and its extent along the contact (the grid's width); a conformal
    patch (D=4) shows its curved reference surface instead, one point per grid row."""
    rail, wheel = placed_profiles(case)
    points = [(p["reference_tr"][1], p["reference_tr"][2]) for p in case["patches"]]
    ax = profiles(rail, wheel, points, ax=ax, title=title)
    for p in case["patches"]:
        if "conformal" in p:
            c = p["conformal"]
            ax.plot(c["row_y"], c["row_z"], "r.-", linewidth=2, markersize=3, alpha=0.6)
            continue
        g, d = p["grid"], p["contact_angle"]
        width = g["my"] * g["dy"]
        y0, z0 = p["reference_tr"][1], p["reference_tr"][2]
        ys = y0 + np.array([-0.5, 0.5]) * width * np.cos(d)
        zs = z0 + np.array([-0.5, 0.5]) * width * np.sin(d)
        ax.plot(ys, zs, "r-", linewidth=3, alpha=0.6)
    if points:
        yc = np.mean([q[0] for q in points])
        ax.set_xlim(yc - margin_mm, yc + margin_mm)
        zc = np.mean([q[1] for q in points])
        ax.set_ylim(zc + 0.5 * margin_mm, zc - 0.5 * margin_mm)  # z downwards
    ax.set_xlabel("y [mm] (track)")
    return ax


def read_dynamic(path):
    """The history `rollcontact dynamic` wrote (CSV, one row per kept step) as a NumPy record
    array with the header's names (t_s, s_mm, z_ws_mm, fz_N, area_mm2, pmax_N_mm2, ...)."""
    return np.genfromtxt(path, delimiter=",", names=True, skip_header=1)


def dynamic(history, fig=None, title=None, static_load_N=None):
    """A dynamic-rolling history (`read_dynamic`): the vertical contact force, the contact area
    and the peak pressure along the rolled distance, and the wheel's height. Returns the
    first Axes; all share the distance axis."""
    import matplotlib

    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt

    if fig is None:
        fig = plt.figure(figsize=(7.0, 7.0), constrained_layout=True)
    axes = fig.subplots(3, 1, sharex=True)
    s = history["s_mm"]
    axes[0].plot(s, history["fz_N"] / 1e3, "k-", linewidth=1.0, label="F$_z$ (rail)")
    if static_load_N:
        axes[0].axhline(static_load_N / 1e3, color="0.5", linestyle="--", linewidth=0.8,
                        label="static load")
        axes[0].legend(loc="best", fontsize="small")
    axes[0].set_ylabel("vertical contact force [kN]")
    axes[1].plot(s, history["area_mm2"], "b-", linewidth=1.0)
    axes[1].set_ylabel("contact area [mm$^2$]", color="b")
    twin = axes[1].twinx()
    twin.plot(s, history["pmax_N_mm2"], "r-", linewidth=1.0)
    twin.set_ylabel("p$_{max}$ [N/mm$^2$]", color="r")
    axes[2].plot(s, 1e3 * (history["z_ws_mm"] - history["z_ws_mm"][0]), "k-", linewidth=1.0,
                 label="wheel")
    if np.any(history["rail_dz_mm"] != 0.0):
        axes[2].plot(s, 1e3 * history["rail_dz_mm"], "g--", linewidth=1.0, label="rail dip")
        axes[2].legend(loc="best", fontsize="small")
    axes[2].set_ylabel("height change [µm] (down)")
    axes[2].set_xlabel("rolled distance [mm]")
    if title:
        axes[0].set_title(title)
    return axes[0]
