#!/usr/bin/env python3
"""Generates the whole-program rejection corpus tests/data/rejected/ from the repository's
examples (run from anywhere; rewrites the generated files, keeps hand-written ones).

Every file starts with a header line `% expect: LINE: FRAGMENT` (`#` for TOML): `rollcontact run`
must exit with status 2, name the file and LINE (0: no line, the file as a whole) with FRAGMENT
in the message, and write nothing (tests/unit/batch/test_cli_rejected_inputs.cpp)."""
import pathlib
import re

HERE = pathlib.Path(__file__).resolve().parent
EXAMPLES = HERE.parent.parent.parent / "examples"
REAL = re.compile(r"(?<![\w.])[-+]?\d+\.\d*(?:[eEdD][-+]?\d+)?(?![\w.])")


def write(name, header_char, line, fragment, body, bom=False):
    # Line numbers count the header line (the generator adds it before `body`).
    text = f"{header_char} expect: {line}: {fragment}\n" + body
    data = text.encode()
    if bom:
        data = b"\xef\xbb\xbf" + data
    (HERE / name).write_bytes(data)


def data_lines(lines):
    """Indices of lines with a real number before any comment (values, not control words)."""
    out = []
    for i, l in enumerate(lines):
        code = l.split("%")[0]
        if i >= 5 and REAL.search(code):
            out.append(i)
    return out


def inp_cases():
    bad_tokens = ["inf", "nan", "1e999", "-1.0D400", "1.0.0", "1e+", "0x10", "--1.0"]
    n = 0
    for inp in sorted(EXAMPLES.glob("*.inp")):
        lines = inp.read_text().splitlines(keepends=True)
        rows = data_lines(lines)
        # Not-a-number tokens, each on a different value line of the file.
        for k, tok in enumerate(bad_tokens):
            i = rows[k % len(rows)]
            code, sep, comment = lines[i].partition("%")
            m = list(REAL.finditer(code))[0]
            changed = code[: m.start()] + tok + code[m.end():] + sep + comment
            body = "".join(lines[:i] + [changed] + lines[i + 1:])
            write(f"gen_{inp.stem}_token{k}.inp", "%", i + 2, "expected", body)
            n += 1
        # Text past column 256 on a value line.
        i = rows[0]
        body = "".join(lines[:i] + [" " * 260 + lines[i]] + lines[i + 1:])
        write(f"gen_{inp.stem}_long_line.inp", "%", i + 2, "would be ignored", body)
        # A byte-order mark does not hide a real error on the same value line.
        code, sep, comment = lines[i].partition("%")
        m = list(REAL.finditer(code))[0]
        changed = code[: m.start()] + "x" + code[m.end():] + sep + comment
        body = "".join(lines[:i] + [changed] + lines[i + 1:])
        write(f"gen_{inp.stem}_bom.inp", "%", i + 2, "expected", body, bom=True)
        # An input named like its own outputs.
        write(f"gen_{inp.stem}.out", "%", 0, "would replace this input", "".join(lines))
        n += 3
    # Element sizes the influence coefficients cannot represent (rectangular grids, DX DY given).
    for stem in ["rectangle_quadratic", "shift", "two_rectangles", "profile"]:
        path = EXAMPLES / f"{stem}.inp"
        if not path.exists():
            continue
        lines = path.read_text().splitlines(keepends=True)
        for j, size in enumerate(["1e9", "1e30"]):
            out = []
            done = False
            grid_line = 0
            for i, l in enumerate(lines):
                if not done and "MX MY" in l and "DX DY" in l:
                    grid_line = i + 2  # 1-based, after the header line
                    code, sep, comment = l.partition("%")
                    words = code.split()
                    words[-1] = size  # DY
                    words[-2] = size  # DX
                    l = "  " + "  ".join(words) + "       " + sep + comment
                    done = True
                out.append(l)
            if done:
                # Reported at the grid line, as the reader reads it.
                write(f"gen_{stem}_element_size{j}.inp", "%", grid_line,
                      "outside [1e-8, 1e+08] mm", "".join(out))
                n += 1
    return n


def toml_cases():
    n = 0
    bad = ["inf", "-inf", "nan", "+inf", "-nan"]
    for toml in sorted((EXAMPLES / "toml").glob("*.toml")):
        lines = toml.read_text().splitlines(keepends=True)
        k = 0
        for i, l in enumerate(lines):
            code = l.split("#")[0]
            if "=" not in code or not REAL.search(code.split("=", 1)[1]):
                continue
            if k >= 6:
                break
            m = list(REAL.finditer(code))
            key_end = code.index("=")
            m = [x for x in m if x.start() > key_end][0]
            changed = l[: m.start()] + bad[k % len(bad)] + l[m.end():]
            body = "".join(lines[:i] + [changed] + lines[i + 1:])
            write(f"gen_{toml.stem}_nonfinite{k}.toml", "#", i + 2, "is not a finite number", body)
            k += 1
            n += 1
        write(f"gen_{toml.stem}.json", "#", 0, "would replace this input", "".join(lines))
        n += 1
    return n


if __name__ == "__main__":
    for old in HERE.glob("gen_*"):
        old.unlink()
    print(f"{inp_cases()} .inp-derived and {toml_cases()} TOML-derived files in {HERE}")
