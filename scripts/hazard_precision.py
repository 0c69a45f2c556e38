#!/usr/bin/env python3
"""Recompute the precision of effectc's numeric-hazard warnings (W0710-W0722)
on the labelled set in data/hazards/labels.tsv (see data/hazards/README.md).

For every program directory named in the labels file it runs

    $EFFECTC check --color never --format json [--target-env ...] CORPUS_ROOT/<corpus>/<program>

(`--target-env vulkan` for the `vulkan` corpus, `vulkan1.2` for `fresh-vk`),
collects the W07xx warnings reported now, and matches them to the labels by
(corpus, program, stage file name, line, code). Several warnings with the same
key (e.g. `cos(a), sin(a)` on one line) count as one site.

It prints:
  - reported sites, and how many of them are labelled true / false / noise /
    unsure / unlabelled;
  - precision = true / (true + false + noise) over labelled reported sites,
    and noise share = noise / (true + false + noise);
  - labelled `true` sites no longer reported (each one is a regression);
  - unlabelled reported sites (new: they need judging and a label).

Usage:
  EFFECTC=target/release/effectc python3 scripts/hazard_precision.py \
      [--labels data/hazards/labels.tsv] [--corpus-root /work/corpus] [--jobs 2] [--list]

--list also prints every reported site with its verdict. The exit status is
always 0: this script measures, it does not gate.
"""

import argparse
import concurrent.futures
import csv
import json
import os
import subprocess
import sys

TARGET_ENV = {"vulkan": "vulkan", "fresh-vk": "vulkan1.2"}
VERDICTS = ("true", "false", "noise", "unsure")


def read_labels(path):
    labels = {}
    with open(path, newline="") as f:
        for row in csv.DictReader(f, delimiter="\t"):
            key = (row["corpus"], row["program"], row["file"], int(row["line"]), row["code"])
            labels[key] = (row["verdict"], row["reason"])
    return labels


def check_program(effectc, root, corpus, program):
    """Run check on one program dir; return (set of site keys, error text or None)."""
    cmd = [effectc, "check", "--color", "never", "--format", "json"]
    if corpus in TARGET_ENV:
        cmd += ["--target-env", TARGET_ENV[corpus]]
    cmd.append(os.path.join(root, corpus, program))
    try:
        out = subprocess.run(cmd, capture_output=True, text=True, timeout=300).stdout
        diagnostics = json.loads(out)["diagnostics"]
    except (OSError, subprocess.TimeoutExpired, ValueError, KeyError) as e:
        return set(), f"{corpus}/{program}: {e}"
    sites = set()
    for d in diagnostics:
        if d["code"].startswith("W07") and d.get("file") and d.get("span"):
            name = os.path.basename(d["file"])
            sites.add((corpus, program, name, d["span"]["line"], d["code"]))
    return sites, None


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--labels", default="data/hazards/labels.tsv")
    ap.add_argument("--corpus-root", default=os.environ.get("CORPUS_ROOT", "/work/corpus"))
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--list", action="store_true", help="print every reported site with its verdict")
    args = ap.parse_args()
    effectc = os.environ.get("EFFECTC", "target/release/effectc")

    labels = read_labels(args.labels)
    programs = sorted({(k[0], k[1]) for k in labels})

    reported = set()
    errors = []
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        jobs = [pool.submit(check_program, effectc, args.corpus_root, c, p) for c, p in programs]
        for job in jobs:
            sites, err = job.result()
            reported |= sites
            if err:
                errors.append(err)

    counts = {v: 0 for v in VERDICTS}
    counts["unlabelled"] = 0
    for key in reported:
        verdict = labels.get(key, ("unlabelled", ""))[0]
        counts[verdict if verdict in counts else "unlabelled"] += 1

    judged = counts["true"] + counts["false"] + counts["noise"]
    labelled_true = [k for k, (v, _) in labels.items() if v == "true"]
    lost = sorted(k for k in labelled_true if k not in reported)
    new = sorted(k for k in reported if k not in labels)

    def fmt(k):
        return f"{k[0]}/{k[1]}/{k[2]}:{k[3]} {k[4]}"

    print(f"effectc: {effectc}")
    print(f"labels: {args.labels} ({len(labels)} sites in {len(programs)} programs)")
    print(f"reported sites: {len(reported)}")
    for v in VERDICTS + ("unlabelled",):
        print(f"  {v:<11} {counts[v]}")
    if judged:
        print(f"precision: {counts['true']}/{judged} = {100.0 * counts['true'] / judged:.1f}%"
              "  (true / (true+false+noise), labelled reported sites)")
        print(f"noise share: {counts['noise']}/{judged} = {100.0 * counts['noise'] / judged:.1f}%")
    else:
        print("precision: n/a (no labelled site reported)")
    print(f"labelled true sites no longer reported: {len(lost)} of {len(labelled_true)}")
    for k in lost:
        print(f"  LOST {fmt(k)}  -- {labels[k][1]}")
    print(f"unlabelled reported sites (to be judged): {len(new)}")
    for k in new:
        print(f"  NEW  {fmt(k)}")
    for e in errors:
        print(f"error: {e}", file=sys.stderr)
    if args.list:
        print("sites:")
        for k in sorted(reported):
            v, reason = labels.get(k, ("unlabelled", ""))
            print(f"  {v:<10} {fmt(k)}  {reason}")
    return 0


if __name__ == "__main__":
    main()
    sys.exit(0)
