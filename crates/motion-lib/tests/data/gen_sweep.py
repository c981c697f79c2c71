#!/usr/bin/env python3
"""A larger sweep of unseen problems, solved by ruckig 0.19.4 (issue #14's acceptance).

Usage: python3 -m venv /tmp/rk && /tmp/rk/bin/pip install ruckig==0.19.4
       /tmp/rk/bin/python gen_sweep.py [COUNT_PER_KIND (12000)] [SEED (14)] > sweep.jsonl
Check: RUCKIG_UNSEEN=sweep.jsonl cargo test --release -p motion-lib --test profile_oracle unseen

The five kinds of gen_unseen.py (brake, target_v, negative, decades, line3; same fields,
same conventions) plus two:
- "velocity": ruckig's velocity interface (Profile::velocity): start (v0, a0), target
             velocity v1 with acceleration 0, position free; a0 within the limits or up to
             1.5x beyond, limits from either range of gen_unseen.py (decades half the time).
             Direction of travel (amax applies along it): the sign of v1, else of v0.
- "mixed":   everything at once: limits over ten decades with dmax != amax, |v0| up to 2x
             vmax, a0 up to 1.5x the limits, a target velocity of either sign (or 0), any
             direction, the start anywhere within +-10 spans of the origin.
Problems that ruckig refuses are skipped.
"""
import json
import random
import sys

from ruckig import ControlInterface, InputParameter, Result, Ruckig, RuckigError, Trajectory

from gen_unseen import g9, limits, line3, one, solve


def solve_velocity(v0, a0, v1, amax, dmax, jmax):
    inp = InputParameter(1)
    inp.control_interface = ControlInterface.Velocity
    inp.current_position = [0.0]
    inp.current_velocity = [v0]
    inp.current_acceleration = [a0]
    inp.target_velocity = [v1]
    inp.target_acceleration = [0.0]
    inp.max_velocity = [1e300]
    up = v1 > 0 or (v1 == 0 and v0 >= 0)
    inp.max_acceleration = [amax if up else dmax]
    inp.min_acceleration = [-dmax if up else -amax]
    inp.max_jerk = [jmax]
    traj = Trajectory(1)
    try:
        res = Ruckig(1).calculate(inp, traj)
    except RuckigError:
        return None
    if res not in (Result.Working, Result.Finished):
        return None
    return traj.duration


def velocity(r):
    vmax, amax, dmax, jmax = limits(r, r.random() < 0.5)
    if r.random() < 0.5:
        dmax = amax * 10 ** r.uniform(-1, 1)
    v0 = r.uniform(-2, 2) * vmax
    beyond = r.random() < 0.2
    a0 = r.uniform(-1.5, 1.5) * max(amax, dmax) if beyond else r.uniform(-1, 1) * min(amax, dmax) * 0.95
    v1 = r.choice([0.0, r.uniform(-1, 1) * vmax, r.uniform(-1, 1) * vmax])
    v0, a0, v1, vmax, amax, dmax, jmax = map(g9, (v0, a0, v1, vmax, amax, dmax, jmax))
    dur = solve_velocity(v0, a0, v1, amax, dmax, jmax)
    if dur is None or not dur >= 0.0:
        return None
    return {"kind": "velocity", "p0": 0.0, "v0": v0, "a0": a0, "v1": v1, "vmax": vmax,
            "amax": amax, "dmax": dmax, "jmax": jmax, "duration": dur}


def mixed(r):
    vmax, amax, _, jmax = limits(r, True)
    dmax = amax * 10 ** r.uniform(-1, 1)
    span = vmax * vmax / min(amax, dmax) + vmax * min(amax, dmax) / jmax
    p0 = r.uniform(-10, 10) * span
    p1 = p0 + r.choice([-1, 1]) * 10 ** r.uniform(-3, 0.7) * span
    v0 = r.uniform(-2, 2) * vmax
    a0 = r.uniform(-1.5, 1.5) * max(amax, dmax) if r.random() < 0.3 else r.uniform(-1, 1) * min(amax, dmax) * 0.95
    v1 = r.choice([0.0, r.uniform(-1, 1) * vmax])
    p0, v0, a0, p1, v1, vmax, amax, dmax, jmax = map(g9, (p0, v0, a0, p1, v1, vmax, amax, dmax, jmax))
    dur = solve(p0, v0, a0, p1, v1, vmax, amax, dmax, jmax)
    if dur is None:
        return None
    return {"kind": "mixed", "p0": p0, "v0": v0, "a0": a0, "p1": p1, "v1": v1, "vmax": vmax,
            "amax": amax, "dmax": dmax, "jmax": jmax, "duration": dur}


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 12000
    r = random.Random(int(sys.argv[2]) if len(sys.argv) > 2 else 14)
    for kind in ["brake", "target_v", "negative", "decades", "line3", "velocity", "mixed"]:
        k = 0
        while k < n:
            if kind == "line3":
                p = line3(r)
            elif kind == "velocity":
                p = velocity(r)
            elif kind == "mixed":
                p = mixed(r)
            else:
                p = one(r, kind)
            if p is not None:
                print(json.dumps(p))
                k += 1


if __name__ == "__main__":
    main()
