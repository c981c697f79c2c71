#!/usr/bin/env python3
"""Hostile inputs for issue #12, run end to end through the `ladderc` binary. Drive scripts: deep parentheses, long chains, overfull Motion and Event pools, multi-byte names, lone-CR line
ends, long lines, big literals.

Each input is written under $OUT (a fresh temporary folder by default; nothing here belongs in the
repository) and run; a line starting with BAD exited with something other than 0, 1 or 2, took over 20 s
or printed over 20 MB. Usage, from the repository root: LADDERC=target/debug/ladderc python3
fuzz/hostile/drive.py [input names]
"""
import os, tempfile
LADDERC = os.path.abspath(os.environ.get("LADDERC", "target/debug/ladderc"))
OUT = os.environ.get("OUT") or tempfile.mkdtemp(prefix="ladderc-hostile-")
import subprocess, time, os
L=LADDERC; D=os.path.join(OUT, "drive"); os.makedirs(D, exist_ok=True)
base=open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../crates/drive-script/tests/scripts/three_motions.ds")).read()
N=100_000
c={}
c["d_paren.ds"]="S:: PARAM;\nS:: P0 = "+"("*N+"1"+")"*N+";\n"
c["d_chain.ds"]="S:: PARAM;\nS:: P0 = "+" + ".join(["1"]*N)+";\n"
c["d_and.ds"]="S:: MOTION 0;\nS:: EVENT 0;\nS:: IF "+" AND ".join(["MD0 = 0"]*N)+";\nS:: THEN MD0 = 1;\n"
c["d_events.ds"]="S:: MOTION 0;\n"+"".join(f"S:: EVENT {i};\nS:: IF MD0 = {i};\nS:: THEN MD0 = {i+1};\n" for i in range(20000))
c["d_motions.ds"]="".join(f"S:: MOTION {i};\nS:: EVENT 0;\nS:: IF MD0 = 0;\nS:: THEN MD0 = 1;\n" for i in range(20000))
c["d_mb.ds"]=base.replace("MD0", "M€D0")
c["d_mb_end.ds"]=base+"S:: P0 = '€"
c["d_cr.ds"]=base.replace("\n","\r")
c["d_longline.ds"]="S:: PARAM;\nS:: P0 = 1 "+"x"*N*10+";\n"
c["d_bignum.ds"]="S:: PARAM;\nS:: P0 = "+"9"*1000+";\n"
c["d_mutate.ds"]=base*200
for name,t in c.items(): open(os.path.join(D,name),"w").write(t)
for name in c:
    for mode in (["drive","build","-o",os.path.join(D,name+".img")], ["drive","run","--cycles","20"]):
        t=time.time()
        try:
            p=subprocess.run([L]+mode[:2]+["--message-format","short"]+mode[2:]+[os.path.join(D,name)],capture_output=True,timeout=25); code=p.returncode; out=len(p.stdout)+len(p.stderr); err=p.stderr.decode('utf8','replace')
        except subprocess.TimeoutExpired: code='TIMEOUT'; out=0; err=''
        dt=time.time()-t
        bad = code not in (0,1,2) or dt>20 or out>20e6
        print(f"{'BAD ' if bad else '    '}{name:16} {mode[1]:5} exit={code} {dt:6.2f}s out={out:>9} {err.splitlines()[0][:140] if err else ''}", flush=True)
