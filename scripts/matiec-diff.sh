#!/usr/bin/env bash
# Cycle-by-cycle differential run of ladderc against matiec (tests/tests/matiec_diff.rs, live).
#
# Usage:  scripts/matiec-diff.sh [--unseen-only] [PROGRAM.il|PROGRAM.st ...]
#   without arguments: the corpus tests/tests/fixtures/matiec_diff/ (each program against its known
#   disagreements); with arguments: those programs as well, every difference reported;
#   --unseen-only: only the programs named (scripts/matiec-fuzz.sh), not the corpus.
# Input (environment, all optional):
#   MATIEC_BIN   iec2c; default target/matiec/iec2c (scripts/build-matiec.sh builds it)
#   MATIEC_LIB   matiec's lib/ folder; default target/matiec/build/lib, else $MATIEC_SRC/lib
#   MATIEC_DIFF_RECORD=1   rewrite the corpus's recorded matiec traces (NAME.matiec.csv)
# A program needs a CONFIGURATION with a task that runs on every tick; its first line may say
# `(* matiec-diff: cycles=N *)` (default 100). Both sides run N cycles at matiec's tick time, with
# matiec's __CURRENT_TIME and ladderc's scan clock both at k * tick in cycle k.
# Output: per program, the columns and cycles compared and each differing column's first difference.
# Exit: 0 all agree (or differ only as documented), 1 a difference or a failure, 2 usage (no iec2c).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bin="${MATIEC_BIN:-$root/target/matiec/iec2c}"
if [[ ! -x "$bin" ]]; then
    echo "error: no iec2c at $bin; build it with MATIEC_SRC=<clone of beremiz/matiec> scripts/build-matiec.sh" >&2
    exit 2
fi
lib="${MATIEC_LIB:-}"
if [[ -z "$lib" ]]; then
    if [[ -d "$root/target/matiec/build/lib" ]]; then lib="$root/target/matiec/build/lib"
    elif [[ -n "${MATIEC_SRC:-}" ]]; then lib="$MATIEC_SRC/lib"; fi
fi
if [[ -z "$lib" || ! -f "$lib/ieclib.txt" ]]; then
    echo "error: matiec's lib/ folder not found; set MATIEC_LIB (or MATIEC_SRC)" >&2
    exit 2
fi
bin="$(cd "$(dirname "$bin")" && pwd)/$(basename "$bin")"
lib="$(cd "$lib" && pwd)"
filter=()
if [[ "${1:-}" == "--unseen-only" ]]; then
    filter=(unseen_programs_from_the_environment)
    shift
fi
files=()
for f in "$@"; do
    [[ -f "$f" ]] || { echo "error: no such file: $f" >&2; exit 2; }
    files+=("$(cd "$(dirname "$f")" && pwd)/$(basename "$f")")
done
export MATIEC_BIN="$bin" MATIEC_LIB="$lib"
if ((${#files[@]})); then
    MATIEC_DIFF_FILES="$(IFS=:; echo "${files[*]}")"
    export MATIEC_DIFF_FILES
fi
cd "$root"
if cargo test -q -p ladderc-tests --test matiec_diff -- "${filter[@]}" --nocapture --test-threads 1; then exit 0; else exit 1; fi
