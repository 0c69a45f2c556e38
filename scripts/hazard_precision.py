#!/usr/bin/env python3
"""Recompute the precision of effectc's numeric-hazard warnings (W0710-W0722)
on the labelled set in data/hazards/labels.tsv (see data/hazards/README.md).

For every program directory named in the labels file it runs

    $EFFECTC check --color never --format json [--target-env ...] CORPUS_ROOT/<corpus>/<program>

(`--target-env vulkan` for the `vulkan` corpus, `vulkan1.2` for `fresh-vk`),
collects the W07xx warnings reported now, and matches them to the labels by
(corpus, program, stage file name, line, code). Several warnings with the same
key (e.g. `cos(a), sin(a)` on one line) count as one site.

It runs with `--hazards possible` and reads each warning's tier from its note
(`certain: ...` or `possible: ...`): the default report is the certain tier
(what a bare `effectc check` prints), the possible tier is what
`--hazards possible` adds. A build without tiers (no `--hazards` flag) is run
plainly and all its warnings count as the default report.

For the default report, and for both tiers together, it prints:
  - reported sites, and how many of them are labelled true / false / noise /
    unsure / unlabelled;
  - precision = true / (true + false + noise) over labelled reported sites,
    and noise share = noise / (true + false + noise);
then:
  - labelled `true` sites reported in neither tier (each one is a regression),
    and those reported in the possible tier only;
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


def check_program(effectc, root, corpus, program, tiers):
    """Run check on one program dir; return (dict site key -> certain?, error text or None)."""
    cmd = [effectc, "check", "--color", "never", "--format", "json"]
    if tiers:
        cmd += ["--hazards", "possible"]
    if corpus in TARGET_ENV:
        cmd += ["--target-env", TARGET_ENV[corpus]]
    cmd.append(os.path.join(root, corpus, program))
    try:
        out = subprocess.run(cmd, capture_output=True, text=True, timeout=300).stdout
        diagnostics = json.loads(out)["diagnostics"]
    except (OSError, subprocess.TimeoutExpired, ValueError, KeyError) as e:
        return {}, f"{corpus}/{program}: {e}"
    sites = {}
    for d in diagnostics:
        if d["code"].startswith("W07") and d.get("file") and d.get("span"):
            name = os.path.basename(d["file"])
            key = (corpus, program, name, d["span"]["line"], d["code"])
            certain = not tiers or any(n.startswith("certain:") for n in d.get("notes", []))
            sites[key] = sites.get(key, False) or certain
    return sites, None


def knows_tiers(effectc):
    """Whether this build has `check --hazards`."""
    try:
        out = subprocess.run([effectc, "check", "--help"], capture_output=True, text=True, timeout=60).stdout
    except (OSError, subprocess.TimeoutExpired):
        return False
    return "--hazards" in out


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

    tiers = knows_tiers(effectc)
    found = {}
    errors = []
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        jobs = [pool.submit(check_program, effectc, args.corpus_root, c, p, tiers) for c, p in programs]
        for job in jobs:
            sites, err = job.result()
            found.update(sites)
            if err:
                errors.append(err)
    certain = {k for k, c in found.items() if c}
    either = set(found)

    def fmt(k):
        return f"{k[0]}/{k[1]}/{k[2]}:{k[3]} {k[4]}"

    def summary(title, reported):
        counts = {v: 0 for v in VERDICTS}
        counts["unlabelled"] = 0
        for key in reported:
            verdict = labels.get(key, ("unlabelled", ""))[0]
            counts[verdict if verdict in counts else "unlabelled"] += 1
        judged = counts["true"] + counts["false"] + counts["noise"]
        print(f"{title}: {len(reported)} sites")
        for v in VERDICTS + ("unlabelled",):
            print(f"  {v:<11} {counts[v]}")
        if judged:
            print(f"  precision: {counts['true']}/{judged} = {100.0 * counts['true'] / judged:.1f}%"
                  "  (true / (true+false+noise), labelled reported sites)")
            print(f"  noise share: {counts['noise']}/{judged} = {100.0 * counts['noise'] / judged:.1f}%")
        else:
            print("  precision: n/a (no labelled site reported)")

    print(f"effectc: {effectc}{'' if tiers else ' (no tiers: every warning is in the default report)'}")
    print(f"labels: {args.labels} ({len(labels)} sites in {len(programs)} programs)")
    summary("default report (certain tier)", certain)
    if tiers:
        summary("with --hazards possible (both tiers)", either)
    labelled_true = [k for k, (v, _) in labels.items() if v == "true"]
    lost = sorted(k for k in labelled_true if k not in either)
    possible_only = sorted(k for k in labelled_true if k in either and k not in certain)
    new = sorted(k for k in either if k not in labels)
    print(f"labelled true sites reported in neither tier: {len(lost)} of {len(labelled_true)}")
    for k in lost:
        print(f"  LOST {fmt(k)}  -- {labels[k][1]}")
    if tiers:
        print(f"labelled true sites in the possible tier only: {len(possible_only)} of {len(labelled_true)}")
        for k in possible_only:
            print(f"  POSSIBLE {fmt(k)}  -- {labels[k][1]}")
    print(f"unlabelled reported sites (to be judged): {len(new)}")
    for k in new:
        print(f"  NEW  {fmt(k)}{'' if k in certain else '  (possible)'}")
    for e in errors:
        print(f"error: {e}", file=sys.stderr)
    if args.list:
        print("sites:")
        for k in sorted(either):
            v, reason = labels.get(k, ("unlabelled", ""))
            tier = "certain " if k in certain else "possible"
            print(f"  {tier} {v:<10} {fmt(k)}  {reason}")
    return 0


if __name__ == "__main__":
    main()
    sys.exit(0)
