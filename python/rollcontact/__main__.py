"""python3 -m rollcontact run CASE [-o DIR] | plot CASE --what ... -o FIG.png"""

import argparse
import json
import pathlib
import sys
import tempfile

import rollcontact as rc


def _summary(case):
    head = f"case {case['case']}"
    if not case["solved"]:
        return f"{head}: {case['error'] or 'skipped'}"
    if case["module"] == 1:
        f = case["force_tr"]
        return (f"{head}: {len(case['patches'])} patch(es), FX {f[0]:.6g} FY {f[1]:.6g} "
                f"FZ {f[2]:.6g} N (track)")
    return (f"{head}: FN {case['fn']:.6g} FX {case['fx']:.6g} FY {case['fy']:.6g} N, "
            f"pen {case['pen']:.6g} mm, pmax {case['pmax']:.6g} N/mm2")


def _pick(cases, number, patch):
    case = next((c for c in cases if c["case"] == number), None)
    if case is None or not case["solved"]:
        raise SystemExit(f"case {number} was not solved")
    if case["module"] == 1:
        if not case["patches"]:
            raise SystemExit(f"case {number} has no contact patch")
        return case["patches"][patch - 1]
    return case


def _input_of(path):
    """The input file of a run's .json (its "input", as given to the run), else path."""
    path = pathlib.Path(path)
    if path.suffix != ".json":
        return path
    given = pathlib.Path(json.loads(path.read_text())["input"])
    for candidate in (given, path.parent / given, path.parent / given.name):
        if candidate.exists():
            return candidate
    raise SystemExit(f"{path}: its input file {given} was not found")


def main(argv=None):
    parser = argparse.ArgumentParser(prog="python3 -m rollcontact")
    sub = parser.add_subparsers(dest="command", required=True)
    run = sub.add_parser("run", help="solve every case of a .inp or TOML file (like the CLI)")
    run.add_argument("file")
    run.add_argument("-o", "--output-dir", default=None)
    plot = sub.add_parser("plot", help="solve a file and plot one of its results")
    plot.add_argument("file", help=".inp, .toml, the .json a run wrote, or the .csv of "
                                   "`rollcontact dynamic` (with --what dynamic)")
    plot.add_argument("--what", required=True,
                      choices=["pressure", "traction", "slip", "creep-curve", "profiles",
                               "dynamic"])
    plot.add_argument("--case", type=int, default=1)
    plot.add_argument("--patch", type=int, default=1, help="wheel/rail patch (module 1)")
    plot.add_argument("-o", "--output", required=True, help="image file (.png, .pdf, .svg)")
    args = parser.parse_args(argv)

    try:
        if args.command == "run":
            cases = rc.run(args.file, args.output_dir)
            for c in cases:
                print(_summary(c))
            failed = sum(1 for c in cases if not c["solved"] and not c["skipped"])
            return 1 if failed else 0
        if args.what == "dynamic":
            path = pathlib.Path(args.file)
            first = path.read_text().splitlines()[0]
            load = None
            if "static load" in first:
                load = float(first.split("static load")[1].split("N")[0])
            ax = rc.plot.dynamic(rc.plot.read_dynamic(path), static_load_N=load,
                                 title=f"{path.name}: dynamic rolling")
            ax.figure.savefig(args.output, dpi=150)
            print(args.output)
            return 0
        source = _input_of(args.file)
        with tempfile.TemporaryDirectory() as scratch:
            cases = rc.run(source, scratch)
        if args.what == "profiles":
            case = next((c for c in cases if c["case"] == args.case), None)
            if case is None or case.get("module") != 1 or not case["solved"]:
                raise SystemExit(f"case {args.case} is not a solved wheel/rail case")
            ax = rc.plot.wheelrail(case, title=f"{source.name}, case {args.case}: profiles")
        elif args.what == "creep-curve":
            solved = [c for c in cases if c["solved"] and c["module"] == 3]
            ax = rc.plot.creep_curve(solved, title=f"{source.name}: creep-force curve")
        else:
            result = _pick(cases, args.case, args.patch)
            patch = f", patch {args.patch}" if result is not None and "xi" in result else ""
            ax = rc.plot.field(result, args.what,
                               title=f"{source.name}, case {args.case}{patch}: {args.what}, "
                                     f"F$_n$ = {result['fn']:.4g} N")
        ax.figure.savefig(args.output, dpi=150)
        print(args.output)
        return 0
    except (rc.Error, rc.InputError) as e:
        print(f"rollcontact: error: {e}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
