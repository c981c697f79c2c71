#!/usr/bin/env python3
"""Hostile inputs for issue #12, run end to end through the `ladderc` binary. IL and ST: 100,000-level nesting in every syntactic position, long chains and huge counts (POUs, variables,
labels, jumps, CASE labels, array and string sizes), multi-byte characters at every boundary, lone-CR line ends.

Each input is written under $OUT (a fresh temporary folder by default; nothing here belongs in the
repository) and run; a line starting with BAD exited with something other than 0, 1 or 2, took over 20 s
or printed over 20 MB. Usage, from the repository root: LADDERC=target/debug/ladderc python3
fuzz/hostile/text.py [input names]
"""
import os, tempfile
LADDERC = os.path.abspath(os.environ.get("LADDERC", "target/debug/ladderc"))
OUT = os.environ.get("OUT") or tempfile.mkdtemp(prefix="ladderc-hostile-")
import subprocess, sys, time, os
L = LADDERC
D = os.path.join(OUT, "text")
os.makedirs(D, exist_ok=True)
N = 100_000
def prog(decl, body, kind="PROGRAM main", end="END_PROGRAM"):
    return f"{kind}\nVAR\n{decl}\nEND_VAR\n{body}\n{end}\n"
cases = {}
# --- ST: deep nesting in every syntactic position
cases["st_paren.st"] = prog("x : INT;", "x := " + "("*N + "1" + ")"*N + ";")
cases["st_not.st"] = prog("b : BOOL;", "b := " + "NOT "*N + "b;")
cases["st_neg.st"] = prog("x : INT;", "x := " + "-"*N + "x;")
cases["st_call.st"] = prog("x : INT;", "x := " + "ABS("*N + "x" + ")"*N + ";")
cases["st_index.st"] = prog("v : ARRAY[0..1] OF INT;", "v[0] := " + "v["*N + "0" + "]"*N + ";")
cases["st_index_lhs.st"] = prog("v : ARRAY[0..1] OF INT;", "v[" + "v["*N + "0" + "]"*N + "] := 1;")
cases["st_if.st"] = prog("x : INT;", "IF TRUE THEN\n"*N + "x := 1;\n" + "END_IF;\n"*N)
cases["st_case.st"] = prog("x : INT;", "CASE x OF 1:\n"*N + "x := 1;\n" + "END_CASE;\n"*N)
cases["st_for.st"] = prog("i : INT;", "FOR i := 1 TO 2 DO\n"*N + "i := 1;\n" + "END_FOR;\n"*N)
cases["st_while.st"] = prog("b : BOOL;", "WHILE b DO\n"*N + "b := FALSE;\n" + "END_WHILE;\n"*N)
cases["st_repeat.st"] = prog("b : BOOL;", "REPEAT\n"*N + "b := TRUE;\n" + "UNTIL b END_REPEAT;\n"*N)
cases["st_member.st"] = prog("x : INT;", "x := x" + ".y"*N + ";")
cases["st_elsif.st"] = prog("x : INT;", "IF x = 0 THEN x := 1;\n" + "".join(f"ELSIF x = {i} THEN x := {i};\n" for i in range(1, 20000)) + "END_IF;")
cases["st_case_labels.st"] = prog("x : DINT;", "CASE x OF\n" + "".join(f"{i}: x := {i};\n" for i in range(N)) + "END_CASE;")
cases["st_case_range.st"] = prog("x : DINT;", "CASE x OF\n" + ",".join(f"{i}..{i}" for i in range(N)) + ": x := 1;\nEND_CASE;")
cases["st_stmts.st"] = prog("x : DINT; a : DINT := 1;", "x := x / a;\n"*20000)
cases["st_struct_type.st"] = "TYPE\n" + "".join(f"S{i} : STRUCT a : S{i+1}; END_STRUCT;\n" for i in range(5000)) + "S5000 : STRUCT a : INT; END_STRUCT;\nEND_TYPE\n" + prog("s : S0;", "s" + ".a"*5001 + " := 1;")
cases["st_call_args.st"] = prog("x : INT;", "x := MAX(" + ",".join(["x"]*N) + ");")
cases["st_formal_args.st"] = "FUNCTION f : INT\nVAR_INPUT a : INT; END_VAR\nf := a;\nEND_FUNCTION\n" + prog("x : INT;", "x := f(" + ",".join(["a := x"]*20000) + ");")
# --- IL
cases["il_labels.il"] = prog("x : INT;", "".join(f"L{i}: LD x\n" for i in range(N)) + "".join(f"JMP L{i}\n" for i in range(0, N, 7)))
cases["il_jmps.il"] = prog("x : INT;", "L0: LD x\n" + "JMPC L0\n"*N)
cases["il_dup_labels.il"] = prog("x : INT;", "L: LD x\n"*20000)
cases["il_nested_mixed.il"] = prog("x : INT;", "LD x\n" + "".join(["ADD(", "AND(", "MUL(", "GT("][i%4] + " x\n" for i in range(3000)) + ")\n"*3000 + "ST x")
cases["il_vars.il"] = "PROGRAM main\nVAR\n" + "".join(f"v{i} : INT := {i};\n" for i in range(N)) + "END_VAR\nLD v0\nST v1\nEND_PROGRAM\n"
cases["il_pous.il"] = "".join(f"FUNCTION f{i} : INT\nVAR_INPUT a : INT; END_VAR\nLD a\nST f{i}\nEND_FUNCTION\n" for i in range(20000)) + prog("x : INT;", "LD x\nf19999\nST x")
cases["il_call_chain.il"] = "".join(f"FUNCTION f{i} : INT\nVAR_INPUT a : INT; END_VAR\nLD a\n{'f'+str(i-1) if i else 'ADD 1'}\nST f{i}\nEND_FUNCTION\n" for i in range(5000)) + prog("x : INT;", "LD x\nf4999\nST x")
cases["il_fb_chain.il"] = "".join(f"FUNCTION_BLOCK b{i}\nVAR_INPUT a : INT; END_VAR\nVAR " + (f"i : b{i-1};" if i else "q : INT;") + " END_VAR\n" + (f"CAL i(a := a)\n" if i else "LD a\nST q\n") + "END_FUNCTION_BLOCK\n" for i in range(3000)) + prog("k : b2999;", "CAL k(a := 1)")
cases["il_array_huge.il"] = prog("v : ARRAY[0..2147483647] OF INT;", "LD 1\nST v[0]")
cases["il_array_neg.il"] = prog("v : ARRAY[-2147483648..2147483647] OF BYTE;", "LD 1\nST v[0]")
cases["il_array_md.il"] = prog("v : ARRAY[0..65535, 0..65535, 0..65535] OF LREAL;", "LD 1\nST v[0,0,0]")
cases["il_string_huge.il"] = prog("s : STRING[2147483647];", "LD 'a'\nST s")
cases["il_string_huge2.il"] = prog("s : STRING[4294967295];", "LD 'a'\nST s")
cases["il_string_huge3.il"] = prog("s : WSTRING[99999999999999999999999];", "LD \"a\"\nST s")
cases["il_string_big_ok.il"] = prog("s : STRING[65535];", "LD 'a'\nST s")
cases["il_array_of_strings.il"] = prog("s : ARRAY[0..100000] OF STRING[65535];", "LD 'a'\nST s[0]")
cases["il_long_string.il"] = prog("s : STRING[254];", "LD '" + "a"*1_000_000 + "'\nST s")
cases["il_long_name.il"] = prog("a" * 100_000 + " : INT;", "LD 1\nST " + "a"*100_000)
cases["il_enum_init.il"] = "TYPE E : (" + ",".join(f"e{i}" for i in range(N)) + ") := e99999; END_TYPE\n" + prog("x : E;", "LD e5\nST x")
cases["il_subrange.il"] = prog("x : INT(-170141183460469231731687303715884105728..170141183460469231731687303715884105727);", "LD 1\nST x")
cases["il_init_list.il"] = prog("v : ARRAY[0..99999] OF INT := [" + ",".join(str(i%100) for i in range(N)) + "];", "LD v[5]\nST v[6]")
# --- multi-byte at every boundary
mb = "€𝄞é"
for i, t in enumerate([
    "PROGRAM m€in\nVAR x : INT; END_VAR\nEND_PROGRAM\n",
    "PROGRAM main\nVAR x€ : INT; END_VAR\nLD x€\nEND_PROGRAM\n",
    "PROGRAM main\nVAR x : INT; END_VAR\n(* " + mb,
    "PROGRAM main\nVAR x : INT; END_VAR\nLD '" + mb,
    "PROGRAM main\nVAR x : INT; END_VAR\nLD \"" + mb,
    "PROGRAM main\nVAR x : INT; END_VAR\n{" + mb,
    "PROGRAM main\nVAR x : INT; END_VAR\nLD x // " + mb,
    "PROGRAM main\nVAR x : INT; END_VAR\nLD %IX" + mb,
    "PROGRAM main\nVAR x : INT; END_VAR\nLD 16#" + mb,
    "PROGRAM main\nVAR x : INT; END_VAR\nLD T#1" + mb,
    "PROGRAM main\nVAR x : INT; END_VAR\nLD INT#" + mb,
    "PROGRAM main\nVAR x : INT; END_VAR\nLD x\n" + mb,
    mb,
    "€" * 50000,
    "PROGRAM main\nVAR x : STRING := '" + "€"*300 + "'; END_VAR\nEND_PROGRAM\n",
    "PROGRAM main\nVAR x : INT; END_VAR\nLD x\nST x\nEND_PROGRAM\n" + "\u0301"*10,
    "\ufeff\ufeffPROGRAM main\nEND_PROGRAM\n",
    "PROGRAM main\nVAR x : INT; END_VAR\nx := '$" + mb,
    "PROGRAM main\nVAR x : INT; END_VAR\nLD x (* $€ *) €\nEND_PROGRAM",
]):
    cases[f"mb{i}.il"] = t
    cases[f"mb{i}.st"] = t.replace("LD ", "x := ")
cases["mb_pragma.st"] = prog("x : INT;", "{attribute '" + "€"*1000 + "'}\nx := 1;")
cases["mb_cr.st"] = "PROGRAM main\rVAR x : INT; END_VAR\r x := '€\r y := 1;\rEND_PROGRAM"
# --- lone CR and mixed
cases["cr_only.il"] = "\r" * N
cases["crlf_mix.st"] = ("PROGRAM main\r\nVAR x : INT; END_VAR\r" + "x := y;\n\r" * 2000 + "END_PROGRAM\r")

def run(name, args, timeout=25):
    path = os.path.join(D, name)
    t0 = time.time()
    try:
        p = subprocess.run([L] + args + [path], capture_output=True, timeout=timeout)
        code = p.returncode; out = len(p.stdout) + len(p.stderr); err = p.stderr[:300].decode('utf8', 'replace')
    except subprocess.TimeoutExpired:
        code = 'TIMEOUT'; out = 0; err = ''
    dt = time.time() - t0
    bad = code not in (0, 1, 2) or dt > 20 or out > 20_000_000
    return code, dt, out, err, bad

if __name__ == "__main__":
    sel = sys.argv[1:] or list(cases)
    for name in sel:
        open(os.path.join(D, name), "w").write(cases[name])
    for name in sel:
        for mode in (["check"], ["build", "-o", os.path.join(D, "out_" + name)]):
            code, dt, out, err, bad = run(name, ["--message-format", "short"] + mode)
            flag = "BAD " if bad else "    "
            first = err.splitlines()[0][:150] if err else ''
            print(f"{flag}{name:24} {mode[0]:5} exit={code} {dt:6.2f}s out={out:>9}  {first}", flush=True)
