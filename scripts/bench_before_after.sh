#!/usr/bin/env bash
# Runs the speed benchmarks in two checkouts alternately (A B A B), so a refactor's
# before/after figures come from one session on one machine. Each tree's benchmark runs
# its own baseline (glslangValidator for check_speed.sh, a bare wgpu loop for
# render_speed), so the ratios are comparable across trees even when the machine drifts.
#
#   scripts/bench_before_after.sh BEFORE_DIR [AFTER_DIR] [ROUNDS]
#   (AFTER_DIR defaults to this checkout; ROUNDS to 2)
# Both trees must have been built first (`cargo build --release`,
# `cargo bench --bench render_speed --no-run`), e.g. with a git worktree of the old commit.
set -euo pipefail
before=$(cd "$1" && pwd)
after=$(cd "${2:-$(dirname "$0")/..}" && pwd)
rounds=${3:-2}
for r in $(seq 1 "$rounds"); do
    for tree in "$before" "$after"; do
        echo "== round $r: $tree ($(git -C "$tree" rev-parse --short HEAD))"
        (cd "$tree" && benches/check_speed.sh 10 | tail -3)
        (cd "$tree" && cargo bench --locked --quiet --bench render_speed 2>/dev/null | sed -n '/program/,/^$/p')
    done
done
