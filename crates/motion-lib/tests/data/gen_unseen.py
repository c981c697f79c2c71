#!/usr/bin/env python3
"""Writes ruckig-unseen.jsonl: new random problems of the hard kinds, solved by ruckig.

Usage: python3 -m venv /tmp/rk && /tmp/rk/bin/pip install ruckig==0.19.4
       /tmp/rk/bin/python gen_unseen.py [COUNT_PER_KIND (600)] [SEED] > ruckig-unseen.jsonl

Kinds (same fields as ruckig-profiles.jsonl, see README.md):
- "brake":   |v0| up to 3x vmax (either sign), a0 up to 2x the limits, any target, v1 = 0.
- "target_v": non-zero target velocity v1 (|v1| <= vmax, either sign) with a start
             acceleration a0 within the limits, any direction of travel.
- "negative": p1 < p0, start and target velocities <= 0, a0 within the limits.
- "decades": limits spread over ten decades (vmax 1e-4..1e6, amax and jmax independent),
             arbitrary start state within the limits, v1 = 0.
- "line3":   three axes, rest to rest on a straight line, unequal per-axis limits; the
             duration is the 1-D optimum with the axis limits projected onto the line.

Acceleration limits follow the library's convention (README_profile.md): amax in the
direction of travel, dmax against it; ruckig's max/min_acceleration are set accordingly
(mirrored for a move towards -p). Problems that ruckig refuses are skipped.
"""
import json
import math
import random
import sys

from ruckig import InputParameter, Result, Ruckig, RuckigError, Trajectory


def g9(x):
    """Rounds to 9 significant digits (short lines; the problem is solved as written)."""
    return float(f"{x:.9g}")


def solve(p0, v0, a0, p1, v1, vmax, amax, dmax, jmax):
    inp = InputParameter(1)
    inp.current_position = [p0]
    inp.current_velocity = [v0]
    inp.current_acceleration = [a0]
    inp.target_position = [p1]
    inp.target_velocity = [v1]
    inp.target_acceleration = [0.0]
    inp.max_velocity = [vmax]
    if p1 >= p0:
        inp.max_acceleration = [amax]
        inp.min_acceleration = [-dmax]
    else:
        inp.max_acceleration = [dmax]
        inp.min_acceleration = [-amax]
    inp.max_jerk = [jmax]
    traj = Trajectory(1)
    try:
        res = Ruckig(1).calculate(inp, traj)
    except RuckigError:  # no solution for this input
        return None
    if res not in (Result.Working, Result.Finished):
        return None
    d = traj.duration
    return d if math.isfinite(d) and d > 0.0 else None


def limits(r, decades=False):
    if decades:
        vmax = 10 ** r.uniform(-4, 6)
        amax = 10 ** r.uniform(-4, 6)
        jmax = 10 ** r.uniform(-4, 6)
        dmax = amax
    else:
        vmax = 10 ** r.uniform(-1, 3)
        amax = vmax * 10 ** r.uniform(-1, 1.5)
        jmax = amax * 10 ** r.uniform(-1, 1.5)
        dmax = amax * r.uniform(0.3, 3.0)
    return vmax, amax, dmax, jmax


def one(r, kind):
    vmax, amax, dmax, jmax = limits(r, kind == "decades")
    span = vmax * vmax / min(amax, dmax) + vmax * min(amax, dmax) / jmax
    p0 = r.uniform(-10, 10) * span
    if kind == "brake":
        dmax = amax  # a start beyond the limits: the symmetric convention
        v0 = r.choice([-1, 1]) * vmax * r.uniform(1.01, 3.0)
        a0 = r.uniform(-2, 2) * amax
        p1 = p0 + r.uniform(-5, 5) * span
        v1 = 0.0
    elif kind == "target_v":
        v0 = r.uniform(-1, 1) * vmax
        a0 = r.uniform(-dmax, amax) * 0.95
        d = r.uniform(0.05, 5) * span * r.choice([-1, 1])
        p1 = p0 + d
        if p1 < p0:
            a0 = -a0
        v1 = r.choice([-1, 1]) * r.uniform(0.05, 1.0) * vmax
    elif kind == "negative":
        v0 = -r.uniform(0, 1) * vmax
        a0 = r.uniform(-amax, dmax) * 0.95
        p1 = p0 - r.uniform(0.01, 5) * span
        v1 = -r.uniform(0, 1) * vmax if r.random() < 0.5 else 0.0
    else:  # decades
        dmax = amax
        v0 = r.uniform(-1, 1) * vmax
        a0 = r.uniform(-1, 1) * amax * 0.95
        p1 = p0 + r.uniform(-5, 5) * span
        v1 = 0.0
    p0, v0, a0, p1, v1, vmax, amax, dmax, jmax = map(
        g9, (p0, v0, a0, p1, v1, vmax, amax, dmax, jmax))
    dur = solve(p0, v0, a0, p1, v1, vmax, amax, dmax, jmax)
    if dur is None:
        return None
    return {"kind": kind, "p0": p0, "v0": v0, "a0": a0, "p1": p1, "v1": v1, "vmax": vmax,
            "amax": amax, "dmax": dmax, "jmax": jmax, "duration": dur}


def line3(r):
    start = [g9(r.uniform(-1000, 1000)) for _ in range(3)]
    end = [g9(s + r.uniform(-500, 500) * (10 ** r.uniform(-3, 0))) for s in start]
    vmax = [g9(10 ** r.uniform(0, 3)) for _ in range(3)]
    amax = [g9(v * 10 ** r.uniform(-1, 1.5)) for v in vmax]
    jmax = [g9(a * 10 ** r.uniform(-1, 1.5)) for a in amax]
    d = [e - s for s, e in zip(start, end)]
    length = math.sqrt(sum(x * x for x in d))
    if length == 0.0:
        return None
    u = [abs(x) / length for x in d]
    proj = lambda lim: min(l / ui for l, ui in zip(lim, u) if ui > 0.0)
    dur = solve(0.0, 0.0, 0.0, length, 0.0, proj(vmax), proj(amax), proj(amax), proj(jmax))
    if dur is None:
        return None
    return {"kind": "line3", "start": start, "end": end, "vmax": vmax, "amax": amax,
            "jmax": jmax, "duration": dur}


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 600
    r = random.Random(int(sys.argv[2]) if len(sys.argv) > 2 else 20261202)
    for kind in ["brake", "target_v", "negative", "decades", "line3"]:
        k = 0
        while k < n:
            p = line3(r) if kind == "line3" else one(r, kind)
            if p is not None:
                print(json.dumps(p))
                k += 1


if __name__ == "__main__":
    main()
