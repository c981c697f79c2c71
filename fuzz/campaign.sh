#!/bin/sh
# Runs cargo-fuzz targets one after the other at the lowest priority, each for a given time, with the
# flags of fuzz/README.md; logs go to $LOG (default /work/fuzzlog): <target>.log (libFuzzer's output),
# <target>.time (user, system and wall time from /usr/bin/time) and campaign.log (start and end lines).
# Usage: fuzz/campaign.sh il:300 st:240 ...   (build first: RUSTC_BOOTSTRAP=1 cargo fuzz build -s none)
set -u
cd "$(dirname "$0")" || exit 1
LOG=${LOG:-/work/fuzzlog}
mkdir -p "$LOG"
B=target/x86_64-unknown-linux-gnu/release
for spec in "$@"; do
    t=${spec%%:*}; s=${spec##*:}
    mkdir -p "artifacts/$t" "corpus/$t"
    echo "$(date -u +%FT%TZ) start $t $s s" >> "$LOG/campaign.log"
    /usr/bin/time -f "%U user %S sys %e wall" -o "$LOG/$t.time" \
        nice -n 19 "$B/$t" "corpus/$t" -artifact_prefix="artifacts/$t/" -max_total_time="$s" \
        -max_len=65536 -timeout=1 -rss_limit_mb=2048 -print_final_stats=1 > "$LOG/$t.log" 2>&1
    echo "$(date -u +%FT%TZ) end $t rc=$? $(tail -1 "$LOG/$t.time")" >> "$LOG/campaign.log"
done
