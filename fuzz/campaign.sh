#!/bin/sh
# Runs cargo-fuzz targets one after the other, each for a given time, with the flags of fuzz/README.md;
# logs go to $LOG (default /work/fuzzlog): <name>.log (libFuzzer's output), <name>.time (user, system and
# wall time from /usr/bin/time) and campaign.log (start and end lines).
# Usage: fuzz/campaign.sh il:300 st:240 ...   (build first: RUSTC_BOOTSTRAP=1 cargo fuzz build -s none)
# A spec is target:seconds or target:seconds:name (the log name, for a second run of a target).
# Environment: NICE (priority, default 19), RUNS (stop after this many executions, default none),
# MAX_LEN (default 65536), LOG, ALTSTACK (default 1: build fuzz/altstack.c and preload it, so that a stack
# overflow writes its input instead of dying silently; 0: run without it).
set -u
cd "$(dirname "$0")" || exit 1
LOG=${LOG:-/work/fuzzlog}
NICE=${NICE:-19}
MAX_LEN=${MAX_LEN:-65536}
RUNS=${RUNS:--1}
mkdir -p "$LOG"
B=target/x86_64-unknown-linux-gnu/release
PRELOAD=
if [ "${ALTSTACK:-1}" = 1 ]; then
    cc -shared -fPIC -O2 -o target/altstack.so altstack.c && PRELOAD="$(pwd)/target/altstack.so"
fi
for spec in "$@"; do
    t=${spec%%:*}; rest=${spec#*:}; s=${rest%%:*}; n=$t
    [ "$rest" != "$s" ] && n=${rest#*:}
    mkdir -p "artifacts/$t" "corpus/$t"
    echo "$(date -u +%FT%TZ) start $n ($t) $s s runs=$RUNS max_len=$MAX_LEN nice=$NICE" >> "$LOG/campaign.log"
    /usr/bin/time -f "%U user %S sys %e wall" -o "$LOG/$n.time" \
        env LD_PRELOAD="$PRELOAD" nice -n "$NICE" "$B/$t" "corpus/$t" -artifact_prefix="artifacts/$t/" -max_total_time="$s" \
        -runs="$RUNS" -max_len="$MAX_LEN" -timeout=1 -rss_limit_mb=2048 -print_final_stats=1 > "$LOG/$n.log" 2>&1
    echo "$(date -u +%FT%TZ) end $n rc=$? $(tail -1 "$LOG/$n.time")" >> "$LOG/campaign.log"
done
