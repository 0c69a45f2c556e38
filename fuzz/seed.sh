#!/usr/bin/env bash
# Seeds the fuzz corpora from the repository's own inputs (fuzz/corpus/, git-ignored):
# manifests, fragment stages, and vertex+fragment pairs joined by a `//--` line.
set -euo pipefail
cd "$(dirname "$0")/.."
mkdir -p fuzz/corpus/manifest fuzz/corpus/front fuzz/corpus/check
for f in $(find effects tests -name effect.toml); do cp "$f" "fuzz/corpus/manifest/$(echo "$f" | tr / _)"; done
for f in $(find effects tests -name '*.frag'); do cp "$f" "fuzz/corpus/front/$(echo "$f" | tr / _)"; done
for d in $(find tests effects -name '*.vert' -printf '%h\n' | sort -u); do
    v=$(ls "$d"/*.vert | head -1); f=$(ls "$d"/*.frag 2>/dev/null | head -1 || true)
    [ -n "$f" ] || continue
    { cat "$v"; printf '\n//--\n'; cat "$f"; } > "fuzz/corpus/check/$(echo "$d" | tr / _)"
done
ls fuzz/corpus/* | wc -l
