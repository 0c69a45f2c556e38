#!/usr/bin/env python3
"""Validates effectc's SARIF against the SARIF 2.1.0 JSON schema, and checks that every
rule a result references is described (short and full description, help URI).

The schema ships in the npm package `@microsoft/sarif-multitool-linux` (sarif-2.1.0.json);
it is fetched with `npm pack` into a temporary directory unless SCHEMA is given. Needs
python3's `jsonschema`.

    scripts/validate_sarif.py [EFFECTC] [INPUT] [SCHEMA]
        # defaults: target/release/effectc, tests/fail (a failing run: every fixture's codes)
"""
import json
import os
import subprocess
import sys
import tempfile

import jsonschema

EFFECTC = sys.argv[1] if len(sys.argv) > 1 else "target/release/effectc"
INPUT = sys.argv[2] if len(sys.argv) > 2 else "tests/fail"


def schema_path(tmp):
    if len(sys.argv) > 3:
        return sys.argv[3]
    subprocess.run(["npm", "pack", "--silent", "@microsoft/sarif-multitool-linux"], cwd=tmp, check=True, capture_output=True)
    tgz = next(f for f in os.listdir(tmp) if f.endswith(".tgz"))
    subprocess.run(["tar", "xzf", tgz, "package/sarif-2.1.0.json"], cwd=tmp, check=True)
    return os.path.join(tmp, "package", "sarif-2.1.0.json")


def main():
    with tempfile.TemporaryDirectory() as tmp:
        schema = json.load(open(schema_path(tmp)))
    run = subprocess.run([EFFECTC, "check", "--format", "sarif", INPUT], capture_output=True, text=True)
    doc = json.loads(run.stdout)
    validator = jsonschema.validators.validator_for(schema)(schema)
    errors = list(validator.iter_errors(doc))
    for e in errors[:20]:
        print(f"schema: {e.json_path}: {e.message[:200]}")
    runs = doc["runs"]
    rules = {r["id"]: r for r in runs[0]["tool"]["driver"].get("rules", [])}
    used = {res["ruleId"] for res in runs[0]["results"]}
    undescribed = sorted(
        rid for rid in used
        if rid not in rules
        or not rules[rid].get("shortDescription", {}).get("text")
        or not rules[rid].get("fullDescription", {}).get("text")
        or not rules[rid].get("helpUri")
    )
    print(f"effectc exit {run.returncode}; {len(runs[0]['results'])} results, {len(used)} rules referenced, "
          f"{len(rules)} described; schema errors: {len(errors)}; rules without a description: {undescribed or 'none'}")
    return 1 if errors or undescribed else 0


if __name__ == "__main__":
    sys.exit(main())
