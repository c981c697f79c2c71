#!/usr/bin/env bash
# The matiec anchor, side by side: compiles the same generated IL program with matiec's iec2c and with
# `ladderc build`, in paired, interleaved runs, and prints CPU time (user+sys) and peak RSS of each
# process, with the ratios.
#
# Input (environment, all optional):
#   LINES, POUS   shape of the program, il_frontend::testgen::generate(LINES, POUS); default 2000 x 50
#                 (100,000 body lines; matiec rejects a POU body over 64 KiB, so keep POUs moderate)
#   PAIRS         number of (iec2c, ladderc) pairs; default 5. The order inside a pair alternates.
#   IEC2C         the iec2c binary; default target/matiec/iec2c (scripts/build-matiec.sh builds it)
#   MATIEC_LIB    matiec's lib/ folder (iec2c -I); default target/matiec/build/lib, else $MATIEC_SRC/lib
#   LADDERC       the ladderc binary; default target/release/ladderc (built with cargo if missing)
# Output: one line per run, then medians and ratios (matiec / ladderc). Exit 0 also when iec2c is
# missing (it says so and measures nothing); 1 when a compiler fails on the program; 2 on usage errors.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
lines="${LINES:-2000}"
pous="${POUS:-50}"
pairs="${PAIRS:-5}"
iec2c="${IEC2C:-$root/target/matiec/iec2c}"
ladderc="${LADDERC:-$root/target/release/ladderc}"

if [[ ! -x "$iec2c" ]]; then
    echo "matiec anchor: no iec2c at $iec2c; nothing measured."
    echo "  build it with: MATIEC_SRC=<clone of beremiz/matiec> scripts/build-matiec.sh (or set IEC2C)"
    exit 0
fi
lib="${MATIEC_LIB:-}"
if [[ -z "$lib" ]]; then
    if [[ -d "$root/target/matiec/build/lib" ]]; then
        lib="$root/target/matiec/build/lib"
    elif [[ -n "${MATIEC_SRC:-}" ]]; then
        lib="$MATIEC_SRC/lib"
    fi
fi
if [[ -z "$lib" || ! -f "$lib/ieclib.txt" ]]; then
    echo "error: matiec's lib/ folder not found; set MATIEC_LIB (or MATIEC_SRC)" >&2
    exit 2
fi
if [[ ! -x /usr/bin/time ]]; then
    echo "error: /usr/bin/time (GNU time) is needed for peak RSS; apt-get install -y time" >&2
    exit 2
fi

gen="$root/target/release/examples/gen_il"
if [[ ! -x "$ladderc" || ! -x "$gen" ]]; then
    (cd "$root" && cargo build --release -q -p ladderc --bin ladderc && cargo build --release -q -p il-frontend --example gen_il)
fi

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
prog="$work/program.il"
"$gen" "$lines" "$pous" >"$prog"

# One run: $1 = name, the rest = command. Prints "name cpu_s peak_kb wall_s" and fails if the command does.
run() {
    local name="$1" out="$work/out-$1"
    shift
    rm -rf "$out" && mkdir -p "$out"
    if ! /usr/bin/time -f "%U %S %M %e" -o "$work/time" "$@" >"$work/log" 2>&1; then
        echo "error: $name failed on the program:" >&2
        tail -20 "$work/log" >&2
        exit 1
    fi
    read -r user sys peak wall <"$work/time"
    echo "$name $(echo "$user + $sys" | bc -l) $peak $wall"
}
run_iec2c() { run iec2c "$iec2c" -I "$lib" -T "$work/out-iec2c" "$prog"; }
run_ladderc() { run ladderc "$ladderc" build "$prog" -o "$work/out-ladderc"; }

echo "program: $pous POUs x $lines body lines, $(wc -l <"$prog") source lines, $(wc -c <"$prog") bytes of IL"
echo "iec2c:   $iec2c -I $lib"
echo "ladderc: $ladderc build"
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg), $(nproc) cores"
# Warm-up (page cache, and a check that both accept the program); not counted.
run_iec2c >/dev/null
run_ladderc >/dev/null
echo "C written: iec2c $(cat "$work"/out-iec2c/*.c "$work"/out-iec2c/*.h 2>/dev/null | wc -c) bytes, ladderc $(cat "$work"/out-ladderc/*.c "$work"/out-ladderc/*.h 2>/dev/null | wc -c) bytes"
echo
printf '%-5s %-8s %10s %10s %10s\n' pair compiler "CPU s" "wall s" "peak MB"
: >"$work/results"
for ((i = 1; i <= pairs; i++)); do
    if ((i % 2)); then order="iec2c ladderc"; else order="ladderc iec2c"; fi
    for c in $order; do
        read -r name cpu peak wall < <("run_$c")
        echo "$i $name $cpu $peak $wall" >>"$work/results"
        printf '%-5s %-8s %10.3f %10.3f %10.1f\n' "$i" "$name" "$cpu" "$wall" "$(echo "$peak / 1024" | bc -l)"
    done
done
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
echo

# Medians per compiler, and the per-pair CPU ratios.
median() { sort -g | awk '{ a[NR] = $1 } END { if (NR % 2) print a[(NR + 1) / 2]; else print (a[NR / 2] + a[NR / 2 + 1]) / 2 }'; }
col() { awk -v c="$1" -v k="$2" '$2 == c { print $k }' "$work/results"; }
m_cpu=$(col iec2c 3 | median); l_cpu=$(col ladderc 3 | median)
m_rss=$(col iec2c 4 | median); l_rss=$(col ladderc 4 | median)
m_wall=$(col iec2c 5 | median); l_wall=$(col ladderc 5 | median)
ratios=$(awk '{ cpu[$1, $2] = $3 } END { for (i = 1; cpu[i, "iec2c"] != ""; i++) printf "%.1f ", cpu[i, "iec2c"] / cpu[i, "ladderc"] }' "$work/results")
printf '%-24s %12s %12s %10s\n' "median of $pairs" iec2c ladderc "ratio"
printf '%-24s %12.3f %12.3f %9.1fx\n' "CPU s (user+sys)" "$m_cpu" "$l_cpu" "$(echo "$m_cpu / $l_cpu" | bc -l)"
printf '%-24s %12.3f %12.3f %9.1fx\n' "wall s" "$m_wall" "$l_wall" "$(echo "$m_wall / $l_wall" | bc -l)"
printf '%-24s %12.1f %12.1f %9.2fx\n' "peak RSS MB" "$(echo "$m_rss / 1024" | bc -l)" "$(echo "$l_rss / 1024" | bc -l)" "$(echo "$m_rss / $l_rss" | bc -l)"
echo "CPU ratio per pair: $ratios"
