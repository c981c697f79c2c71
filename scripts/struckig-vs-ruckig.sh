#!/usr/bin/env bash
# Struckig (the TwinCAT port of ruckig) compiled by ladderc, measured against ruckig and motion-lib.
#
# Struckig (github stefanbesler/struckig) is GPL-3: it is not in this repository. Give its checkout
# (or the bare mirror's work tree); the script copies it to a scratch folder (unedited: since
# Session 36 ladderc compiles the library as it is), writes one ST driver program with one
# `Struckig.Otg(cycletime := 0.001, dofs := 1)` per oracle case (the first N of each single-axis
# kind of the ruckig oracle: rest, blend, abort), runs it one scan with
# `ladderc run driver.st --lib Struckig.plcproj --sanitize`, and prints, case by case, the
# trajectory duration of ruckig (the oracle), of Struckig compiled by ladderc (`otg.Duration`
# after its first call) and of motion-lib (`ladderc motion plan`).
#
# Usage: scripts/struckig-vs-ruckig.sh STRUCKIG_DIR [ORACLE.jsonl] [N_PER_KIND]
#   STRUCKIG_DIR  a checkout of stefanbesler/struckig (holds Struckig/Struckig/Struckig/Struckig.plcproj)
#   ORACLE.jsonl  default /work/shared/oracle/ruckig-profiles.jsonl
#   N_PER_KIND    default 4
# Env: LADDERC (default target/debug/ladderc), KEEP=1 keeps the scratch folder.
set -euo pipefail

src=${1:?usage: $0 STRUCKIG_DIR [ORACLE.jsonl] [N_PER_KIND]}
oracle=${2:-/work/shared/oracle/ruckig-profiles.jsonl}
per_kind=${3:-4}
root=$(cd "$(dirname "$0")/.." && pwd)
ladderc=${LADDERC:-$root/target/debug/ladderc}
work=$(mktemp -d)
[ "${KEEP:-}" = 1 ] || trap 'rm -rf "$work"' EXIT

cp -r "$src/Struckig" "$work/"

python3 - "$oracle" "$work" "$per_kind" <<'EOF'
# The driver: one Otg per case, its limits and states as the declaration's initial value.
import json, sys
oracle, out, per_kind = sys.argv[1], sys.argv[2], int(sys.argv[3])
cases, seen = [], {}
for line in open(oracle):
    c = json.loads(line)
    k = c["kind"]
    if k == "line3" or seen.get(k, 0) >= per_kind:
        continue
    seen[k] = seen.get(k, 0) + 1
    cases.append(c)
r = lambda x: repr(float(x))
decl, body = [], []
for i, c in enumerate(cases):
    decl.append(f"""  otg{i} : Struckig.Otg(cycletime := 0.001, dofs := 1) := (
    Synchronization := Struckig.SynchronizationType.None,
    MaxVelocity := [ {r(c['vmax'])} ], MaxAcceleration := [ {r(c['amax'])} ],
    MinAcceleration := [ {r(-c['dmax'])} ], MaxJerk := [ {r(c['jmax'])} ],
    CurrentPosition := [ {r(c['p0'])} ], CurrentVelocity := [ {r(c['v0'])} ],
    CurrentAcceleration := [ {r(c['a0'])} ],
    TargetPosition := [ {r(c['p1'])} ], TargetVelocity := [ {r(c['v1'])} ],
    TargetAcceleration := [ 0.0 ]);
  d{i} : LREAL;
  s{i} : Struckig.TrajectoryState;""")
    body.append(f"otg{i}();\nd{i} := otg{i}.Duration;\ns{i} := otg{i}.State;")
open(f"{out}/driver.st", "w").write(
    "PROGRAM main\nVAR\n" + "\n".join(decl) + "\nEND_VAR\n" + "\n".join(body) + "\nEND_PROGRAM\n")
with open(f"{out}/cases.jsonl", "w") as f:
    for c in cases:
        f.write(json.dumps(c) + "\n")
with open(f"{out}/watch", "w") as f:
    f.write(",".join(f"main.d{i},main.s{i}" for i in range(len(cases))))
EOF

"$ladderc" motion plan "$work/cases.jsonl" > "$work/motionlib.jsonl"
"$ladderc" --message-format short run "$work/driver.st" \
    --lib "$work/Struckig/Struckig/Struckig/Struckig.plcproj" \
    --cycles 1 --sanitize --trace "$work/trace.csv" --watch "$(cat "$work/watch")" \
    2> "$work/stderr.txt" || { grep -v 'warning\[\|note\[' "$work/stderr.txt" >&2; exit 1; }

python3 - "$work" <<'EOF'
import csv, json, sys
w = sys.argv[1]
cases = [json.loads(l) for l in open(f"{w}/cases.jsonl")]
plans = [json.loads(l) for l in open(f"{w}/motionlib.jsonl")]
row = list(csv.DictReader(open(f"{w}/trace.csv")))[0]
print("| # | kind | ruckig (s) | Struckig via ladderc (s) | rel. diff | motion-lib (s) | rel. diff | Otg state |")
print("|---|---|---|---|---|---|---|---|")
worst_s = worst_m = 0.0
for i, (c, p) in enumerate(zip(cases, plans)):
    ref = c["duration"]
    s = float(row[f"main.d{i}"])
    m = p["duration"]
    ds, dm = abs(s - ref) / ref, abs(m - ref) / ref
    worst_s, worst_m = max(worst_s, ds), max(worst_m, dm)
    print(f"| {i} | {c['kind']} | {ref:.9f} | {s:.9f} | {ds:.1e} | {m:.9f} | {dm:.1e} | {row[f'main.s{i}']} |")
print(f"\nlargest relative difference to ruckig: Struckig {worst_s:.1e}, motion-lib {worst_m:.1e}")
EOF
