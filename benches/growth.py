#!/usr/bin/env python3
"""Time and peak memory of `effectc check` (and `translate` for the longest shape) as a
program doubles in size four times, beside glslangValidator (`-l`) on the same files.

Each shape is generated here (nothing committed): statements in `main`, terms of one sum,
functions called in a chain, nested `if`s, uniform declarations. Each size runs `RUNS`
times; the median time and the largest peak RSS are kept. A step is the ratio of one size
to the half size before it: linear growth gives ~2 or less (start-up cost weighs on the
small sizes), quadratic 4. The script exits 1 when an effectc step is over 2.5x and
glslangValidator's own step on the same files is not (a growth of effectc's, not of the
reference compiler it runs in process).

    benches/growth.py [EFFECTC] [RUNS]     # EFFECTC defaults to target/release/effectc
"""
import os
import statistics
import subprocess
import sys
import tempfile

EFFECTC = sys.argv[1] if len(sys.argv) > 1 else "target/release/effectc"
RUNS = int(sys.argv[2]) if len(sys.argv) > 2 else 3
LIMIT = 2.5
HEAD = "#version 330\nuniform float u;\nout vec4 c;\n"


def statements(n):
    body = "".join(f"  x = x * 1.0001 + {i % 7}.5;\n" for i in range(n))
    return f"{HEAD}void main() {{\n  float x = u;\n{body}  c = vec4(x);\n}}\n"


def sum_terms(n):
    terms = " + ".join(f"u * {i % 9}.0" for i in range(n))
    return f"{HEAD}void main() {{ float x = {terms}; c = vec4(x); }}\n"


def functions(n):
    defs = "".join(f"float f{i}(float x) {{ return x * 1.5 + {i}.0; }}\n" for i in range(n))
    calls = "".join(f"  x = f{i}(x);\n" for i in range(n))
    return f"{HEAD}{defs}void main() {{\n  float x = u;\n{calls}  c = vec4(x);\n}}\n"


def nested_ifs(n):
    opened = "".join(f"if (x > {i}.0) {{\n" for i in range(n))
    return f"{HEAD}void main() {{ float x = u;\n{opened}x += 1.0;\n{'}' * n}\nc = vec4(x); }}\n"


def uniforms(n):
    decls = "".join(f"uniform vec4 v{i};\n" for i in range(n))
    reads = " + ".join(f"v{i}" for i in range(0, n, 8))
    return f"{HEAD}{decls}void main() {{ c = {reads}; }}\n"


SHAPES = [
    ("statements in main", statements, 4500),
    ("terms of one sum", sum_terms, 1250),
    ("functions", functions, 250),
    ("nested ifs", nested_ifs, 80),
    ("uniforms", uniforms, 500),
]


def measure(cmd):
    """Median seconds and largest peak RSS (MiB) of `cmd` over RUNS runs, and its exit code."""
    times, peaks, code = [], [], 0
    for _ in range(RUNS):
        r = subprocess.run(["/usr/bin/time", "-f", "%e %M", *cmd], capture_output=True, text=True)
        code = r.returncode
        last = r.stderr.strip().splitlines()[-1].split()
        times.append(float(last[0]))
        peaks.append(int(last[1]) / 1024)
    return statistics.median(times), max(peaks), code


def step(now, before):
    return now / before if before > 0 else float("nan")


def main():
    failed = []
    with tempfile.TemporaryDirectory() as tmp:
        print(f"effectc: {EFFECTC}; {RUNS} runs per size (median time, largest peak RSS)\n")
        print("| shape | size | effectc check | step | peak MiB | step | glslangValidator -l | step | exit |")
        print("|---|---|---|---|---|---|---|---|---|")
        for name, make, first in SHAPES:
            before = None
            for k in range(5):
                n = first << k
                path = os.path.join(tmp, f"{name.split()[0]}{n}.frag")
                with open(path, "w") as f:
                    f.write(make(n))
                t, m, code = measure([EFFECTC, "check", path])
                g, _, _ = measure(["glslangValidator", "-l", path])
                if before:
                    ts, ms, gs = step(t, before[0]), step(m, before[1]), step(g, before[2])
                    steps = f"{ts:.2f}x | {m:.0f} | {ms:.2f}x | {g:.3f} s | {gs:.2f}x"
                    if (ts > LIMIT and gs <= LIMIT) or ms > LIMIT:
                        failed.append(f"{name} {n}: time {ts:.2f}x (glslang {gs:.2f}x), memory {ms:.2f}x")
                else:
                    steps = f"— | {m:.0f} | — | {g:.3f} s | —"
                print(f"| {name} | {n} | {t:.3f} s | {steps} | {code} |", flush=True)
                before = (t, m, g)
        # Translation of the longest shape: WGSL and SPIR-V written from the same IR.
        before = None
        for k in range(5):
            n = 4500 << k
            path = os.path.join(tmp, f"t{n}.frag")
            with open(path, "w") as f:
                f.write(statements(n))
            out = os.path.join(tmp, "out")
            t, m, code = measure([EFFECTC, "translate", "--to", "wgsl,spv", "--out", out, path])
            if before:
                ts, ms = step(t, before[0]), step(m, before[1])
                if ts > LIMIT or ms > LIMIT:
                    failed.append(f"translate {n}: time {ts:.2f}x, memory {ms:.2f}x")
                print(f"| translate --to wgsl,spv | {n} | {t:.3f} s | {ts:.2f}x | {m:.0f} | {ms:.2f}x | | | {code} |", flush=True)
            else:
                print(f"| translate --to wgsl,spv | {n} | {t:.3f} s | — | {m:.0f} | — | | | {code} |", flush=True)
            before = (t, m)
    if failed:
        print("\nsteps over 2.5x that are effectc's own:\n  " + "\n  ".join(failed))
        return 1
    print("\nevery step of effectc's within 2.5x (or the reference compiler's own)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
