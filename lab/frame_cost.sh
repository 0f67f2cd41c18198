#!/bin/sh
# Instructions per frame of the tracer's cornell scene (128x128, 16 spp,
# the default tracing) for each sampler, over the pcg32 baseline's, under
# callgrind (stable where the frame times of docs/tracer.md are not), as
# the Markdown table of docs/tracer.md's "Frame cost in instructions":
#
#     lab/frame_cost.sh > target/frame-cost.md         # the default samplers
#     lab/frame_cost.sh sobol halton > target/x.md     # chosen ones
#
# A frame's count is half of (3 frames - 1 frame), so the start-up, the
# reference (read from its cache under out/, made natively first) and the
# report drop out. About 25 seconds a sampler; needs valgrind.
set -eu
cd "$(dirname "$0")/.."
. lab/callgrind.sh
callgrind_example tracer
count() { collected --scene cornell --sampler "$1" --spp 16 --frames "$2"; }
frame() { echo $(( ($(count "$1" 3) - $(count "$1" 1)) / 2 )); }
if [ $# -eq 0 ]; then
    set -- random sobol pmj02 zsobol blue-noise jittered correlated-multi-jittered \
        blue-multi-jittered orthogonal
fi
# One native frame of each first: it makes (or finds) the reference, which
# under callgrind would take hours, and a name the tracer does not know
# stops here with its one-line message and exit status 2.
"$bin" --scene cornell --sampler "pcg32$(printf ',%s' "$@")" --spp 16 --frames 1 >/dev/null
base=$(frame pcg32)
echo "Instructions per cornell 128x128 frame at 16 spp (callgrind), pcg32: $base ($(( base / (128 * 128 * 16) )) a pixel sample)."
echo
echo "| sampler | instructions per frame | / pcg32 | more than pcg32, per pixel sample |"
echo "|---|---:|---:|---:|"
for kind in "$@"; do
    n=$(frame "$kind")
    awk -v k="$kind" -v n="$n" -v b="$base" \
        'BEGIN { printf "| %s | %.0f | %.3fx | %.0f |\n", k, n, n / b, (n - b) / (128 * 128 * 16) }'
done
