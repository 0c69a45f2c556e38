#!/usr/bin/env bash
# Seeds the fuzz corpora from the repository's own inputs (fuzz/corpus/, git-ignored):
# manifests, fragment stages, and vertex+fragment pairs joined by a `//--` line; and a few
# recipes for `structure` (bytes, not GLSL: see fuzz_targets/structure.rs).
set -euo pipefail
cd "$(dirname "$0")/.."
mkdir -p fuzz/corpus/manifest fuzz/corpus/front fuzz/corpus/check fuzz/corpus/structure
for f in $(find effects tests -name effect.toml); do cp "$f" "fuzz/corpus/manifest/$(echo "$f" | tr / _)"; done
for f in $(find effects tests -name '*.frag'); do cp "$f" "fuzz/corpus/front/$(echo "$f" | tr / _)"; done
for d in $(find tests effects -name '*.vert' -printf '%h\n' | sort -u); do
    v=$(ls "$d"/*.vert | head -1); f=$(ls "$d"/*.frag 2>/dev/null | head -1 || true)
    [ -n "$f" ] || continue
    { cat "$v"; printf '\n//--\n'; cat "$f"; } > "fuzz/corpus/check/$(echo "$d" | tr / _)"
done
# A recipe from hex bytes: flags, then parts (opcode, then its parameters; counts are a
# class byte, 02 = up to the maximum, and a little-endian u16).
recipe() { printf "$(echo "$2" | tr -d ' ' | sed 's/../\\x&/g')" > "fuzz/corpus/structure/$1"; }
recipe ifs1000-sum10000 '00  00 02 e803 00 00  02 02 1027 00 00'   # the hostile suite's deep legal shapes
recipe parens1000 '00  01 02 e803 00 00'                           # (u0 + (u1 + (… x …)))
recipe wrappers1500 '00  01 02 dc05 00 01'                         # parentheses, abs(), -(), ?:, vec2().x
recipe functions2000 '00  03 02 d007 00'                           # a chain of 2,000 functions
recipe statements20000 '00  04 02 204e 00'                         # 20,000 statements in main
recipe uniforms5000 '00  06 02 8813 0b'                            # 5,000 vec4 uniforms in one declaration
recipe block2000 '00  07 02 d007 00 00'                            # a uniform block of 2,000 members
recipe struct500-nested32 '00  07 02 f401 20 04'                   # a uniform struct nested 32 deep, with an initializer
recipe macro24-used '00  05 18 08'                                 # 24 doubling levels, used: E0107
recipe macro20 '00  05 14 00'                                      # the first level past 2^20 tokens: E0107
recipe array1e8 '00  08 03 ffe0f505 00 00'                         # uniform float w[100000000]: E0107
recipe array65537 '00  08 01 11000000 00 00'                       # one element past the limit: E0107
recipe array65536 '00  08 01 10000000 00 00'                       # at the limit: no error
recipe two-stages-mixed '01  00 02 f401 01 00  06 01 2c01 00  02 02 d007 00 01  04 01 c800 00  08 00 05000000 01 01'
ls fuzz/corpus/* | wc -l
