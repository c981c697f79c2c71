#!/usr/bin/env python3
"""One huge POU body (issue #12: the system C compiler's time on one long C function). Writes typical
programs of N rungs or statements in four languages and times `ladderc run --cycles 1` (which builds the
C with `cc -std=c99 -O2`, then runs one cycle), split into ladderc and cc:

- `ld`: PLCopen XML LD, N rungs cycling through contacts and coils, a rising-edge contact, set/reset coils,
  a TON, a CTU, a GT compare block, and every 50th rung a conditional jump forward over the next rung;
- `il`: the same rungs written in IL (about 5 instructions each);
- `st`: N ST statements of the same kinds (IF, FB calls, comparisons, arithmetic);
- `sfc`: a textual SFC (`.st`) of N/10 steps in a loop, each with an action and a timed transition.

Usage, from the repository root:

    LADDERC=target/release/ladderc python3 fuzz/hostile/bigbody.py [ld il st sfc] [N ...]

Prints, per language and N, the wall time of `ladderc run`, the CPU time (user + system) of its cc
child (`CC` is pointed at a wrapper that runs the real compiler under /usr/bin/time) and of ladderc
itself (total CPU minus cc). `LADDERC_BEFORE=path` times a second binary on the same input, side by
side. Inputs go to $OUT (a temporary folder), never into the repository.
"""
import os, subprocess, sys, tempfile, time

OUT = os.environ.get("OUT") or tempfile.mkdtemp(prefix="ladderc-bigbody-")
NVARS = 64  # variables of each kind the rungs cycle through


def ld_xml(n):
    head = '''<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201" xmlns:xhtml="http://www.w3.org/1999/xhtml">
<fileHeader companyName="x" productName="x" productVersion="1" creationDateTime="2026-01-01T00:00:00"/>
<contentHeader name="t"><coordinateInfo><fbd><scaling x="0" y="0"/></fbd><ld><scaling x="0" y="0"/></ld><sfc><scaling x="0" y="0"/></sfc></coordinateInfo></contentHeader>
<types><dataTypes/><pous>
'''
    v = []
    for i in range(NVARS):
        v.append(f'<variable name="x{i}"><type><BOOL/></type></variable>')
        v.append(f'<variable name="y{i}"><type><BOOL/></type></variable>')
        v.append(f'<variable name="k{i}"><type><INT/></type></variable>')
        v.append(f'<variable name="t{i}"><type><derived name="TON"/></type></variable>')
        v.append(f'<variable name="c{i}"><type><derived name="CTU"/></type></variable>')
    out = [head, '<pou name="main" pouType="program"><interface><localVars>', "".join(v),
           '</localVars></interface><body><LD>']
    ids = [1]

    def nid():
        ids[0] += 1
        return ids[0]

    def pos():
        return '<position x="0" y="0"/>'

    for r in range(n):
        a, b = r % NVARS, (r * 7 + 3) % NVARS
        rail = nid()
        out.append(f'<leftPowerRail localId="{rail}">{pos()}<connectionPointOut formalParameter=""/></leftPowerRail>')
        kind = r % 7
        if r % 50 == 25 and r + 2 < n:
            c = nid()
            j = nid()
            out.append(f'<contact localId="{c}">{pos()}<connectionPointIn><connection refLocalId="{rail}"/></connectionPointIn><variable>x{a}</variable></contact>')
            out.append(f'<jump localId="{j}" label="J{r}">{pos()}<connectionPointIn><connection refLocalId="{c}"/></connectionPointIn></jump>')
            continue
        if r % 50 == 27:
            out.append(f'<label localId="{nid()}" label="J{r - 2}">{pos()}</label>')
            rail2 = nid()
            out.append(f'<leftPowerRail localId="{rail2}">{pos()}<connectionPointOut formalParameter=""/></leftPowerRail>')
            rail = rail2
        if kind in (0, 1, 2):
            c1, c2, co = nid(), nid(), nid()
            neg = "true" if kind == 1 else "false"
            edge = ' edge="rising"' if kind == 2 else ""
            storage = ' storage="set"' if kind == 2 else (' storage="reset"' if kind == 1 else "")
            out.append(f'<contact localId="{c1}" negated="false"{edge}>{pos()}<connectionPointIn><connection refLocalId="{rail}"/></connectionPointIn><connectionPointOut/><variable>x{a}</variable></contact>')
            out.append(f'<contact localId="{c2}" negated="{neg}">{pos()}<connectionPointIn><connection refLocalId="{c1}"/></connectionPointIn><connectionPointOut/><variable>y{b}</variable></contact>')
            out.append(f'<coil localId="{co}" negated="false"{storage}>{pos()}<connectionPointIn><connection refLocalId="{c2}"/></connectionPointIn><connectionPointOut/><variable>y{a}</variable></coil>')
        elif kind == 3:  # TON
            c1, pt, bl, co = nid(), nid(), nid(), nid()
            out.append(f'<contact localId="{c1}" negated="false">{pos()}<connectionPointIn><connection refLocalId="{rail}"/></connectionPointIn><connectionPointOut/><variable>x{a}</variable></contact>')
            out.append(f'<inVariable localId="{pt}">{pos()}<connectionPointOut/><expression>T#30ms</expression></inVariable>')
            out.append(f'<block localId="{bl}" typeName="TON" instanceName="t{a}">{pos()}<inputVariables>'
                       f'<variable formalParameter="IN"><connectionPointIn><connection refLocalId="{c1}"/></connectionPointIn></variable>'
                       f'<variable formalParameter="PT"><connectionPointIn><connection refLocalId="{pt}"/></connectionPointIn></variable>'
                       '</inputVariables><inOutVariables/><outputVariables><variable formalParameter="Q"><connectionPointOut/></variable>'
                       '<variable formalParameter="ET"><connectionPointOut/></variable></outputVariables></block>')
            out.append(f'<coil localId="{co}" negated="false">{pos()}<connectionPointIn><connection refLocalId="{bl}" formalParameter="Q"/></connectionPointIn><connectionPointOut/><variable>y{b}</variable></coil>')
        elif kind == 4:  # CTU
            c1, c2, pv, bl, co, o = nid(), nid(), nid(), nid(), nid(), nid()
            out.append(f'<contact localId="{c1}" negated="false">{pos()}<connectionPointIn><connection refLocalId="{rail}"/></connectionPointIn><connectionPointOut/><variable>x{a}</variable></contact>')
            out.append(f'<contact localId="{c2}" negated="false">{pos()}<connectionPointIn><connection refLocalId="{rail}"/></connectionPointIn><connectionPointOut/><variable>y{b}</variable></contact>')
            out.append(f'<inVariable localId="{pv}">{pos()}<connectionPointOut/><expression>10</expression></inVariable>')
            out.append(f'<block localId="{bl}" typeName="CTU" instanceName="c{a}">{pos()}<inputVariables>'
                       f'<variable formalParameter="CU"><connectionPointIn><connection refLocalId="{c1}"/></connectionPointIn></variable>'
                       f'<variable formalParameter="R"><connectionPointIn><connection refLocalId="{c2}"/></connectionPointIn></variable>'
                       f'<variable formalParameter="PV"><connectionPointIn><connection refLocalId="{pv}"/></connectionPointIn></variable>'
                       '</inputVariables><inOutVariables/><outputVariables><variable formalParameter="Q"><connectionPointOut/></variable>'
                       '<variable formalParameter="CV"><connectionPointOut/></variable></outputVariables></block>')
            out.append(f'<coil localId="{co}" negated="false">{pos()}<connectionPointIn><connection refLocalId="{bl}" formalParameter="Q"/></connectionPointIn><connectionPointOut/><variable>y{a}</variable></coil>')
            out.append(f'<outVariable localId="{o}">{pos()}<connectionPointIn><connection refLocalId="{bl}" formalParameter="CV"/></connectionPointIn><expression>k{a}</expression></outVariable>')
        else:  # GT compare, then ADD on the same rung
            i1, i2, bl, co = nid(), nid(), nid(), nid()
            out.append(f'<inVariable localId="{i1}">{pos()}<connectionPointOut/><expression>k{a}</expression></inVariable>')
            out.append(f'<inVariable localId="{i2}">{pos()}<connectionPointOut/><expression>{r % 20}</expression></inVariable>')
            out.append(f'<block localId="{bl}" typeName="GT">{pos()}<inputVariables>'
                       f'<variable formalParameter="IN1"><connectionPointIn><connection refLocalId="{i1}"/></connectionPointIn></variable>'
                       f'<variable formalParameter="IN2"><connectionPointIn><connection refLocalId="{i2}"/></connectionPointIn></variable>'
                       '</inputVariables><inOutVariables/><outputVariables><variable formalParameter="OUT"><connectionPointOut/></variable></outputVariables></block>')
            out.append(f'<coil localId="{co}" negated="false">{pos()}<connectionPointIn><connection refLocalId="{bl}" formalParameter="OUT"/></connectionPointIn><connectionPointOut/><variable>x{b}</variable></coil>')
    out.append('</LD></body></pou>\n</pous></types></project>\n')
    return "".join(out)


def il_text(n):
    decl = "".join(f"x{i}, y{i} : BOOL; k{i} : INT; t{i} : TON; c{i} : CTU; e{i} : R_TRIG;\n" for i in range(NVARS))
    body = []
    for r in range(n):
        a, b = r % NVARS, (r * 7 + 3) % NVARS
        kind = r % 7
        if r % 50 == 25 and r + 2 < n:
            body.append(f"LD x{a}\nJMPC J{r}\n")
            continue
        if r % 50 == 27:
            body.append(f"J{r - 2}:\n")
        if kind == 0:
            body.append(f"LD x{a}\nAND y{b}\nST y{a}\n")
        elif kind == 1:
            body.append(f"LD x{a}\nANDN y{b}\nR y{a}\n")
        elif kind == 2:
            body.append(f"CAL e{a}(CLK := x{a})\nLD e{a}.Q\nAND y{b}\nS y{a}\n")
        elif kind == 3:
            body.append(f"CAL t{a}(IN := x{a}, PT := T#30ms)\nLD t{a}.Q\nST y{b}\n")
        elif kind == 4:
            body.append(f"CAL c{a}(CU := x{a}, R := y{b}, PV := 10)\nLD c{a}.Q\nST y{a}\nLD c{a}.CV\nST k{a}\n")
        else:
            body.append(f"LD k{a}\nGT {r % 20}\nST x{b}\n")
    return f"PROGRAM main\nVAR\n{decl}END_VAR\n{''.join(body)}END_PROGRAM\n"


def st_text(n):
    decl = "".join(f"x{i}, y{i} : BOOL; k{i} : INT; t{i} : TON; c{i} : CTU; e{i} : R_TRIG;\n" for i in range(NVARS))
    body = []
    for r in range(n):
        a, b = r % NVARS, (r * 7 + 3) % NVARS
        kind = r % 7
        if kind == 0:
            body.append(f"y{a} := x{a} AND y{b};\n")
        elif kind == 1:
            body.append(f"IF x{a} AND NOT y{b} THEN y{a} := FALSE; END_IF;\n")
        elif kind == 2:
            body.append(f"e{a}(CLK := x{a}); IF e{a}.Q AND y{b} THEN y{a} := TRUE; END_IF;\n")
        elif kind == 3:
            body.append(f"t{a}(IN := x{a}, PT := T#30ms); y{b} := t{a}.Q;\n")
        elif kind == 4:
            body.append(f"c{a}(CU := x{a}, R := y{b}, PV := 10); y{a} := c{a}.Q; k{a} := c{a}.CV;\n")
        elif kind == 5:
            body.append(f"x{b} := k{a} > {r % 20};\n")
        else:
            body.append(f"k{b} := k{a} + {r % 20} * 2;\n")
    return f"PROGRAM main\nVAR\n{decl}END_VAR\n{''.join(body)}END_PROGRAM\n"


def sfc_text(n):
    steps = max(2, n // 10)
    decl = "".join(f"x{i}, y{i} : BOOL; k{i} : INT;\n" for i in range(NVARS))
    body = ["INITIAL_STEP S0:\n  A0(N);\nEND_STEP\n"]
    for s in range(1, steps):
        body.append(f"STEP S{s}:\n  A{s % NVARS}(N);\n  y{s % NVARS}(S);\nEND_STEP\n")
    for s in range(steps):
        nxt = (s + 1) % steps
        body.append(f"TRANSITION FROM S{s} TO S{nxt} := x{s % NVARS} OR S{s}.T >= T#20ms; END_TRANSITION\n")
    for a in range(min(NVARS, steps)):
        body.append(f"ACTION A{a}:\n  k{a} := k{a} + 1;\nEND_ACTION\n")
    return f"PROGRAM main\nVAR\n{decl}END_VAR\n{''.join(body)}END_PROGRAM\n"


GEN = {"ld": ("xml", ld_xml), "il": ("il", il_text), "st": ("st", st_text), "sfc": ("st", sfc_text)}

WRAPPER = """#!/bin/sh
exec /usr/bin/time -a -o "$CCLOG" -f "%U %S" {cc} "$@"
"""


def build(ladderc, path, outdir):
    log = outdir + ".cclog"
    wrapper = outdir + ".cc.sh"
    with open(wrapper, "w") as f:
        f.write(WRAPPER.format(cc=os.environ.get("CC", "cc")))
    os.chmod(wrapper, 0o755)
    if os.path.exists(log):
        os.remove(log)
    env = dict(os.environ, CC=wrapper, CCLOG=log)
    t0 = time.time()
    r0 = os.times()
    p = subprocess.run([ladderc, "--message-format", "short", "run", "--cycles", "1", "--watch", "main.x0", path],
                       env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    wall = time.time() - t0
    r1 = os.times()
    cpu = (r1.children_user - r0.children_user) + (r1.children_system - r0.children_system)
    cc = 0.0
    if os.path.exists(log):
        for line in open(log):
            parts = line.split()
            if len(parts) == 2:
                cc += float(parts[0]) + float(parts[1])
    err = p.stderr.decode(errors="replace").splitlines()
    return p.returncode, wall, cpu - cc, cc, (err[0][:100] if err else "")


def main():
    args = sys.argv[1:]
    langs = [a for a in args if a in GEN] or list(GEN)
    sizes = [int(a) for a in args if a.isdigit()] or [2500, 5000, 10000, 20000, 40000]
    bins = [("after", os.path.abspath(os.environ.get("LADDERC", "target/release/ladderc")))]
    if os.environ.get("LADDERC_BEFORE"):
        bins.insert(0, ("before", os.path.abspath(os.environ["LADDERC_BEFORE"])))
    os.makedirs(OUT, exist_ok=True)
    print(f"{'lang':4} {'N':>6} {'binary':6} {'exit':>4} {'wall s':>7} {'ladderc CPU s':>13} {'cc CPU s':>9}", flush=True)
    for lang in langs:
        ext, gen = GEN[lang]
        for n in sizes:
            path = os.path.join(OUT, f"{lang}_{n}.{ext}")
            with open(path, "w") as f:
                f.write(gen(n))
            for label, exe in bins:
                outdir = os.path.join(OUT, f"{lang}_{n}_{label}")
                code, wall, own, cc, first = build(exe, path, outdir)
                print(f"{lang:4} {n:>6} {label:6} {code:>4} {wall:>7.2f} {own:>13.2f} {cc:>9.2f}  {first}", flush=True)


if __name__ == "__main__":
    main()
