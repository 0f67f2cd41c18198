#!/bin/sh
# Instructions per pixel sample of every pixel sampler's draws, under
# callgrind (stable where wall time is not), as the Markdown table of
# docs/performance.md:
#
#     lab/draw_cost.sh > target/draw-cost.md
#     lab/draw_cost.sh study > target/joint-cost.md   # docs/joint_study.md's table
#
# Runs lab/examples/draw_cost.rs for each kind and workload: 2^16 scattered
# pixel samples, the inputs' loop (`sobol loop`) subtracted. "static" is
# the concrete type (through AnyPixelSampler::visit), "any" the borrowed
# Domain<&AnyPixelSampler>, "owned" the owned Domain<AnyPixelSampler>.
set -eu
cd "$(dirname "$0")/.."
. lab/callgrind.sh
callgrind_example draw_cost
loop=$(collected sobol loop)
per() { echo $(( ($(collected "$1" "$2") - loop) / 65536 )); }
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.2fx", a / b }'; }
unit2=$(per unit 2d)
unit9=$(per unit path)
if [ "${1:-}" = study ]; then
    # The study's candidates (static only: they are not AnyPixelSampler
    # kinds) beside sobol and orthogonal, and their ratios to sobol's
    # AnyPixelSampler counts, the bounds of the orthogonal-array issue.
    s2=$(per sobol 2d-any); sp=$(per sobol path-any)
    echo "Unit: $unit2 instructions for start+next_2d's PCG hash, $unit9 for the nine-unit path. Ratios are to sobol through AnyPixelSampler: 2d $s2, path $sp."
    echo
    echo "| back end | start+next_2d | / sobol any | start+next_4d | 9-draw path, keyed / call order | keyed / sobol any |"
    echo "|---|---|---|---|---|---|"
    for kind in sobol pmj02 orthogonal faure joint-sobol joint-sobol-4d; do
        k2=$(per $kind 2d); k4=$(per $kind 4d); kp=$(per $kind path); kc=$(per $kind path-call)
        echo "| $kind (static) | $k2 | $(ratio $k2 $s2) | $k4 | $kp / $kc | $(ratio $kp $sp) |"
    done
    for kind in sobol orthogonal faure; do
        k2=$(per $kind 2d-any); k4=$(per $kind 4d-any); kp=$(per $kind path-any); kc=$(per $kind path-call-any)
        echo "| $kind (any) | $k2 | $(ratio $k2 $s2) | $k4 | $kp / $kc | $(ratio $kp $sp) |"
    done
    exit 0
fi
echo "Unit: $unit2 instructions for start+next_2d's PCG hash, $unit9 for the nine-unit path."
echo
echo "| back end | start+next_2d: static / any / owned | any / static | start+next_4d | 9-draw path: static / any / owned | any / static | start: static / any |"
echo "|---|---|---|---|---|---|---|"
for kind in regular random jittered n-rooks multi-jittered cmj blue-multi-jittered \
    hammersley halton sobol pmj02 zsobol blue-noise orthogonal latin-hypercube faure; do
    s2=$(per $kind 2d); a2=$(per $kind 2d-any); o2=$(per $kind 2d-any-owned)
    s4=$(per $kind 4d)
    sp=$(per $kind path); ap=$(per $kind path-any); op=$(per $kind path-any-owned)
    sn=$(per $kind none); an=$(per $kind none-any)
    echo "| $kind | $s2 / $a2 / $o2 | $(ratio $a2 $s2) | $s4 | $sp / $ap / $op | $(ratio $ap $sp) | $sn / $an |"
done
