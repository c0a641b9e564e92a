#!/usr/bin/python3
"""Random wheel/rail cases around the Manchester benchmark (S1002 on UIC60), run one process
each: a robustness campaign for what no sweep visits.

Each case draws the wheel (left or right), lateral position (-15..16 mm), yaw (+-80 mrad),
roll, cant, vertical load (10 N..300 kN, log-uniform) or wheelset height, DX = DS (0.1..3 mm),
friction, speed (also backwards, fast and nearly standing), the separation/combination
distances, the pressures and tangential model (exact, KPEC, ANALYN; exact or Fastsim), the
contact approach (planar D=2, conformal D=4, brute-force D=5), a massless rail (F=3, rail
stiffnesses 1e3..1e7 N/mm and preloads) or none, a track or a roller rig (C1 = 4, 5: roller
radius 300, 600, 1e5 mm or an internal ring of 1500 mm), and one friction coefficient or 1, 2
or 4 varying with the rail's inclination (V=1) or along the track (V=2). A case is a *problem* when the process

  * crashes, hangs (timeout) or reports an internal error,
  * writes no JSON, or
  * reports "converged" with a non-finite value, with FZ more than 1 % off a prescribed
    vertical load, or with exit status 1 — or exits 0 with a case that is not converged.

Errors and non-converged cases with their messages are legitimate answers (a patch smaller
than an element whose force jumps over the target, say) and are listed, not counted.

With --wheel-flat it draws cases of CONTACT's wheel-flat example instead (the Chalmers flat's
258 slices on a 300 mm crowned rail, run with --unvalidated): lateral position -6..10 mm, yaw
+-20 mrad, the wheel turned anywhere (-180..180 degrees), 1..300 kN or the height, DX 0.4 or 1 mm.

With --viscoelastic every case has viscoelastic bodies (M = 1, exact theory, B = 0): creep
ratios FG 0..2 per body and relaxation times giving relaxation lengths TC·|VS| of 0.01..20 mm
(the same for both bodies or not), always rolling forwards (backwards, χ = π, is refused: M=1
relaxes along +x only).

With --inclination every case has Blanco's correction of the influence coefficients (C3 = 4,
IF_METH 0, VARIANT 1..4, MAXOUT 1 or 5), on conformal patches (D=4) three times in four.

With --sequences K it runs K random walks of --length cases each as one sequence (the lateral
position wandering with jumps, yaw drifting, the load changing now and then, I = 0 or 1 at
random) and every case of them again alone: steady rolling has no memory, so a case's answer
must not depend on the cases before it (the warm starts, the approach extrapolated from the
previous cases, the operators kept). A problem is then also a case whose status differs or
whose forces differ by more than 1e-4*FZ or z_ws by more than 2e-5 mm (ten times what the
iterations' tolerance EPS = 1e-5 leaves); for KPEC, whose F_z(z) jumps as rows enter its
ellipse, 1e-2*FZ (its jump rule) and 2e-3 mm (the validation's Z_WS). The inputs are written
with the same digits in both runs (y with 4 against 5 decimals once looked like a 1e-3*FZ
dependence on the sequence on a flange).

With --round-trip every input (each single case, each sequence) is also converted to a TOML
case file and back to .inp (`rollcontact convert` both ways) and solved again: any difference
from the original's results, bit for bit, is a problem (the converters drop or bend a value).

    /usr/bin/python3 scripts/wheelrail_random_cases.py --exe build/release/bin/rollcontact \\
        --cases 300 --seed 1 --out /tmp/random_cases
    /usr/bin/python3 scripts/wheelrail_random_cases.py --exe build/release/bin/rollcontact \\
        --sequences 10 --length 30 --seed 1 --out /tmp/random_sequences

Exit status 0 without problems, 1 otherwise.
"""

import argparse
import json
import math
import random
import re
import shutil
import subprocess
import sys
from pathlib import Path

EXAMPLES = Path(__file__).resolve().parent.parent.parent / "shared" / "reference" / "contact-examples"
PROFILES = ["MBench_UIC60_v3.prr", "MBench_S1002_v3.prw"]


def draw(rng):
    """One case's parameters."""
    p = dict(B=rng.choice([0, 0, 0, 5, 6]), N=rng.choice([1, 1, 0]), D=rng.choice([2, 2, 4, 5]),
             C=rng.choice([0, 1, 0, 1, 4, 5]), F=rng.choice([0, 0, 3]),
             nomradr=rng.choice([300.0, 600.0, 1e5, -1500.0]), V=rng.choice([0, 0, 0, 1, 2]),
             nvf=rng.choice([1, 2, 4]), s_ws=rng.uniform(-50.0, 150.0),
             krail=[rng.choice([1e3, 1e5, 1e7]), rng.uniform(-2e4, 2e4),
                    rng.choice([1e3, 1e5, 1e7]), rng.uniform(-1e5, 0.0)],
             dx=rng.choice([0.1, 0.15, 0.3, 0.5, 1.0, 2.0, 3.0]), mu=rng.uniform(0.05, 0.6),
             asep=rng.choice(["90d", "1.0", "0.2"]), dsep=rng.choice([8.0, 2.0, 20.0]),
             dcomb=rng.choice([4.0, 1.0, 10.0]), cant=rng.choice([0.0, rng.uniform(-0.05, 0.1)]),
             y=rng.uniform(-15, 16), roll=rng.uniform(-0.01, 0.01), yaw=rng.uniform(-0.08, 0.08),
             vs=rng.choice([2000.0, 2000.0, -2000.0, 30000.0, 1.0]))
    p["dcomb"] = min(p["dcomb"], p["dsep"])  # the input requires D_SEP >= D_COMB
    p["M"] = 3 if p["B"] in (5, 6) else rng.choice([0, 0, 3])
    # N=1: the vertical load [N]; N=0: the wheelset height [mm] (negative: lifted).
    p["fz"] = (math.exp(rng.uniform(math.log(10.0), math.log(3e5))) if p["N"] == 1
               else rng.uniform(-0.3, 2.0))
    p["vpitch"] = -p["vs"] / 460.0 * (1 + rng.uniform(-0.01, 0.01))
    if p["C"] >= 4:  # a roller rig: no cant; its angular velocity replaces VS (positive forward)
        p["cant"] = 0.0
        p["rpitch"] = p["vs"] / p["nomradr"]
        if p["F"] == 3:
            p["F"] = 0
    return p


def viscoelastic(rng, p):
    """Makes a drawn case viscoelastic: M = 1 with the exact theory, FG1 FG2 TC1 TC2."""
    p.update(B=0, M=1)
    if p["vs"] < 0.0:  # backwards rolling is CONTACT's error for M=1 (CHI = 0 only): forwards
        p.update(vs=-p["vs"], vpitch=-p["vpitch"])
        if p["C"] >= 4:
            p["rpitch"] = p["vs"] / p["nomradr"]
    fg = [rng.uniform(0.0, 2.0), rng.uniform(0.0, 2.0)]
    ell = [math.exp(rng.uniform(math.log(0.01), math.log(20.0))) for _ in range(2)]
    if rng.random() < 0.5:
        fg[1], ell[1] = fg[0], ell[0]
    p["visc"] = fg + [e / abs(p["vs"]) for e in ell]
    return p


def inclination(rng, p):
    """Makes a drawn case use Blanco's correction (C3 = 4): a variant, the coupling passes, and
    conformal patches (D=4) most of the time, where the rows' inclinations make it act."""
    p.update(C3=4, variant=rng.choice([1, 2, 3, 4]), maxout=rng.choice([1, 5]))
    if p["D"] != 5 and rng.random() < 0.75:
        p["D"] = 4
    if p["M"] == 1:  # C=4 with viscoelastic bodies is refused
        p["M"] = 0
    return p


def wheel_flat_case(rng):
    """A case of CONTACT's wheel-flat example (`wheelflat.inp`'s first case, varied)."""
    head = (EXAMPLES / "wheelflat.inp").read_text().split("\n")[6:19]
    n_digit = rng.choice([1, 1, 0])
    p = dict(N=n_digit, fz=math.exp(rng.uniform(math.log(1e3), math.log(3e5))))
    if n_digit == 0:
        p["fz"] = rng.uniform(-0.5, 2.0)  # the height [mm]
    dx = rng.choice([0.4, 1.0])
    head[1] = f" 1203{n_digit}00    C-P-B-T-N-F-S"
    head[7] = f"  {dx}   {dx}   1.000   90d   8.0   4.0"
    head += [f"  0.0  {rng.uniform(-6.0, 10.0):.6f}  {p['fz']:.6g} 0.000  "
             f"{rng.uniform(-0.02, 0.02):.6f}   {rng.uniform(-180.0, 180.0):.4f}d",
             " 2000. 0.0  0.0    0.0    0.0    -4.08190679"]
    return p, "\n".join(head) + "\n"


def case_text(p):
    """The case as a CONTACT .inp (module 1, first case of its run)."""
    lines = [" 1 MODULE",
             f" {p['C']}2{p['B']}3{p['N']}{p['F']}0    C-P-B-T-N-F-S",
             f" {p['V']}0{p['D']}{p.get('C3', 2)}{p['M']}33    V-L-D-C-M-Z-E",
             " 0000321    H-G-I-A-O-W-R",
             f"    999     100    30    {p.get('maxout', 1)}     1e-5"
             "         MAXGS, MAXIN, MAXNR, MAXOUT, EPS"]
    if p["V"] == 0:
        lines.append(f"  {p['mu']:.3f}   {p['mu']:.3f}                               FSTAT, FKIN")
    else:
        # V=1: friction by the rail's surface inclination [deg]; V=2: along the track [mm].
        lines.append(f"  {p['nvf']}                                   NVF")
        for k in range(p["nvf"]):
            at = (f"{-40.0 + 60.0 * k / max(p['nvf'] - 1, 1):.1f}d" if p["V"] == 1
                  else f"{-20.0 + 100.0 * k:.1f}")
            mu = p["mu"] * (0.5 + 0.5 * k / max(p["nvf"] - 1, 1))
            lines.append(f"  {at}   {mu:.3f}   {mu:.3f}            ALPHA|SVF, FSTAT, FKIN")
    if p.get("C3") == 4:
        lines.append(f"  0  {p['variant']}                                 IF_METH, VARIANT")
    lines.append("  0.280   0.280   82000.  82000.             POISS 1,2, GG 1,2")
    if p["M"] == 3:
        lines.append("  1.000   1.000   1.000                      K0_MF, ALFAMF, BETAMF")
    if p["M"] == 1:
        lines.append("  {:.6g}  {:.6g}  {:.6g}  {:.6g}         FG1, FG2, TC1, TC2".format(*p["visc"]))
    lines += [f"  {p['dx']}   {p['dx']}   1.000   {p['asep']}   {p['dsep']}   {p['dcomb']}",
              f"   14.0     0    1435.0   {p['nomradr'] if p['C'] >= 4 else p['cant']:.5f}",
              f"  '{PROFILES[0]}'   0     1.0   0.0",
              "     0.0    0.0   0.000   0.0   0.0   0.000"]
    if p["F"] == 3:
        lines.append("  {:.6g}  {:.6g}  {:.6g}  {:.6g}      KYRAIL, FYRAIL, KZRAIL, FZRAIL"
                     .format(*p["krail"]))
    lines += ["  1360.0  -70.0   460.0",
              f"  '{PROFILES[1]}'   0     1.0   0.0",
              f"  {p['s_ws']:.3f}  {p['y']:.6f}  {p['fz']:.6g} {p['roll']:.6f} {p['yaw']:.6f}  0.0",
              f" {p['rpitch'] if p['C'] >= 4 else p['vs']:.8g} 0.0    0.0   0.0        0.0  "
              f"{p['vpitch']:.8f}"]
    return "\n".join(lines) + "\n"


def judge(p, returncode, stderr, json_path):
    """(status, problem or None) of one finished run."""
    if returncode not in (0, 1):
        return None, f"exit {returncode}: {stderr.strip()[-300:]}"
    if "internal" in stderr.lower():
        return None, "internal error: " + stderr.strip()[-300:]
    if not json_path.exists():
        return None, "no JSON written"
    c = json.loads(json_path.read_text())["cases"][0]
    status = c["status"]
    if status == "converged":
        values = list(c["force_tr"]) + [c["z_ws"]]
        for patch in c["patches"]:
            values += [patch[k] for k in ("fn", "fx", "fs", "mn", "pen", "pmax")]
        if not all(math.isfinite(v) for v in values):
            return status, "converged with a non-finite value"
        if p["N"] == 1 and abs(c["force_tr"][2] - p["fz"]) > 0.01 * p["fz"]:
            return status, f"converged with FZ {c['force_tr'][2]:.6g} N for {p['fz']:.6g} N"
        if returncode != 0:
            return status, "converged but exit status 1"
    elif returncode == 0:
        return status, f"status {status} with exit status 0"
    return status, None


def results_without_input(path):
    """The cases of a JSON output without the parts that echo the input (digits, source) and
    without the input's file and line in front of a message."""
    drop = ("input", "digits", "source", "control")
    cases = []
    for c in json.loads(path.read_text())["cases"]:
        c = {k: v for k, v in c.items() if k not in drop}
        if isinstance(c.get("message"), str):
            c["message"] = re.sub(r"^\S+\.inp:\d+: ", "", c["message"])
        cases.append(c)
    return cases


def round_trip(args, inp, extra):
    """None when `inp` converted to TOML and back to .inp solves to the same results bit for bit
    (`rollcontact convert` both ways), else the problem."""
    back = args.out / "round_trip"
    back.mkdir(exist_ok=True)
    toml, again = back / (inp.stem + ".toml"), back / (inp.stem + ".inp")
    for source, target in ((inp, toml), (toml, again)):
        conv = subprocess.run([args.exe, "convert", "-q", str(source), str(target)],
                              capture_output=True, text=True, timeout=args.timeout)
        if conv.returncode != 0:
            return f"convert {source.name} -> {target.name}: {conv.stderr.strip()[-300:]}"
    subprocess.run([args.exe, "run", str(again), "-o", str(back), "-q"] + extra,
                   capture_output=True, text=True, timeout=args.timeout * 10)
    a = results_without_input(args.out / "out" / (inp.stem + ".json"))
    b = results_without_input(back / (inp.stem + ".json"))
    differ = [k + 1 for k, (x, y) in enumerate(zip(a, b)) if x != y]
    if len(a) != len(b) or differ:
        return f"converted .inp -> TOML -> .inp: cases {differ or 'count'} solve differently"
    return None


def sequence_case_lines(p, first):
    """A case of a sequence: the whole first case, or only what changes (later cases keep the
    friction, discretisation, material and track: digits 1, and E = 2: the wheelset only)."""
    if first:
        return case_text(p).splitlines()
    return [" 1 MODULE",
            f" {p['C']}2{p['B']}3{p['N']}{p['F']}0",
            f" 0111{p['M']}02",
            f" 01{p['I']}0321",
            f"  0.0  {p['y']:.6f}  {p['fz']:.6g} {p['roll']:.6f} {p['yaw']:.6f}  0.0",
            f" {p['vs']:.1f} 0.0    0.0   0.0        0.0  {p['vpitch']:.8f}"]


def random_walk(rng, length):
    """One sequence's cases: exact or KPEC pressures, planar or conformal, the vertical force
    prescribed, the wheelset wandering."""
    base = draw(rng)
    base.update(N=1, F=0, B=rng.choice([0, 0, 5]), D=rng.choice([2, 2, 4]),
                dx=rng.choice([0.3, 0.5, 1.0]), vs=2000.0, vpitch=-2000.0 / 460.0, roll=0.0,
                cant=0.0, asep="90d", dsep=8.0, dcomb=4.0, V=0, C=rng.choice([0, 1]), s_ws=0.0)
    base["M"] = 3 if base["B"] == 5 else rng.choice([0, 0, 3])
    y, yaw, fz = rng.uniform(-3.0, 6.0), 0.0, 1.0e4
    cases = []
    for _ in range(length):
        y = rng.uniform(-8.0, 12.0) if rng.random() < 0.15 else y + rng.gauss(0.0, 0.3)
        yaw = max(-0.03, min(0.03, yaw + rng.gauss(0.0, 0.002)))
        if rng.random() < 0.1:
            fz = rng.uniform(2.0e3, 6.0e4)
        cases.append(dict(base, y=y, yaw=yaw, fz=fz, I=rng.choice([0, 1])))
    return cases


def run_sequences(args, rng):
    """Each walk as one sequence, then each of its cases alone; (counts, problems)."""
    counts, problems = {}, 0
    for w in range(args.sequences):
        cases = random_walk(rng, args.length)
        lines = []
        for k, p in enumerate(cases):
            lines += sequence_case_lines(p, k == 0)
        seq = args.out / f"sequence_{args.seed}_{w}.inp"
        seq.write_text("\n".join(lines + [" 0 MODULE"]) + "\n")
        run = subprocess.run([args.exe, "run", str(seq), "-o", str(args.out / "out"), "-q"],
                             capture_output=True, text=True, timeout=args.timeout * len(cases))
        if run.returncode not in (0, 1):
            problems += 1
            print(f"PROBLEM {seq.name}: exit {run.returncode}: {run.stderr.strip()[-300:]}")
            continue
        in_sequence = json.loads((args.out / "out" / (seq.stem + ".json")).read_text())["cases"]
        if args.round_trip and (problem := round_trip(args, seq, [])) is not None:
            problems += 1
            print(f"PROBLEM {seq.name}: {problem}")
        for k, p in enumerate(cases):
            alone = args.out / f"{seq.stem}_case{k + 1}.inp"
            alone.write_text("\n".join(sequence_case_lines(p, True) + [" 0 MODULE"]) + "\n")
            subprocess.run([args.exe, "run", str(alone), "-o", str(args.out / "out"), "-q"],
                           capture_output=True, text=True, timeout=args.timeout)
            a = in_sequence[k]
            b = json.loads((args.out / "out" / (alone.stem + ".json")).read_text())["cases"][0]
            counts[a["status"]] = counts.get(a["status"], 0) + 1
            where = f"{seq.name} case {k + 1}"
            if a["status"] != b["status"]:
                problems += 1
                print(f"PROBLEM {where}: {a['status']} in the sequence, {b['status']} alone")
            elif a["status"] == "converged":
                df = max(abs(a["force_tr"][i] - b["force_tr"][i]) for i in range(3))
                dz = abs(a["z_ws"] - b["z_ws"])
                # The iterations stop at EPS = 1e-5 (measured over 270 cases: forces within
                # 2.1e-5*FZ, z_ws within 1.9e-6 mm); KPEC's F_z(z) jumps as rows enter its
                # ellipse, and the nearer side of a jump stands within 1 % of FZ.
                exact = p["B"] == 0
                if df > (1e-4 if exact else 1e-2) * p["fz"] or dz > (2e-5 if exact else 2e-3):
                    problems += 1
                    print(f"PROBLEM {where}: forces differ by {df:.4g} N, z_ws by {dz:.3g} mm")
    return counts, problems


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--exe", required=True, help="the rollcontact program")
    ap.add_argument("--cases", type=int, default=300)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--out", type=Path, required=True, help="folder for the inputs and outputs")
    ap.add_argument("--timeout", type=float, default=120.0, help="per case [s]")
    ap.add_argument("--sequences", type=int, default=0,
                    help="run this many random walks as sequences instead (see above)")
    ap.add_argument("--length", type=int, default=30, help="cases per sequence")
    ap.add_argument("--wheel-flat", action="store_true",
                    help="cases of CONTACT's wheel-flat example (wheel slices) instead")
    ap.add_argument("--viscoelastic", action="store_true",
                    help="viscoelastic bodies (M=1) in every case")
    ap.add_argument("--inclination", action="store_true",
                    help="Blanco's correction of the coefficients (C3=4) in every case")
    ap.add_argument("--round-trip", action="store_true",
                    help="also convert each input .inp -> TOML -> .inp and require the same "
                         "results bit for bit (a difference is a problem)")
    args = ap.parse_args()
    args.out.mkdir(parents=True, exist_ok=True)
    for name in PROFILES + ["r300_wide.prr", "S1002_flat.slcw"]:
        shutil.copyfile(EXAMPLES / name, args.out / name)
    shutil.copytree(EXAMPLES / "S1002_flat", args.out / "S1002_flat", dirs_exist_ok=True)
    rng = random.Random(args.seed)
    if args.sequences > 0:
        counts, problems = run_sequences(args, rng)
        print(f"{args.sequences} sequences of {args.length} cases: {counts}; problems: {problems}")
        return 1 if problems else 0
    counts, problems = {}, 0
    for k in range(args.cases):
        if args.wheel_flat:
            p, text = wheel_flat_case(rng)
        else:
            p = draw(rng)
            if args.viscoelastic:
                p = viscoelastic(rng, p)
            if args.inclination:
                p = inclination(rng, p)
            text = case_text(p)
        inp = args.out / f"case_{args.seed}_{k}.inp"
        inp.write_text(text)
        command = [args.exe, "run", str(inp), "-o", str(args.out / "out"), "-q"]
        if args.wheel_flat:
            command.append("--unvalidated")  # wheel slices: solved with a warning
        try:
            run = subprocess.run(command, capture_output=True, text=True, timeout=args.timeout)
        except subprocess.TimeoutExpired:
            problems += 1
            print(f"PROBLEM {inp.name}: no answer within {args.timeout} s  {p}")
            continue
        status, problem = judge(p, run.returncode, run.stderr,
                                args.out / "out" / (inp.stem + ".json"))
        if status is not None:
            counts[status] = counts.get(status, 0) + 1
            if status != "converged" and problem is None:
                message = json.loads((args.out / "out" / (inp.stem + ".json")).read_text())
                print(f"  {inp.name} {status}: {message['cases'][0]['message'][:160]}")
        if problem is None and args.round_trip and status is not None:
            problem = round_trip(args, inp, command[6:])
        if problem is not None:
            problems += 1
            print(f"PROBLEM {inp.name}: {problem}  {p}")
    print(f"{args.cases} cases: {counts}; problems: {problems}")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
