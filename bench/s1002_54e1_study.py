#!/usr/bin/python3
"""Static S1002-on-54E1 contact of Ma et al. (2018): the measurements of docs/validation-fe.md.

Writes module-1 .inp files for the case of examples/s1002_54e1.inp (S1002 wheel, 54E1 rail of
scripts/make_54e1_profile.py, cant 1:40, FZ prescribed, normal problem T=0) and runs each as a
whole process (`rollcontact run FILE -q`), timed from spawning to exit (os.wait4: wall time and
peak resident set). Tables, in Markdown:

  grid     DX = DS = 1.0 ... 0.1 mm at 100 kN, with a Richardson-style extrapolation of area
           and pmax from the finest grids;
  load     80/100/120/140 kN at DX = DS = 0.25 mm, with the Hertz ratios (p ~ F^1/3,
           A ~ F^2/3) and the paper's FE pmax, at Y_WS = 0 and -1 mm (--load-y-ws);
  lateral  Y_WS = -3 ... +3 mm (0.5 mm steps) at 100 kN (the sensitivity of
           ../shared/spec/dynamic-rolling.md §6.3), for the 54E1 of examples/profiles and,
           with --variant-crown, a 54E1 whose R300/R80 tangent point is moved (e.g. 10.0 mm,
           the extent of spec §2.3); and the cant 0, 1:40, 1:20 at Y_WS = 0;
  proxy    the Manchester UIC60 file (pre-canted, CANT 0) at 80 ... 140 kN, DX = DS = 0.25 mm,
           normal problem (T=0) and free steady rolling (T=3, VPITCH = -V/460), against
           CONTACT's reference numbers of spec §6.2 (those with FX = -0.25 FZ).

    /usr/bin/python3 bench/s1002_54e1_study.py --exe build/release/bin/rollcontact \\
        [--out study.md] [--json study.json] [--only grid,load,lateral,proxy] [--figure F.png]

Standard library only (matplotlib for --figure). Contact area = n_con DX DS [mm^2]; pmax
[N/mm^2]; approach PEN [mm]; y_r lateral position of the contact reference point on the rail
profile [mm]; delta the contact angle [rad]; z_ws the wheelset height found for the prescribed
FZ [mm]; time the whole process's wall time [s].
"""

import argparse
import json
import math
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPO = HERE.parent
PROFILES = REPO / "examples" / "profiles"

# The paper's converged FE peak pressures [MPa] (Fig. 17) and areas [mm^2] (Table 2, Esize 2 mm,
# and the Esize -> 0 line of spec §4.2), and CONTACT's reference run of spec §6.2 on the UIC60
# proxy (DX = DS = 0.25, F1 = 1 with FX = -0.25 FZ): FZ [kN] -> (pmax, n_con, area, approach).
PAPER_PMAX = {80: 1005.0, 100: 1041.0, 120: 1050.0, 140: 1088.0}
PAPER_AREA_ESIZE2, PAPER_AREA_EXTRAPOLATED = 265.8, 226.6
CONTACT_PROXY = {80: (904.0, 2700, 168.8, 0.06341), 100: (990.1, 3062, 191.4, 0.07442),
                 120: (1065.0, 3392, 212.0, 0.08487), 140: (1133.0, 3685, 230.3, 0.09488)}

V_MM_S = 38888.9  # 140 km/h
VPITCH_FREE = -V_MM_S / 460.0  # free rolling on the nominal radius [rad/s]


def inp_text(rail, wheel, cant, dx, fz, y_ws=0.0, rolling=False):
    """One module-1 case: right wheel, FZ prescribed (N=1), T=0 or free steady rolling (T=3)."""
    t = 3 if rolling else 0
    return "\n".join([
        f"% bench/s1002_54e1_study.py: rail {Path(rail).name}, cant {cant}, DX = DS = {dx}, "
        f"FZ {fz}, Y_WS {y_ws}, T={t}",
        "  1 MODULE",
        f" 120{t}100    C-P-B-T-N-F-S",
        " 0022033    V-L-D-C-M-Z-E",
        " 0000321    H-G-I-A-O-W-R",
        # NPOT_MAX 400000: the 0.1 mm grid must not be coarsened (default 20000 elements).
        "    999  100  30  1  1e-5  400000      MAXGS MAXIN MAXNR MAXOUT EPS NPOT_MAX",
        "  0.5  0.5                             FSTAT FKIN",
        "  0.3  0.3  80769.2  80769.2           POISS GG",
        f"  {dx!r} {dx!r} 1.0 90d 8.0 4.0      DX DS DQREL A_SEP D_SEP D_COMB",
        f"  14.0  0  1435.0  {cant!r}           GAUGHT GAUGSQ GAUGWD CANT",
        f"  '{rail}'  0  1.0  0.0               rail",
        "  0.0  0.0  0.0  0.0  0.0  0.0",
        "  1360.0  -70.0  460.0                 FBDIST FBPOS NOMRADW",
        f"  '{wheel}'  0  1.0  0.0              wheel",
        f"  0.0  {y_ws!r}  {fz!r}  0.0  0.0  0.0   S Y FZ ROLL YAW PITCH",
        f"  {V_MM_S!r}  0.0  0.0  0.0  0.0  {VPITCH_FREE!r}   VS VY VZ VROLL VYAW VPITCH",
        "  0 MODULE", ""])


def run(exe, text, work, name):
    """Runs one file; returns the patch's numbers, wall time [s] and peak RSS [MB]."""
    inp = work / f"{name}.inp"
    inp.write_text(text)
    t0 = time.perf_counter()
    proc = subprocess.Popen([exe, "run", str(inp), "-q"], stdout=subprocess.DEVNULL,
                            stderr=subprocess.PIPE)
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - t0
    stderr = proc.stderr.read().decode()
    proc.stderr.close()
    if os.waitstatus_to_exitcode(status) != 0:
        sys.exit(f"{name}: rollcontact failed:\n{stderr}")
    case = json.loads((work / f"{name}.json").read_text())["cases"][0]
    if case["status"] != "converged" or len(case["patches"]) != 1:
        sys.exit(f"{name}: {case['status']}, {len(case['patches'])} patches")
    p = case["patches"][0]
    dx, ds = p["grid"]["dx"], p["grid"]["ds"]
    return {
        "dx": dx, "ds": ds, "npot": p["statistics"]["npot"], "ncon": p["statistics"]["ncon"],
        "area": p["statistics"]["ncon"] * dx * ds, "pmax": p["pmax"], "pen": p["pen"],
        "fn": p["fn"], "fz": case["force_tr"][2], "fx": case["force_tr"][0],
        "y_rail": p["reference_rail"][0], "delta": p["contact_angle"], "z_ws": case["z_ws"],
        "seconds": wall, "peak_mb": usage.ru_maxrss / 1024.0,
    }


def extrapolate(hs, qs):
    """q(h) = q0 + c h^p through the three finest grids when they form a monotone sequence with
    a constant refinement ratio; else None. Returns (q0, p)."""
    (h1, q1), (h2, q2), (h3, q3) = sorted(zip(hs, qs))[:3]
    r = h2 / h1
    if abs(h3 / h2 - r) > 1e-9 or (q3 - q2) * (q2 - q1) <= 0:
        return None
    p = math.log((q3 - q2) / (q2 - q1)) / math.log(r)
    return q1 - (q2 - q1) / (r ** p - 1.0), p


def fit_linear(hs, qs):
    """Least-squares q(h) = q0 + c h: (q0, c)."""
    n = len(hs)
    mh, mq = sum(hs) / n, sum(qs) / n
    c = sum((h - mh) * (q - mq) for h, q in zip(hs, qs)) / sum((h - mh) ** 2 for h in hs)
    return mq - c * mh, c


def table(header, rows):
    out = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    out += ["| " + " | ".join(r) + " |" for r in rows]
    return "\n".join(out)


def grid_study(exe, work, rail, wheel):
    sizes = [1.0, 0.5, 0.4, 0.25, 0.2, 0.15, 0.1]
    res = {h: run(exe, inp_text(rail, wheel, 0.025, h, 100000.0), work, f"grid_{h}") for h in sizes}
    rows = [[f"{h:g}", f"{r['npot']}", f"{r['ncon']}", f"{r['area']:.1f}", f"{r['pmax']:.1f}",
             f"{r['pen']:.5f}", f"{r['y_rail']:.3f}", f"{r['delta']:.4f}", f"{r['z_ws']:.5f}",
             f"{r['seconds']:.2f}", f"{r['peak_mb']:.0f}"] for h, r in res.items()]
    text = table(["DX = DS [mm]", "n_pot", "n_con", "area [mm²]", "pmax [MPa]", "approach [mm]",
                  "y_r [mm]", "δ [rad]", "z_ws [mm]", "time [s]", "peak RSS [MB]"], rows)
    fine = [h for h in sizes if h <= 0.25]
    notes = []
    for q in ("area", "pmax", "pen"):
        hs, qs = fine, [res[h][q] for h in fine]
        q0, c = fit_linear(hs, qs)
        notes.append(f"* {q}: least-squares line q0 + c·h over h = 0.25 ... 0.1 mm: q0 = {q0:.4g},"
                     f" c = {c:+.4g} per mm (h = 0.25: {res[0.25][q]:.4g}, "
                     f"{100 * (res[0.25][q] / q0 - 1):+.2f} % from q0)")
        tri = [0.4, 0.2, 0.1]
        e = extrapolate(tri, [res[h][q] for h in tri])
        if e:
            notes.append(f"  Richardson from h = 0.4, 0.2, 0.1 (ratio 2): q0 = {e[0]:.4g}, "
                         f"observed order {e[1]:.2f}")
        else:
            notes.append("  Richardson from h = 0.4, 0.2, 0.1: not monotone, no extrapolation")
    return text + "\n\n" + "\n".join(notes), res


def load_rows(res):
    rows = []
    for fz, r in res.items():
        paper = PAPER_PMAX[fz]
        rows.append([f"{fz}", f"{r['ncon']}", f"{r['area']:.1f}", f"{r['pmax']:.1f}",
                     f"{r['pen']:.5f}", f"{r['y_rail']:.3f}", f"{r['delta']:.4f}",
                     f"{paper:.0f}", f"{r['pmax'] / paper:.3f}", f"{r['seconds']:.2f}"])
    return rows


def ratio_note(res):
    p = res[140]["pmax"] / res[80]["pmax"]
    a = res[140]["area"] / res[80]["area"]
    hp, ha = (140 / 80) ** (1 / 3), (140 / 80) ** (2 / 3)
    return (f"* 140/80 kN: pmax ratio {p:.3f} (Hertz {hp:.3f}, {100 * (p / hp - 1):+.1f} %), "
            f"area ratio {a:.3f} (Hertz {ha:.3f}, {100 * (a / ha - 1):+.1f} %); "
            f"paper FE pmax ratio {PAPER_PMAX[140] / PAPER_PMAX[80]:.3f}")


def load_study(exe, work, rail, wheel, y_ws):
    res = {fz: run(exe, inp_text(rail, wheel, 0.025, 0.25, fz * 1000.0, y_ws=y_ws), work,
                   f"load_{fz}_{y_ws}") for fz in (80, 100, 120, 140)}
    text = table(["FZ [kN]", "n_con", "area [mm²]", "pmax [MPa]", "approach [mm]", "y_r [mm]",
                  "δ [rad]", "paper FE pmax", "ratio", "time [s]"], load_rows(res))
    return text + "\n\n" + ratio_note(res), res


def lateral_study(exe, work, rails, wheel):
    shifts = [0.5 * k for k in range(-6, 7)]
    res = {}
    for label, rail in rails:
        res[label] = {y: run(exe, inp_text(rail, wheel, 0.025, 0.25, 100000.0, y_ws=y), work,
                             f"lat_{label}_{y}") for y in shifts}
    header = ["rail", "quantity"] + [f"Y_WS {y:+g}" for y in shifts]
    rows = []
    for label, r in res.items():
        rows.append([label, "pmax [MPa]"] + [f"{r[y]['pmax']:.0f}" for y in shifts])
        rows.append([label, "area [mm²]"] + [f"{r[y]['area']:.1f}" for y in shifts])
        rows.append([label, "y_r [mm]"] + [f"{r[y]['y_rail']:.2f}" for y in shifts])
    text = table(header, rows)
    # The rail cant at Y_WS = 0: the 1:40 of the Dutch network assumed for the paper, none, 1:20.
    cants = {"0": 0.0, "1:40": 0.025, "1:20": 0.05}
    res["cant"] = {k: run(exe, inp_text(rails[0][1], wheel, c, 0.25, 100000.0), work,
                          f"cant_{k.replace(':', '_')}") for k, c in cants.items()}
    rows = [[k, f"{r['pmax']:.0f}", f"{r['area']:.1f}", f"{r['y_rail']:.2f}", f"{r['delta']:.4f}"]
            for k, r in res["cant"].items()]
    text += "\n\nCant (54E1, Y_WS = 0):\n\n" + table(
        ["cant", "pmax [MPa]", "area [mm²]", "y_r [mm]", "δ [rad]"], rows)
    return text, res


def proxy_study(exe, work, wheel):
    rail = str(PROFILES / "MBench_UIC60_v3.prr")
    res = {}
    rows = []
    for fz in (80, 100, 120, 140):
        t0 = run(exe, inp_text(rail, wheel, 0.0, 0.25, fz * 1000.0), work, f"proxy_{fz}")
        t3 = run(exe, inp_text(rail, wheel, 0.0, 0.25, fz * 1000.0, rolling=True), work,
                 f"proxy_rolling_{fz}")
        res[fz] = {"normal": t0, "free_rolling": t3}
        cp, cn, ca, cpen = CONTACT_PROXY[fz]
        rows.append([f"{fz}", f"{t0['pmax']:.1f} / {t3['pmax']:.1f} / {cp:.1f}",
                     f"{t0['ncon']} / {t3['ncon']} / {cn}",
                     f"{t0['area']:.1f} / {t3['area']:.1f} / {ca:.1f}",
                     f"{t0['pen']:.5f} / {t3['pen']:.5f} / {cpen:.5f}",
                     f"{t0['fn']:.0f} / {t3['fn']:.0f}", f"{t3['fx']:.0f}",
                     f"{t0['seconds']:.2f} / {t3['seconds']:.2f}"])
    text = table(["FZ [kN]", "pmax [MPa]", "n_con", "area [mm²]", "approach [mm]", "FN [N]",
                  "FX(TR) free [N]", "time [s]"], rows)
    note = ("Each cell: rollcontact T=0 / rollcontact T=3 free rolling / CONTACT T=3 with "
            "FX = -0.25 FZ (spec §6.2).")
    return text + "\n\n" + note, res


def lateral_figure(res, path):
    """pmax and area against Y_WS for each rail, with the paper's FE values (matplotlib)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (ap, aa) = plt.subplots(1, 2, figsize=(8.0, 3.2), constrained_layout=True)
    for label, r in res.items():
        if label == "cant":
            continue
        ys = sorted(r)
        ap.plot(ys, [r[y]["pmax"] for y in ys], "o-", ms=3, label=label)
        aa.plot(ys, [r[y]["area"] for y in ys], "o-", ms=3, label=label)
    ap.axhline(PAPER_PMAX[100], color="k", ls="--", lw=1, label="paper FE (1041)")
    aa.axhline(PAPER_AREA_ESIZE2, color="k", ls="--", lw=1, label="paper FE, Esize 2 mm")
    aa.axhline(PAPER_AREA_EXTRAPOLATED, color="k", ls=":", lw=1, label="paper FE, Esize → 0")
    ap.set(xlabel="Y_WS [mm]", ylabel="pmax [N/mm²]", title="S1002 on 54E1, 100 kN, cant 1:40")
    aa.set(xlabel="Y_WS [mm]", ylabel="contact area [mm²]")
    ap.legend(fontsize=7)
    aa.legend(fontsize=7)
    fig.savefig(path, dpi=90)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--exe", default=str(REPO / "build/release/bin/rollcontact"))
    ap.add_argument("--out", type=Path, help="Markdown tables (default: stdout)")
    ap.add_argument("--json", type=Path, help="all numbers as JSON")
    ap.add_argument("--only", default="grid,load,lateral,proxy")
    ap.add_argument("--load-y-ws", type=lambda t: [float(v) for v in t.split(",")],
                    default=[0.0, -1.0], help="Y_WS [mm] of the load sweeps (default 0,-1)")
    ap.add_argument("--figure", type=Path, help="PNG of the lateral study (needs matplotlib)")
    ap.add_argument("--variant-crown", type=float, default=10.0,
                    help="R300/R80 tangent |y| [mm] of the variant 54E1 in the lateral study "
                         "(0: none; default %(default)g, spec §2.3)")
    a = ap.parse_args()
    which = set(a.only.split(","))
    rail = str(PROFILES / "54E1_head.prr")
    wheel = str(PROFILES / "MBench_S1002_v3.prw")
    parts, data = [], {}
    with tempfile.TemporaryDirectory(prefix="s1002_54e1_") as tmp:
        work = Path(tmp)
        if "grid" in which:
            text, data["grid"] = grid_study(a.exe, work, rail, wheel)
            parts.append("### Grid convergence (54E1, 100 kN)\n\n" + text)
        if "load" in which:
            data["load"] = {}
            for y in a.load_y_ws:
                text, data["load"][y] = load_study(a.exe, work, rail, wheel, y)
                parts.append(f"### Load sweep (54E1, Y_WS = {y:g} mm, DX = DS = 0.25 mm)\n\n"
                             + text)
        if "lateral" in which:
            rails = [("54E1", rail)]
            if a.variant_crown > 0:
                variant = work / f"54E1_crown{a.variant_crown:g}.prr"
                subprocess.run([sys.executable, str(REPO / "scripts/make_54e1_profile.py"), "-o",
                                str(variant), "--crown-half-width", str(a.variant_crown)],
                               check=True, stdout=subprocess.DEVNULL)
                rails.append((f"54E1, R300 to {a.variant_crown:g}", str(variant)))
            text, data["lateral"] = lateral_study(a.exe, work, rails, wheel)
            parts.append("### Lateral position (100 kN, DX = DS = 0.25 mm)\n\n" + text)
            if a.figure:
                lateral_figure(data["lateral"], a.figure)
        if "proxy" in which:
            text, data["proxy"] = proxy_study(a.exe, work, wheel)
            parts.append("### UIC60 proxy vs CONTACT (DX = DS = 0.25 mm)\n\n" + text)
    md = "\n\n".join(parts) + "\n"
    if a.out:
        a.out.write_text(md)
    else:
        print(md)
    if a.json:
        a.json.write_text(json.dumps(data, indent=1, default=str))


if __name__ == "__main__":
    main()
