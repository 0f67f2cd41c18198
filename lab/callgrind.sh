# Sourced, from the workspace root, by lab/draw_cost.sh and
# lab/frame_cost.sh: `callgrind_example NAME` checks for valgrind, builds
# the release example NAME and sets `bin` to it; `collected ARGS...` prints
# the instructions callgrind counts in one run of `$bin ARGS...`.
callgrind_example() {
    command -v valgrind >/dev/null || { echo "${0##*/}: needs valgrind" >&2; exit 2; }
    cargo build --quiet --release -p wellspread-lab --example "$1"
    bin="${CARGO_TARGET_DIR:-target}/release/examples/$1"
}
collected() {
    valgrind --tool=callgrind --callgrind-out-file=/dev/null "$bin" "$@" 2>&1 |
        sed -n 's/.*Collected : \([0-9]*\).*/\1/p'
}
