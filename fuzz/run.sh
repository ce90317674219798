#!/usr/bin/env bash
# Runs one AFL++ fuzz target for a fixed time and prints its statistics.
#
# Usage: fuzz/run.sh TARGET [SECONDS] [OUT_DIR]
#   TARGET: protocol     the external protocol's request and reply decoders
#           certificate  the certificate reader and the sweep merge's combine
#           npy|csv|hex  `gartowen check` on a point file of that format (the whole reader path,
#                        through an instrumented CLI binary)
# Needs cargo-afl (`cargo install cargo-afl`; it builds AFL++ itself). Crashes land in
# OUT_DIR/default/crashes (default OUT_DIR: fuzz/target/findings/TARGET).
set -euo pipefail
cd "$(dirname "$0")"
target="${1:?usage: fuzz/run.sh TARGET [SECONDS] [OUT_DIR]}"
secs="${2:-60}"
out="${3:-target/findings/$target}"
command -v cargo-afl > /dev/null || cargo install cargo-afl
export AFL_NO_UI=1 AFL_SKIP_CPUFREQ=1 AFL_I_DONT_CARE_ABOUT_MISSING_CRASHES=1
rm -rf "$out"
mkdir -p "$(dirname "$out")"
case "$target" in
  protocol | certificate)
    cargo afl build --release --bin "$target"
    cargo afl fuzz -V "$secs" -i "seeds/$target" -o "$out" "target/release/$target" > /dev/null
    ;;
  npy | csv | hex)
    CARGO_TARGET_DIR="$PWD/target/cli" cargo afl build --release -p gartowen-cli \
      --manifest-path ../Cargo.toml
    input="$(mktemp -d)/input.$target"
    cargo afl fuzz -V "$secs" -t 2000 -f "$input" -i "seeds/$target" -o "$out" -- \
      target/cli/release/gartowen check "$input" --base 2 > /dev/null
    ;;
  *)
    echo "unknown target '$target' (protocol, certificate, npy, csv, hex)" >&2
    exit 2
    ;;
esac
stats="$out/default/fuzzer_stats"
for key in execs_done execs_per_sec corpus_count saved_crashes saved_hangs bitmap_cvg; do
  grep "^$key " "$stats" | tr -s ' '
done
