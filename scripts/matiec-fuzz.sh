#!/usr/bin/env bash
# Random IL or ST programs run side by side with matiec, cycle by cycle (issue #13's differential
# acceptance).
#
# Usage:  scripts/matiec-fuzz.sh [--lang il|st] [COUNT [FIRST_SEED]]   (default: IL, 100 seeds from 1)
#   Writes the programs of seeds FIRST_SEED .. FIRST_SEED+COUNT-1 (tests/src/il_gen.rs: random valid
#   IEC 61131-3 IL with functions, function blocks, standard blocks and functions, arrays, structures;
#   with --lang st tests/src/st_gen.rs: random valid Structured Text, the same and IF/CASE/FOR/WHILE/
#   REPEAT/EXIT/RETURN, enumerations, subranges, strings) and compares each with matiec through tests/tests/matiec_diff.rs (unseen_programs_from_the_environment).
# Input (environment):
#   MATIEC_BIN, MATIEC_LIB   iec2c and matiec's lib/ folder, as for scripts/matiec-diff.sh
#   MATIEC_FUZZ_DIR          where the programs are written (default: a new temporary folder; a file
#                            already there is never overwritten)
# Output: per program the columns and cycles compared and each differing column's first difference, or
# the side that refuses it. A seed's program is the same on every machine, so a difference is re-run with
# `scripts/matiec-diff.sh DIR/gen_SEED.il` (`.st`).
# Exit: 0 every program agrees, 1 a difference or a refusal, 2 usage (no iec2c, bad arguments).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
gen=il-gen
if [[ "${1:-}" == "--lang" ]]; then
    case "${2:-}" in
        il) gen=il-gen ;;
        st) gen=st-gen ;;
        *) echo "usage: scripts/matiec-fuzz.sh [--lang il|st] [COUNT [FIRST_SEED]]" >&2; exit 2 ;;
    esac
    shift 2
fi
count="${1:-100}"
first="${2:-1}"
if ! [[ "$count" =~ ^[0-9]+$ && "$first" =~ ^[0-9]+$ ]]; then
    echo "usage: scripts/matiec-fuzz.sh [--lang il|st] [COUNT [FIRST_SEED]]" >&2
    exit 2
fi
bin="${MATIEC_BIN:-$root/target/matiec/iec2c}"
if [[ ! -x "$bin" ]]; then
    echo "error: no iec2c at $bin; build it with MATIEC_SRC=<clone of beremiz/matiec> scripts/build-matiec.sh" >&2
    exit 2
fi
dir="${MATIEC_FUZZ_DIR:-$(mktemp -d "${TMPDIR:-/tmp}/matiec-fuzz.XXXXXX")}"
cd "$root"
mapfile -t files < <(cargo run -q -p ladderc-tests --bin "$gen" -- "$first" "$count" "$dir")
echo "matiec-fuzz: ${#files[@]} programs (seeds $first..$((first + count - 1))) in $dir"
exec "$root/scripts/matiec-diff.sh" --unseen-only "${files[@]}"
