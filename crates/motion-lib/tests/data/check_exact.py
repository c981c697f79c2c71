#!/usr/bin/env python3
"""Checks profiles written by `cargo run --example plan_jsonl` with exact arithmetic.

Usage: cargo run --release -p motion-lib --example plan_jsonl < problems.jsonl | python3 check_exact.py

Each phase [duration, jerk] is integrated from (p0, v0, a0) in rational arithmetic (the
doubles as written, no rounding). Reported per problem, relative to the limits: the largest
velocity and acceleration beyond the limits (velocity extrema inside phases included; a start
beyond a limit is allowed to come back monotonically, so only excess over max(limit, start)
counts), |jerk| beyond jmax, and the end-state errors |p - p1| / max(|p1 - p0|, 1e-300),
|v - v1| / vmax, |a| / amax. Position problems only (kinds other than line3 and velocity).
"""
import json
import sys
from fractions import Fraction as F


def check(o):
    p, v, a = F(o["p0"]), F(o["v0"]), F(o["a0"])
    p1, v1 = F(o["p1"]), F(o["v1"])
    vmax, amax, dmax, jmax = (F(o[k]) for k in ("vmax", "amax", "dmax", "jmax"))
    hi, lo = (amax, dmax) if p1 >= p else (dmax, amax)
    vlim = max(vmax, abs(v))
    ahi, alo = max(hi, a), max(lo, -a)
    worst_v = worst_a = worst_j = F(0)
    for t, j in o["phases"]:
        t, j = F(t), F(j)
        worst_j = max(worst_j, abs(j) - jmax)
        # velocity extremum inside the phase: a + j s = 0
        if j != 0:
            s = -a / j
            if 0 < s < t:
                ve = v + a * s + j * s * s / 2
                worst_v = max(worst_v, abs(ve) - vlim)
        p, v, a = p + v * t + a * t * t / 2 + j * t ** 3 / 6, v + a * t + j * t * t / 2, a + j * t
        worst_v = max(worst_v, abs(v) - vlim)
        worst_a = max(worst_a, a - ahi, -a - alo)
        if abs(v) <= vmax:
            vlim = vmax
        if -lo <= a <= hi:
            ahi, alo = hi, lo
    dist = max(abs(p1 - F(o["p0"])), F(1, 10 ** 300))
    return {
        "v_over": float(worst_v / vmax),
        "a_over": float(worst_a / min(amax, dmax)),
        "j_over": float(worst_j / jmax),
        "p_err": float(abs(p - p1) / dist),
        "v_err": float(abs(v - v1) / vmax),
        "a_err": float(abs(a) / min(amax, dmax)),
    }


for line in sys.stdin:
    if line.strip():
        o = json.loads(line)
        r = check(o)
        print(o["kind"], o["duration"], " ".join(f"{k}={x:.2e}" for k, x in r.items()))
