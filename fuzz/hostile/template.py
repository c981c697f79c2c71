#!/usr/bin/env python3
"""Hostile inputs for issue #12, run end to end through the `ladderc` binary. Parameter templates: hostile values in every attribute (multi-byte, huge, injected C), 100,000 locals,
20,000 parameters, bodies with deep brackets, trigraphs, digraphs, splices, UCNs, `]]>`, `__asm__`.

Each input is written under $OUT (a fresh temporary folder by default; nothing here belongs in the
repository) and run; a line starting with BAD exited with something other than 0, 1 or 2, took over 20 s
or printed over 20 MB. Usage, from the repository root: LADDERC=target/debug/ladderc python3
fuzz/hostile/template.py [input names]
"""
import os, tempfile
LADDERC = os.path.abspath(os.environ.get("LADDERC", "target/debug/ladderc"))
OUT = os.environ.get("OUT") or tempfile.mkdtemp(prefix="ladderc-hostile-")
import subprocess, os, time, shutil
L=LADDERC; D=os.path.join(OUT, "template"); os.makedirs(D, exist_ok=True)
PROGRAM="PROGRAM main\nVAR\n    blk : ACME_Demo;\n    go : BOOL := TRUE;\n    done : BOOL;\nEND_VAR\n    CAL blk(Execute := go, Position := 2.5)\n    LD blk.Done\n    ST done\nEND_PROGRAM\n"
def T(name="ACME_Demo", func="90", p1=('Execute','Ex','input','bool','BOOL','required="true"'), local="", body="Dn = Ex;", extra_params=""):
    n,a,d,c,t,r=p1
    return (f'<blockTemplate name="{name}" funcNum="{func}">\n  <parameters>\n    <param name="{n}" abbr="{a}" direction="{d}" class="{c}" type="{t}" {r}/>\n'
            '    <param name="Position" abbr="Pos" direction="input" class="lreal" type="LREAL" default="0.0"/>\n'
            '    <param name="Done" abbr="Dn" direction="output" class="bool" type="BOOL"/>\n' + extra_params +
            f'  </parameters>\n  {local}\n  <body><![CDATA[\n{body}\n]]></body>\n</blockTemplate>\n')
mb="€𝄞"
cases={
 "ok": T(),
 "name_mb": T(name="ACME_Demo"+mb),
 "func_huge": T(func="9"*40),
 "func_neg": T(func="-1"),
 "func_mb": T(func="9"+mb),
 "pname_mb": T(p1=('Exe'+mb,'Ex','input','bool','BOOL','required="true"')),
 "abbr_mb": T(p1=('Execute','E'+mb,'input','bool','BOOL','required="true"')),
 "abbr_long": T(p1=('Execute','E'*100000,'input','bool','BOOL','required="true"')),
 "dir_mb": T(p1=('Execute','Ex','in'+mb,'bool','BOOL','required="true"')),
 "class_mb": T(p1=('Execute','Ex','input','bo'+mb,'BOOL','required="true"')),
 "type_mb": T(p1=('Execute','Ex','input','bool','BO'+mb,'required="true"')),
 "type_huge_string": T(p1=('Execute','Ex','input','bool','STRING[2147483647]','required="true"')),
 "type_array": T(p1=('Execute','Ex','input','bool','ARRAY[0..2147483647] OF BOOL','required="true"')),
 "required_mb": T(p1=('Execute','Ex','input','bool','BOOL','required="'+mb+'"')),
 "default_mb": T(p1=('Execute','Ex','input','bool','BOOL','default="'+mb+'"')),
 "default_inj": T(p1=('Execute','Ex','input','bool','BOOL','default="1); system(&quot;x&quot;); ("')),
 "local_mb": T(local='<local name="t'+mb+'" ctype="int"/>'),
 "local_ctype_inj": T(local='<local name="t" ctype="int; } void evil(void) { "/>'),
 "local_many": T(local="".join(f'<local name="t{i}" ctype="int"/>' for i in range(100000))),
 "params_many": T(extra_params="".join(f'    <param name="P{i}" abbr="P{i}" direction="input" class="bool" type="BOOL"/>\n' for i in range(20000))),
 "body_deep": T(body="{"*100000+"}"*100000),
 "body_paren": T(body="Dn = "+"("*100000+"Ex"+")"*100000+";"),
 "body_long": T(body="Dn = Ex;\n"*200000),
 "body_mb": T(body="Dn = Ex; /* "+mb+" */"),
 "body_str": T(body='Dn = Ex; const char *s = "'+mb+'\\";'),
 "body_unterminated_comment": T(body="Dn = Ex; /* "+mb),
 "body_trigraph": T(body="Dn = Ex; ??= ??/\n"),
 "body_cdata_end": T(body="Dn = Ex; ]]> <x/>"),
 "body_asm": T(body='__asm__("nop"); Dn = Ex;'),
 "body_goto": T(body='goto x; x: Dn = Ex;'),
 "body_return_struct": T(body='return; }\nint evil(void) { return 0;'),
 "body_backslash_nl": T(body='Dn = Ex; // a \\\n} int evil;'),
 "body_digraph": T(body='Dn = Ex; <% %> %: %:%:'),
 "body_ucn": T(body='int \\u20AC = 1; Dn = Ex;'),
 "body_mb_ident": T(body='int €x = 1; Dn = Ex;'),
 "nested_xml": T(local="<a>"*100000+"</a>"*100000),
 "entity": T(body="&amp;"*1000),
 "empty": "",
 "mb_only": mb*10000,
}
for name, text in cases.items():
    d=os.path.join(D,name); shutil.rmtree(d, ignore_errors=True); os.makedirs(os.path.join(d,"tpl"))
    open(os.path.join(d,"main.il"),"w").write(PROGRAM)
    open(os.path.join(d,"tpl","ACME_Demo.xml"),"w").write(text)
    for mode in (["build","--strategy","template","-o","out"], ["run","--strategy","template","--cycles","2"]):
        t=time.time()
        try:
            p=subprocess.run([L]+mode+["--message-format","short","--templates","tpl","main.il"],cwd=d,capture_output=True,timeout=25); code=p.returncode; out=len(p.stdout)+len(p.stderr); err=p.stderr.decode('utf8','replace')
        except subprocess.TimeoutExpired: code='TIMEOUT'; out=0; err=''
        dt=time.time()-t
        bad = code not in (0,1,2) or dt>20 or out>20e6 or "bug in ladderc" in err or ("error: " in err and ".c:" in err)
        print(f"{'BAD ' if bad else '    '}{name:26} {mode[0]:5} exit={code} {dt:6.2f}s out={out:>8} {err.splitlines()[0][:130] if err else ''}", flush=True)
