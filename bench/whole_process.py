#!/usr/bin/python3
"""Whole-process timings of the benchmark patch (issue 16, item 1).

Writes CONTACT .inp files for the non-Hertzian wheel/rail-like patch of
bench/wheel_rail_patch.hpp (IPOTCN=1 grid of 0.1 mm elements, IBASE=2 tabulated lateral profile
plus x^2/(2*460 mm), approach prescribed, the scale-1 patch stretched by s = 1, 2, 4, 8) for
  - the normal problem (T=0) at 71x81 ... 575x647,
  - shifts (T=1, shift 0.0005 mm, spin 0.0003 rad, mu = 0.3) at the first three sizes,
  - steady rolling (T=3, creepage 0.0005, spin 0.0003 rad/mm) at the first three sizes,
  - steady rolling with the forces prescribed (F=2, the forces of the creepage-driven run) at
    the first two sizes,
the same problems the in-process benchmarks bench/normal_problem.cpp and
bench/tangential_problem.cpp solve, and CONTACT's example inputs spence35, carter2d,
catt_to_cart, tractcurv, mbench_a22_varfric, wheelflat and visc_cylindr. Each file is run as a
whole process,

    rollcontact run FILE -q --timing

--repeat times (with --exe-before, an earlier binary alternating with it run by run), timed from
spawning to exit (Popen and wait4: /usr/bin/time's %e has 10 ms steps); reported are the median,
the fastest and the first wall time (the first plans its FFTs afresh), the largest peak resident
set, the median split set-up / solve / output that `--timing` prints to stderr, and CONTACT's whole-process time
(gfortran -O2, one thread, this machine class; issue 16) with the ratio.

    /usr/bin/python3 bench/whole_process.py --exe build/release/bin/rollcontact --out table.md

--quick runs the smallest size of each kind once (a smoke run, about a second). --before FILE
adds the columns of an earlier run (its --json output) to the table; --doc docs/benchmarks.md
puts the table between its markers. Standard library only.
"""

import argparse
import json
import os
import shutil
import re
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent

# (mx, my, scale) of the four sizes.
SIZES = [(71, 81, 1.0), (143, 163, 2.0), (287, 323, 4.0), (575, 647, 8.0)]

# CONTACT's whole-process wall times [s] per kind and size index (issue 16).
CONTACT_SECONDS = {
    "normal": [0.050, 0.24, 1.53, 9.0],
    "shift": [0.22, 1.46, 14.0],
    "steady": [0.86, 7.3, 51.0],
    "steady_forces": [8.4, 68.0],
}
CONTACT_PEAK_MB = {("normal", 3): 654.0}

# CONTACT's own example inputs of issue 16 (../shared/reference/contact-examples) with CONTACT's
# whole-process wall time [s]: tractcurv from the issue (gfortran -O2, this machine class), the
# others from the "Total" wall clock their .ref_out prints (carter2d prints 0.0: under 0.05 s).
# mbench_a22_varfric has two conformal flange-root patches (D=4, cases 5 and 7); wheelflat is a
# wheel-flat passage (258 wheel slices, 26 positions), run with --unvalidated (the default run
# refuses wheel slices: docs/decisions.md, "Variable wheel profiles"); visc_cylindr is steady
# rolling of viscoelastic cylinders (M=1: the history-integrated influence coefficients).
EXAMPLE_CONTACT_SECONDS = {"spence35": 2.3, "carter2d": None, "catt_to_cart": 2.6, "tractcurv": 19.0,
                           "mbench_a22_varfric": 3.2, "wheelflat": 22.3, "visc_cylindr": 0.1}
# Extra `rollcontact run` arguments per example input.
EXAMPLE_FLAGS = {"wheelflat": ["--unvalidated"]}
# Files an example reads besides its .inp (profiles, slices).
EXAMPLE_FILES = {"mbench_a22_varfric": ["MBench_UIC60_v3.prr", "MBench_S1002_v3.prw"],
                 "wheelflat": ["r300_wide.prr", "S1002_flat.slcw", "S1002_flat"]}
EXAMPLES = HERE.parent.parent / "shared" / "reference" / "contact-examples"

KIND_DIGIT_T = {"normal": 0, "shift": 1, "steady": 3, "steady_forces": 3}
KIND_LABEL = {
    "normal": "normal (T=0)",
    "shift": "shift (T=1)",
    "steady": "steady rolling (T=3)",
    "steady_forces": "steady rolling, forces (T=3, F=2)",
    "example": "CONTACT example",
}


def profile_scale1(y):
    """bench::profile_scale1, operation for operation (the same doubles)."""
    if y < 0.0:
        return y * y / 1400.0 - 2.0e-5 * y * y * y
    return y * y / 2200.0 + 4.0e-5 * y * y * y


def geometry_lines(mx, my, scale):
    """IPOTCN=1 grid and the IBASE=2 block of bench::wheel_rail_patch (repr: exact doubles)."""
    dx = dy = 0.1
    nn = 2 * my + 1
    y1 = -0.5 * my * dy - 0.05
    dy1 = (my * dy + 0.1) / (nn - 1)
    lines = [
        "    1                                          IPOTCN",
        f"  {mx} {my} {-0.5 * mx * dx!r} {-0.5 * my * dy!r} {dx!r} {dy!r}   MX,MY,XL,YL,DX,DY",
        "    2    1                                     IBASE, IPLAN",
        f"  {nn} 0.0 460.0 {y1!r} {dy1!r}   NN,XM,RM,Y1,DY1",
    ]
    values = [repr(scale * scale * profile_scale1((y1 + k * dy1) / scale)) for k in range(nn)]
    for k in range(0, nn, 6):
        lines.append("  " + " ".join(values[k : k + 6]))
    return lines


def inp_text(kind, mx, my, scale, forces=None):
    """One module-3 case of the benchmark patch; `forces` = (FX/(mu FN), FY/(mu FN)) for F=2."""
    t = KIND_DIGIT_T[kind]
    f = 2 if kind == "steady_forces" else 0
    pen = 0.017 * scale * scale
    if f == 2:
        v2, v3 = forces
    else:
        v2, v3 = 0.0005, 0.0
    cphi = 0.0003 if t != 0 else 0.0
    lines = [
        f"% rollcontact whole-process benchmark: {KIND_LABEL[kind]}, {mx}x{my}, scale {scale:g}",
        "% written by bench/whole_process.py (the patch of bench/wheel_rail_patch.hpp)",
        " 3  MODULE",
        f"  00{t}0{f}0     P-B-T-N-F-S   PVTIME, BOUND , TANG  , NORM  , FORCE , STRESS",
        "  022020     L-D-C-M-Z-E   FRCLAW, DISCNS, INFLCF, MATER , RZNORM, EXRHS",
        "  0000201    H-G-I-A-O-W-R   HEAT, GAUSEI, IESTIM, MATFIL, OUTPUT, FLOW, RETURN",
        "  999  100  30  1  1e-5                       MAXGS, MAXIN, MAXNR, MAXOUT, EPS",
        f"  {pen!r} {v2!r} {v3!r} {cphi!r}   PEN, CKSI|FX, CETA|FY, CPHI",
        "  0.3  0.3                                    FSTAT, FKIN",
    ]
    if t == 3:
        lines.append("  0.0  0.1  10000.0                           CHI, DQ, VELOC")
    lines.append("  0.28  0.28  82000.0  82000.0               POISS 1,2, GG 1,2")
    lines += geometry_lines(mx, my, scale)
    lines += ["", " 0  MODULE", ""]
    return "\n".join(lines)


def cases_to_run(quick):
    """(kind, size index) pairs, the forces-prescribed ones after the runs they take forces from."""
    out = []
    for kind in ["normal", "shift", "steady", "steady_forces"]:
        n = 1 if quick else len(CONTACT_SECONDS[kind])
        out += [(kind, i) for i in range(n)]
    return out


TIMING_RE = re.compile(r"^timing: ([a-z-]+)\s+([0-9.]+) s$")


def parse_timing(stderr):
    """The `--timing` lines of stderr as {phase: seconds}; empty if the binary has no --timing."""
    phases = {}
    for line in stderr.splitlines():
        m = TIMING_RE.match(line.strip())
        if m:
            phases[m.group(1)] = float(m.group(2))
    return phases


def run_once(exe, path, timing, flags=()):
    """One whole process: its wall time from spawning to its exit, as a shell or /usr/bin/time
    sees it (Popen and wait4; /usr/bin/time's %e has 10 ms steps and its own start-up adds about
    a millisecond), its peak resident set (wait4's ru_maxrss) and the `--timing` split."""
    cmd = [exe, "run", str(path), "-q", *flags]
    if timing:
        cmd.append("--timing")
    # FFTW's plans are kept in a cache folder of the run's own (empty at the start): each input's
    # first run plans afresh, the later ones read the plans back (rollcontact/fft_plan_cache.hpp).
    env = dict(os.environ, ROLLCONTACT_CACHE_DIR=str(path.parent / "plan-cache"))
    with tempfile.TemporaryFile() as err:
        start = time.perf_counter()
        p = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=err, env=env)
        _, status, usage = os.wait4(p.pid, 0)
        wall = time.perf_counter() - start
        p.returncode = os.waitstatus_to_exitcode(status)
        err.seek(0)
        stderr = err.read().decode()
    # Status 1: some case not solved (tractcurv's cases 91-120 are not supported yet); the others
    # are timed all the same.
    if p.returncode not in (0, 1):
        raise RuntimeError(f"{path.name}: exit {p.returncode}\n{stderr}")
    return wall, usage.ru_maxrss / 1024.0, parse_timing(stderr)


def first_case(json_path):
    doc = json.loads(json_path.read_text())
    return doc["cases"][0]


def summarise(runs):
    """Median wall time and split, fastest run and largest peak RSS of (wall, peak, split) runs."""
    walls = [w for w, _, _ in runs]
    splits = [sp for _, _, sp in runs]
    phases = sorted({k for sp in splits for k in sp})
    split = {k: statistics.median([sp.get(k, 0.0) for sp in splits]) for k in phases}
    return {"wall": statistics.median(walls), "fastest": min(walls), "first": walls[0],
            "walls": walls,
            "peak_mb": max(p for _, p, _ in runs), "split": split}


def measure(exes, path, repeat, timing, flags=()):
    """Runs each binary `repeat` times on `path`, the binaries alternating run by run (so that a
    load that drifts during the measurement affects them alike); one summary per binary."""
    runs = [[] for _ in exes]
    for _ in range(repeat):
        for k, exe in enumerate(exes):
            runs[k].append(run_once(exe, path, timing, flags))
    return [summarise(r) for r in runs]


def case_facts(json_path):
    c = first_case(json_path)
    tot, st = c.get("totals", {}), c.get("statistics", {})
    return {"fn": tot.get("fn"), "fx": tot.get("fx"), "fy": tot.get("fy"), "ncon": st.get("ncon")}


def run_all(args, work):
    """Measurements of --exe and, when given, --exe-before (interleaved): two result lists."""
    exes = [args.exe] + ([args.exe_before] if args.exe_before else [])
    results = [[] for _ in exes]
    forces_of = {}
    for kind, i in cases_to_run(args.quick):
        mx, my, scale = SIZES[i]
        name = f"{kind}_{mx}x{my}.inp"
        path = work / name
        forces = forces_of.get(i) if kind == "steady_forces" else None
        path.write_text(inp_text(kind, mx, my, scale, forces))
        repeat = 1 if args.quick else args.repeat
        summaries = measure(exes, path, repeat, not args.no_timing)
        facts = case_facts(path.with_suffix(".json"))
        if kind == "steady":
            forces_of[i] = (facts["fx"] / (0.3 * facts["fn"]), facts["fy"] / (0.3 * facts["fn"]))
        for k, r in enumerate(summaries):
            r.update({"kind": kind, "size": i, "grid": f"{mx}x{my}", "input": name, **facts})
            results[k].append(r)
        r = summaries[0]
        print(f"{name}: {r['wall']:.3f} s, {r['peak_mb']:.0f} MB, ncon {facts['ncon']}, "
              f"split {r['split']}", file=sys.stderr)
    if not args.quick and EXAMPLES.is_dir():
        for name in EXAMPLE_CONTACT_SECONDS:
            path = work / f"{name}.inp"
            shutil.copy(EXAMPLES / path.name, path)
            for extra in EXAMPLE_FILES.get(name, []):
                source, target = EXAMPLES / extra, work / extra
                if source.is_dir() and not target.exists():
                    shutil.copytree(source, target)
                elif source.is_file():
                    shutil.copy(source, target)
            summaries = measure(exes, path, args.repeat, not args.no_timing,
                                EXAMPLE_FLAGS.get(name, []))
            cases = len(json.loads(path.with_suffix(".json").read_text())["cases"])
            for k, r in enumerate(summaries):
                r.update({"kind": "example", "size": name, "grid": f"{cases} cases",
                          "input": path.name, "ncon": "–"})
                results[k].append(r)
            print(f"{name}: {summaries[0]['wall']:.3f} s, split {summaries[0]['split']}",
                  file=sys.stderr)
    return results


def fmt_split(split):
    if not split:
        return "–"
    keys = ["set-up", "solve", "output"]
    return " / ".join(f"{split.get(k, 0.0):.3f}" for k in keys)


def example_row(r, b, before):
    """A row of one of CONTACT's example inputs (its CONTACT time may be unknown)."""
    contact = EXAMPLE_CONTACT_SECONDS[r["size"]]
    c_text = f"{contact:g}" if contact else "< 0.05"
    ratio = f"{contact / r['wall']:.1f}×" if contact else "–"
    row = (f"| `{r['input']}` | {r['grid']} | – | {c_text} | {r['wall']:.3f} | {ratio} | "
           f"{r['fastest']:.3f} | {r.get('first', r['wall']):.3f} | {r['peak_mb']:.0f} | "
           f"{fmt_split(r['split'])} |")
    if before:
        if b:
            b_ratio = f"{contact / b['wall']:.1f}×" if contact else "–"
            row += f" {b['wall']:.3f} | {fmt_split(b['split'])} | {b_ratio} |"
        else:
            row += " – | – | – |"
    return row


def markdown(results, before, args):
    key = lambda r: (r["kind"], r["size"])
    old = {key(r): r for r in before}
    head = "| input | grid | in contact | CONTACT (s) | rollcontact (s) | speed-up | fastest run (s) |"
    head += " first run (s) | peak RSS (MB) | set-up / solve / output (s) |"
    sep = "|---|---|---:|---:|---:|---:|---:|---:|---:|---|"
    if before:
        head += " before (s) | before: set-up / solve / output (s) | before: speed-up |"
        sep += "---:|---|---:|"
    lines = [head, sep]
    for r in results:
        if r["kind"] == "example":
            lines.append(example_row(r, old.get(key(r)), before))
            continue
        contact = CONTACT_SECONDS[r["kind"]][r["size"]]
        peak = f"{r['peak_mb']:.0f}"
        if key(r) in CONTACT_PEAK_MB:
            peak += f" (CONTACT {CONTACT_PEAK_MB[key(r)]:.0f})"
        fastest = r.get("fastest", r["wall"])
        row = (f"| {KIND_LABEL[r['kind']]} | {r['grid']} | {r['ncon']} | {contact:g} | "
               f"{r['wall']:.3f} | {contact / r['wall']:.1f}× | {fastest:.3f} | "
               f"{r.get('first', r['wall']):.3f} | {peak} | {fmt_split(r['split'])} |")
        if before:
            b = old.get(key(r))
            if b:
                row += f" {b['wall']:.3f} | {fmt_split(b['split'])} | {contact / b['wall']:.1f}× |"
            else:
                row += " – | – | – |"
        lines.append(row)
    reps = 1 if args.quick else args.repeat
    lines += [
        "",
        f"Wall time: median of {reps} whole processes `rollcontact run FILE -q --timing`, from "
        "spawning to exit (Python's Popen and wait4, as a shell or `/usr/bin/time` sees it); "
        "fastest run: the quickest of them; first "
        "run: the first of them, which plans its FFTs afresh (the others read the plans back from "
        "the run's FFTW plan cache); peak RSS: the largest (wait4's ru_maxrss)."
        + (" Before: the earlier binary, run alternately with this one." if args.exe_before else "")
        + " Set-up (reading, geometry, influence kernels, operators, FFT plans, preconditioners), "
        "solve and output (report, JSON): medians of `--timing`; process start-up and exit count "
        "in the wall time only. CONTACT: gfortran -O2, one thread, this machine class (issue 16).",
    ]
    return "\n".join(lines) + "\n"


BEGIN = "<!-- bench/whole_process.py: begin (generated, do not edit) -->"
END = "<!-- bench/whole_process.py: end -->"


def replace_block(doc, table):
    """Puts the table between the BEGIN and END markers of `doc` (appended when missing)."""
    text = doc.read_text()
    block = f"{BEGIN}\n{table}{END}"
    if BEGIN in text and END in text:
        head, rest = text.split(BEGIN, 1)
        tail = rest.split(END, 1)[1]
        text = head + block + tail
    else:
        text = text.rstrip("\n") + "\n\n" + block + "\n"
    doc.write_text(text)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--exe", default=str(HERE.parent / "build/release/bin/rollcontact"))
    ap.add_argument("--out", required=True, help="Markdown table to write")
    ap.add_argument("--json", help="also write the raw measurements here (for --before)")
    ap.add_argument("--before", help="raw measurements of an earlier run (its --json)")
    ap.add_argument("--exe-before", help="an earlier binary, run alternately with --exe")
    ap.add_argument("--json-before", help="write the --exe-before measurements here")
    ap.add_argument("--repeat", type=int, default=5, help="runs per input (median)")
    ap.add_argument("--quick", action="store_true", help="smallest size of each kind, one run")
    ap.add_argument("--no-timing", action="store_true", help="binary without --timing")
    ap.add_argument("--doc", help="also put the table between the markers of this Markdown file")
    ap.add_argument("--work", help="folder for the .inp files and outputs (default: temporary)")
    args = ap.parse_args()
    with tempfile.TemporaryDirectory(prefix="rollcontact-whole-") as tmp:
        work = Path(args.work) if args.work else Path(tmp)
        work.mkdir(parents=True, exist_ok=True)
        measured = run_all(args, work)
    results = measured[0]
    if args.exe_before:
        before = measured[1]
    else:
        before = json.loads(Path(args.before).read_text()) if args.before else []
    table = markdown(results, before, args)
    Path(args.out).write_text(table)
    if args.doc:
        replace_block(Path(args.doc), table)
    if args.json:
        Path(args.json).write_text(json.dumps(results, indent=1) + "\n")
    if args.json_before and before:
        Path(args.json_before).write_text(json.dumps(before, indent=1) + "\n")


if __name__ == "__main__":
    main()
