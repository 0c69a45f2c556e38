#!/usr/bin/env python3
"""Per set and source figures from the VERDICTS.tsv files corpus_verdicts.sh writes.

Usage: verdict_summary.py CORPUS_ROOT [SET...]   (default: every CORPUS_ROOT/*/VERDICTS.tsv)
Prints a Markdown table (set, source, programs, glslang ok, Mesa ok, both ok, Mesa na,
glslang-only, Mesa-only) and, per set, the disagreement messages grouped by a normalised
form (numbers and paths folded; quoted names too for per-name messages) with counts and one example program.
"""
import collections
import os
import re
import sys


def norm(msg):
    msg = re.sub(r"^fail: ", "", msg)
    msg = re.sub(r"ERROR: [^:]*:\d+: ", "ERROR: ", msg)
    msg = re.sub(r"^[\w.-]+\.(vert|frag|geom|tesc|tese|comp): ", "", msg)
    msg = re.sub(r"\d+:\d+\(\d+\): ", "", msg)
    if re.search(r"undeclared identifier|no matching overloaded|has no matching output|redeclar|must be a constant", msg):
        msg = re.sub(r"[`'][^`']*'", "'X'", msg)  # names vary, the rule does not
    msg = re.sub(r"\b\d+\b", "N", msg)
    return msg.strip()[:160]


def main():
    root = sys.argv[1]
    sets = sys.argv[2:] or sorted(d for d in os.listdir(root) if os.path.isfile(os.path.join(root, d, "VERDICTS.tsv")))
    print("| set | source | programs | glslang ok | Mesa ok | both ok | Mesa na | glslang only | Mesa only |")
    print("|---|---|---:|---:|---:|---:|---:|---:|---:|")
    classes = {}
    for s in sets:
        rows = collections.defaultdict(lambda: [0] * 7)
        cls = collections.defaultdict(list)
        for line in open(os.path.join(root, s, "VERDICTS.tsv"), encoding="utf-8", errors="replace"):
            name, g, m = (line.rstrip("\n").split("\t") + ["", ""])[:3]
            src = name.split("__")[0]
            r = rows[src]
            r[0] += 1
            r[1] += g == "ok"
            r[2] += m == "ok"
            r[3] += g == "ok" and m == "ok"
            r[4] += m == "na"
            if g == "ok" and m not in ("ok", "na"):
                r[5] += 1
                cls[("glslang only", norm(m))].append(name)
            elif m == "ok" and g != "ok":
                r[6] += 1
                cls[("Mesa only", norm(g))].append(name)
        tot = [0] * 7
        for src in sorted(rows):
            print(f"| {s} | {src} | " + " | ".join(str(x) for x in rows[src]) + " |")
            tot = [a + b for a, b in zip(tot, rows[src])]
        print(f"| **{s}** | **all** | " + " | ".join(f"**{x}**" for x in tot) + " |")
        classes[s] = cls
    for s in sets:
        if not classes[s]:
            continue
        print(f"\n### Disagreements in {s}\n")
        for (side, msg), names in sorted(classes[s].items(), key=lambda kv: -len(kv[1])):
            srcs = collections.Counter(n.split("__")[0] for n in names)
            print(f"- {len(names)} × {side}: `{msg}` — {', '.join(f'{k} {v}' for k, v in srcs.most_common())}; e.g. {names[0]}")


main()
