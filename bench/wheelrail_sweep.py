#!/usr/bin/python3
"""Whole-process wheel/rail sweeps (issue 12, point 10): the Manchester benchmark A-2.2 of the
shared examples (S1002 on UIC60) refined from 21 to 101 lateral positions (0-10 mm in 0.1 mm
steps, yaw rising with it to 24 mrad; roll and pitch rate interpolated between the benchmark's
values), for the right and the left wheel, FZ = 10 and 50 kN per wheel (20 and 100 kN per
axle), DX = DS = 0.5 and 0.2 mm, steady rolling with the exact solvers, the vertical force
prescribed (N=1) and the position prescribed (N=0, at the heights the N=1 sweep found), and
KPEC pressures (B=5) with Fastsim (M=3) at prescribed vertical force: 24 sweeps, 2,424 cases;
with --conformal also each force sweep with conformal contact (D=4): 32 sweeps, 3,232 cases.

Each sweep is one .inp file of 101 cases, run as a whole process under /usr/bin/time -v
(median of --repeat runs; the wall time measured around the process with a monotonic clock).
Reported per sweep: wall time, time per case, peak memory, the share
of in-process time spent in geometry (profiles, contact search, patch set-up) against the patch
solves (from the per-case console lines), and the robustness counts: crashes (exit status other
than 0/1), cases with an error, cases not converged (each listed).

    /usr/bin/python3 bench/wheelrail_sweep.py --exe build/release/bin/rollcontact --out sweep/

writes sweep/*.inp, sweep/results.md and sweep/results.csv. --quick runs 11 positions per sweep
(a smoke test, about a second).
"""

import argparse
import csv
import json
import re
import shutil
import statistics
import subprocess
import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
EXAMPLES = HERE.parent.parent / "shared" / "reference" / "contact-examples"
PROFILES = ["MBench_UIC60_v3.prr", "MBench_S1002_v3.prw"]
SIDES = {"right": "mbench_a22_right.inp", "left": "mbench_a22_left.inp"}
LOADS_N = [10000.0, 50000.0]
GRIDS_MM = [0.5, 0.2]


def benchmark_cases(path):
    """(y, roll, yaw, vpitch) of each case of a benchmark file, and the first case's lines."""
    lines = path.read_text().splitlines()
    first, cases, in_first = [], [], True
    for line in lines:
        if in_first:
            first.append(line)
        if "S, Y, FZ, ROLL, YAW, PITCH" in line:
            v = line.split()
            cases.append([float(v[1]), float(v[3]), float(v[4])])
        if "VS,VY,VZ, VROLL,VYAW,VPITCH" in line:
            cases[-1].append(float(line.split()[5]))
            in_first = False
    return first, cases


def interpolate(cases, y):
    """Roll, yaw and pitch rate at lateral position y by linear interpolation in |y|."""
    ys = [abs(c[0]) for c in cases]
    for k in range(len(ys) - 1):
        if ys[k] <= abs(y) <= ys[k + 1]:
            t = (abs(y) - ys[k]) / (ys[k + 1] - ys[k])
            return [cases[k][j] + t * (cases[k + 1][j] - cases[k][j]) for j in (1, 2, 3)]
    return cases[-1][1:]


def digits_line(line, n_digit, kpec=False):
    """The C-P-B-T-N-F-S line with N replaced (and B = 5, KPEC, when asked)."""
    word = line.split()[0]
    new = word[:4] + str(n_digit) + word[5:]
    if kpec:
        new = new[:2] + "5" + new[3:]
    return line.replace(word, new, 1)


def material_digit(line, m_digit):
    """The V-L-D-C-M-Z-E line with M replaced."""
    word = line.split()[0]
    return line.replace(word, word[:4] + str(m_digit) + word[5:], 1)


def search_digit(line, d_digit):
    """The V-L-D-C-M-Z-E line with D replaced."""
    word = line.split()[0]
    return line.replace(word, word[:2] + str(d_digit) + word[3:], 1)


def write_sweep(path, side_file, load, grid, positions, heights=None, kpec=False,
                conformal=False):
    """One sweep file; heights (per case, from the N=1 run) make it position-prescribed; kpec:
    KPEC pressures (B=5) with Fastsim (M=3), as mbench_a22_kpec's first cases; conformal:
    conformal contact (D=4) instead of the planar patches (D=2)."""
    first, cases = benchmark_cases(side_file)
    sign = 1.0 if cases[-1][0] >= 0 else -1.0
    out = []
    for k, y_abs in enumerate(positions):
        y = sign * y_abs
        roll, yaw, vpitch = interpolate(cases, y)
        z_or_fz = heights[k] if heights is not None else load
        wheelset = f"  0.0  {y:.3f}  {z_or_fz:.8g}  {roll:.8f} {yaw:.6f}  0.0      S, Y, {'Z' if heights else 'FZ'}, ROLL, YAW, PITCH"
        velocity = f" 2000. 0.0    0.0   0.0        0.0  {vpitch:.8f} VS,VY,VZ, VROLL,VYAW,VPITCH"
        out.append(f"%  {k + 1}: lateral displacement {y:.1f} mm")
        if k == 0:
            for line in first:
                if line.startswith("%"):
                    continue
                if "C-P-B-T-N-F-S" in line:
                    line = digits_line(line, 0 if heights else 1, kpec)
                elif "V-L-D-C-M-Z-E" in line and (kpec or conformal):
                    line = material_digit(line, 3) if kpec else search_digit(line, 4)
                elif "DX" in line and "DS" in line:
                    v = line.split()
                    line = f"  {grid:.3f}   {grid:.3f}   {v[2]}   {v[3]}   {v[4]}   {v[5]}      DX, DS, DQREL, A_SEP, D_SEP, D_COMB"
                elif "S, Y, FZ" in line:
                    line = wheelset
                elif "VS,VY,VZ" in line:
                    line = velocity
                out.append(line)
                if kpec and "POISS" in line:
                    out.append("  1.000   1.000   1.000                        K0_MF,ALFAMF,BETAMF")
        else:
            digits = [l for l in first if "C-P-B-T-N-F-S" in l][0]
            out += ["  1 MODULE", digits_line(digits, 0 if heights else 1, kpec),
                    f" 0111{3 if kpec else 0}02    V-L-D-C-M-Z-E", " 0100321    H-G-I-A-O-W-R",
                    wheelset, velocity]
        out.append("")
    out.append("  0 MODULE")
    path.write_text("\n".join(out) + "\n")


CASE_LINE = re.compile(r"case\s+(\d+): (.*?)\(geometry ([\d.]+) ms, patches ([\d.]+) ms\)")


def run(exe, inp):
    """One whole-process run: wall [s], peak RSS [MB], exit status, console.

    The wall time is taken around the process with a monotonic clock: /usr/bin/time prints it in
    steps of 10 ms, a tenth of a millisecond per case of a 101-case sweep. It includes
    /usr/bin/time's own start (about 1 ms per sweep, 0.01 ms per case)."""
    start = time.perf_counter()
    p = subprocess.run(["/usr/bin/time", "-v", str(exe), "run", str(inp)],
                       capture_output=True, text=True)
    seconds = time.perf_counter() - start
    rss = re.search(r"Maximum resident set size \(kbytes\): (\d+)", p.stderr)
    status = re.search(r"Exit status: (\d+)", p.stderr)
    code = int(status.group(1)) if status else p.returncode
    return seconds, (int(rss.group(1)) / 1024 if rss else float("nan")), code, p.stdout


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--exe", default=str(HERE.parent / "build" / "release" / "bin" / "rollcontact"))
    ap.add_argument("--examples", default=str(EXAMPLES))
    ap.add_argument("--out", default="wheelrail_sweep")
    ap.add_argument("--repeat", type=int, default=3, help="runs per sweep; the median is reported")
    ap.add_argument("--quick", action="store_true", help="11 positions per sweep (smoke test)")
    ap.add_argument("--conformal", action="store_true",
                    help="also each force sweep with conformal contact (D=4)")
    a = ap.parse_args()
    out, examples = Path(a.out), Path(a.examples)
    out.mkdir(parents=True, exist_ok=True)
    for name in PROFILES:
        shutil.copy(examples / name, out / name)
    step = 1.0 if a.quick else 0.1
    positions = [round(k * step, 3) for k in range(int(round(10.0 / step)) + 1)]

    rows, problems = [], []
    for side, side_name in SIDES.items():
        for load in LOADS_N:
            for grid in GRIDS_MM:
                stem = f"{side}_fz{int(load / 1000)}k_dx{grid}"
                heights = None
                modes = ("force", "position", "kpec") + (("conformal",) if a.conformal else ())
                for mode in modes:
                    inp = out / f"{stem}_{mode}.inp"
                    write_sweep(inp, examples / side_name, load, grid, positions,
                                heights if mode == "position" else None, mode == "kpec",
                                mode == "conformal")
                    runs = [run(a.exe, inp) for _ in range(max(1, a.repeat))]
                    wall = statistics.median(r[0] for r in runs)
                    rss = max(r[1] for r in runs)
                    code, console = runs[-1][2], runs[-1][3]
                    lines = CASE_LINE.findall(console)
                    geometry = sum(float(m[2]) for m in lines) / 1e3
                    patches = sum(float(m[3]) for m in lines) / 1e3
                    not_conv = [int(m[0]) for m in lines if "NOT CONVERGED" in m[1]]
                    errors = len(re.findall(r"case\s+\d+: ERROR", console))
                    n = len(positions)
                    rows.append({"sweep": inp.stem, "cases": n, "wall_s": round(wall, 3),
                                 "ms_per_case": round(1e3 * wall / n, 2),
                                 "geometry_share": round(geometry / max(geometry + patches, 1e-12), 3),
                                 "peak_rss_mb": round(rss, 1), "exit": code,
                                 "errors": errors, "not_converged": len(not_conv)})
                    if code not in (0, 1):
                        problems.append(f"{inp.name}: CRASH (exit status {code})")
                    if not_conv:
                        problems.append(f"{inp.name}: not converged in cases {not_conv}")
                    if mode == "force":
                        doc = json.loads((out / f"{inp.stem}.json").read_text())
                        heights = [c.get("z_ws", 0.0) for c in doc["cases"]]
                    print(f"{inp.stem:<36} {n:4d} cases  {wall:7.3f} s  "
                          f"{1e3 * wall / n:7.2f} ms/case  geometry {rows[-1]['geometry_share']:.0%}"
                          f"  exit {code}  errors {errors}  not converged {len(not_conv)}",
                          flush=True)

    with open(out / "results.csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    with open(out / "results.md", "w") as f:
        f.write("| sweep | cases | wall [s] | per case [ms] | geometry share | peak RSS [MB] | "
                "exit | errors | not converged |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|\n")
        for r in rows:
            f.write("| " + " | ".join(str(v) for v in r.values()) + " |\n")
        total = sum(r["cases"] for r in rows)
        f.write(f"\n{total} cases in {len(rows)} sweeps.\n")
        for p in problems:
            f.write(f"\n* {p}")
    print(f"{sum(r['cases'] for r in rows)} cases; results in {out / 'results.md'}")
    for p in problems:
        print(p)
    return 1 if any("CRASH" in p for p in problems) else 0


if __name__ == "__main__":
    sys.exit(main())
