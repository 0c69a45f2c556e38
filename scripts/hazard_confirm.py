#!/usr/bin/env python3
"""Compare `effectc stress --confirm` verdicts with the hand labels of the
numeric-hazard warnings (W0710-W0722) in data/hazards/labels.tsv (see
data/hazards/README.md).

For every labelled program directory present under the corpus root it runs

    $EFFECTC stress --confirm --format json --color never --size 64x64 --samples 2 \
        [--target-env ...] CORPUS_ROOT/<corpus>/<program>

(`--target-env vulkan` for the `vulkan` corpus, `vulkan1.2` for `fresh-vk`;
timeout 120 s per program), reads the `programs[].hazards[]` of the JSON report
and matches each hazard to the labels by (corpus, program, stage file name,
line, code), the way scripts/hazard_precision.py matches `check` warnings.
Several hazards with the same key (e.g. `cos(a), sin(a)` on one line) count as
one site; its verdict is the first of confirmed, refuted, unreached, untested
that any of them got (a site whose hazards disagree is marked `mixed` in --list).

It prints:
  - a table: label verdict (true / false / noise / unsure / unlabelled) x
    confirm verdict (confirmed / refuted / unreached / untested), plus
    `no-verdict` for a warning in the report that has no hazard entry, and
    `absent` for labelled sites of a program that ran but reported no such
    warning at all;
  - the same table per tier (`certain` / `possible`, the hazard's `tier`);
  - the disagreements: `false` or `noise` sites that are confirmed, and `true`
    sites that are refuted;
  - programs that are missing, time out, crash or print no JSON, and the error
    diagnostics of the reports (e.g. a program that cannot be rendered: its
    warnings are counted as `no-verdict`), with the command.

Usage:
  EFFECTC=/tmp/s45/bin/effectc-confirm python3 scripts/hazard_confirm.py \
      [--labels data/hazards/labels.tsv] [--corpus-root /work/corpus] [--jobs 2] \
      [--timeout 120] [--list]

--list also prints every site with its label, verdict, tier, case and the
label's reason. The exit status is always 0: this script measures, it does not
gate.
"""

import argparse
import concurrent.futures
import json
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from hazard_precision import TARGET_ENV, read_labels  # noqa: E402  (the labels, read one way)

LABELS = ("true", "false", "noise", "unsure", "unlabelled")
CONFIRM = ("confirmed", "refuted", "unreached", "untested")
COLUMNS = CONFIRM + ("no-verdict", "absent")


def confirm_program(effectc, root, corpus, program, timeout):
    """Run stress --confirm on one program dir.

    Returns (dict site key -> list of hazard dicts, list of error texts). A W07xx
    warning in the report's diagnostics with no hazard entry (the program could
    not be rendered) gets a single pseudo-hazard with verdict `no-verdict`; the
    report's error diagnostics are returned as errors."""
    cmd = [effectc, "stress", "--confirm", "--format", "json", "--color", "never",
           "--size", "64x64", "--samples", "2"]
    if corpus in TARGET_ENV:
        cmd += ["--target-env", TARGET_ENV[corpus]]
    cmd.append(os.path.join(root, corpus, program))
    shown = " ".join(cmd)
    try:
        proc = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return {}, [f"timeout after {timeout} s: {shown}"]
    except OSError as e:
        return {}, [f"{e}: {shown}"]
    try:
        doc = json.loads(proc.stdout)
        programs = doc["programs"]
    except (ValueError, KeyError, TypeError):
        msg = (proc.stderr.strip().splitlines() or ["(no stderr)"])[-1]
        return {}, [f"exit {proc.returncode}, no JSON report: {shown}: {msg}"]
    sites = {}
    for prog in programs:
        for h in prog.get("hazards", []):
            at = h.get("at") or ""
            path, _, line = at.rpartition(":")
            if not path or not line.isdigit():
                continue
            key = (corpus, program, os.path.basename(path), int(line), h.get("code"))
            sites.setdefault(key, []).append(h)
    errs = []
    diags = doc.get("diagnostics", [])
    if isinstance(diags, dict):
        diags = diags.get("diagnostics", [])
    for d in diags:
        code = d.get("code") or ""
        if code.startswith("W07") and d.get("file") and d.get("span"):
            key = (corpus, program, os.path.basename(d["file"]), d["span"]["line"], code)
            if key not in sites:
                tier = next((n.split(":")[0] for n in d.get("notes", [])
                             if n.startswith(("certain:", "possible:"))), None)
                sites[key] = [{"verdict": "no-verdict", "tier": tier, "case": None}]
        elif d.get("severity") == "error" and code != "E0703":  # E0703 = a confirmed hazard
            msg = " ".join(str(d.get("message", "")).split())
            errs.append(f"{code} {msg}: {shown}")
    if proc.returncode not in (0, 1):
        msg = (proc.stderr.strip().splitlines() or ["(no stderr)"])[-1]
        errs.append(f"exit {proc.returncode}: {shown}: {msg}")
    return sites, errs


def site_verdict(hazards):
    """(verdict, tier, case, mixed?) of a site from its hazards."""
    verdicts = [h.get("verdict") for h in hazards]
    verdict = next((v for v in COLUMNS if v in verdicts), verdicts[0] or "?")
    tiers = {h.get("tier") for h in hazards}
    tier = "certain" if "certain" in tiers else (tiers.pop() if len(tiers) == 1 else "?")
    case = next((h.get("case") for h in hazards if h.get("verdict") == verdict and h.get("case")), None)
    return verdict, tier, case, len(set(verdicts)) > 1


def fmt_case(case):
    if case is None:
        return "-"
    if isinstance(case, str):
        return case
    return json.dumps(case, sort_keys=True, separators=(",", ":"))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--labels", default="data/hazards/labels.tsv")
    ap.add_argument("--corpus-root", default=os.environ.get("CORPUS_ROOT", "/work/corpus"))
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--timeout", type=int, default=120)
    ap.add_argument("--list", action="store_true", help="print every site with its label and verdict")
    args = ap.parse_args()
    effectc = os.environ.get("EFFECTC", "target/release/effectc")

    labels = read_labels(args.labels)
    programs = sorted({(k[0], k[1]) for k in labels})
    present = [(c, p) for c, p in programs if os.path.isdir(os.path.join(args.corpus_root, c, p))]
    missing = [(c, p) for c, p in programs if (c, p) not in present]

    found = {}
    errors = []
    ran = set()
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, min(args.jobs, 2))) as pool:
        jobs = {pool.submit(confirm_program, effectc, args.corpus_root, c, p, args.timeout): (c, p)
                for c, p in present}
        for job in concurrent.futures.as_completed(jobs):
            sites, errs = job.result()
            found.update(sites)
            errors += errs
            if not any(e.startswith("timeout") or "no JSON" in e for e in errs):
                ran.add(jobs[job])

    # site -> (label, verdict, tier, case, mixed, reason)
    rows = {}
    for key, hazards in found.items():
        label, reason = labels.get(key, ("unlabelled", ""))
        verdict, tier, case, mixed = site_verdict(hazards)
        rows[key] = (label, verdict, tier, case, mixed, reason)
    for key, (label, reason) in labels.items():
        if key not in rows and (key[0], key[1]) in ran:
            rows[key] = (label, "absent", "-", None, False, reason)

    def table(title, keys):
        counts = {(l, v): 0 for l in LABELS for v in COLUMNS}
        for k in keys:
            label, verdict = rows[k][0], rows[k][1]
            label = label if label in LABELS else "unlabelled"
            if verdict in COLUMNS:
                counts[(label, verdict)] += 1
        print(f"{title}: {len(keys)} sites")
        print(f"  {'label':<11}" + "".join(f"{v:>11}" for v in COLUMNS) + f"{'total':>8}")
        for l in LABELS:
            n = [counts[(l, v)] for v in COLUMNS]
            print(f"  {l:<11}" + "".join(f"{x:>11}" for x in n) + f"{sum(n):>8}")
        tot = [sum(counts[(l, v)] for l in LABELS) for v in COLUMNS]
        print(f"  {'total':<11}" + "".join(f"{x:>11}" for x in tot) + f"{sum(tot):>8}")

    def fmt(k):
        return f"{k[0]}/{k[1]}/{k[2]}:{k[3]} {k[4]}"

    labelled_sites = sum(1 for k in labels if (k[0], k[1]) in present)
    print(f"effectc: {effectc}")
    print(f"labels: {args.labels} ({len(labels)} sites in {len(programs)} programs)")
    print(f"present under {args.corpus_root}: {len(present)} programs ({labelled_sites} labelled sites); "
          f"ran: {len(ran)}; missing: {len(missing)}")
    table("all sites (label x confirm verdict)", sorted(rows))
    for tier in ("certain", "possible"):
        table(f"tier {tier}", sorted(k for k, r in rows.items() if r[2] == tier))

    bad = sorted(k for k, r in rows.items()
                 if (r[0] in ("false", "noise") and r[1] == "confirmed") or (r[0] == "true" and r[1] == "refuted"))
    print(f"disagreements (false/noise confirmed, true refuted): {len(bad)}")
    for k in bad:
        label, verdict, tier, case, _, reason = rows[k]
        print(f"  {label}->{verdict} {fmt(k)} [{tier}] case={fmt_case(case)}  -- {reason}")
    for c, p in missing:
        print(f"missing: {c}/{p}")
    for e in sorted(errors):
        print(f"error: {e}", file=sys.stderr)
    if args.list:
        print("sites:")
        for k in sorted(rows):
            label, verdict, tier, case, mixed, reason = rows[k]
            mark = " (mixed)" if mixed else ""
            print(f"  {label:<10} {verdict:<9}{mark} {tier:<8} {fmt(k)}  case={fmt_case(case)}  {reason}")
    return 0


if __name__ == "__main__":
    main()
    sys.exit(0)
