#!/usr/bin/env python3
"""Hostile inputs for issue #12, run end to end through the `ladderc` binary. PLCopen XML: nested elements, huge and many attributes, 100,000 connections into one input, 20,000-block
FBD chains, 20,000 LD rungs, 5,000 POUs, 20,000 SFC steps, a multi-byte character cut at the end of the file.

Each input is written under $OUT (a fresh temporary folder by default; nothing here belongs in the
repository) and run; a line starting with BAD exited with something other than 0, 1 or 2, took over 20 s
or printed over 20 MB. Usage, from the repository root: LADDERC=target/debug/ladderc python3
fuzz/hostile/xml.py [input names]
"""
import os, sys
from text import run, OUT
D = os.path.join(OUT, "text")
N=100_000
head='''<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201" xmlns:xhtml="http://www.w3.org/1999/xhtml">
<fileHeader companyName="x" productName="x" productVersion="1" creationDateTime="2026-01-01T00:00:00"/>
<contentHeader name="t"><coordinateInfo><fbd><scaling x="0" y="0"/></fbd><ld><scaling x="0" y="0"/></ld><sfc><scaling x="0" y="0"/></sfc></coordinateInfo></contentHeader>
<types><dataTypes/><pous>
'''
tail='</pous></types></project>\n'
def pou(body, vars='<variable name="a"><type><INT/></type></variable><variable name="b"><type><BOOL/></type></variable>', name="main"):
    return f'<pou name="{name}" pouType="program"><interface><localVars>{vars}</localVars></interface><body>{body}</body></pou>\n'
c={}
c["x_nest.xml"]=head+pou("<ST><xhtml:p>"+"<a>"*N+"</a>"*N+"</xhtml:p></ST>")+tail
c["x_attr.xml"]=head+pou('<ST><xhtml:p x="'+"€"*N*5+'"><![CDATA[a := 1;]]></xhtml:p></ST>')+tail
c["x_attrs.xml"]=head+pou('<ST><xhtml:p '+" ".join(f'a{i}="1"' for i in range(N))+'><![CDATA[a := 1;]]></xhtml:p></ST>')+tail
c["x_name.xml"]=head+pou('<ST><xhtml:p><![CDATA[a := 1;]]></xhtml:p></ST>', name="m"*N)+tail
# FBD: one block with many inputs connected; a chain of N ADD blocks
fb=['<FBD>','<inVariable localId="1"><position x="0" y="0"/><connectionPointOut/><expression>a</expression></inVariable>']
prev=1
for i in range(2, 20002):
    fb.append(f'<block localId="{i}" typeName="ADD"><position x="0" y="0"/><inputVariables><variable formalParameter="IN1"><connectionPointIn><connection refLocalId="{prev}"/></connectionPointIn></variable><variable formalParameter="IN2"><connectionPointIn><connection refLocalId="1"/></connectionPointIn></variable></inputVariables><inOutVariables/><outputVariables><variable formalParameter="OUT"><connectionPointOut/></variable></outputVariables></block>')
    prev=i
fb.append(f'<outVariable localId="99999"><position x="0" y="0"/><connectionPointIn><connection refLocalId="{prev}" formalParameter="OUT"/></connectionPointIn><expression>a</expression></outVariable></FBD>')
c["x_fbd_chain.xml"]=head+pou("".join(fb))+tail
# many connections into one input
conns="".join(f'<connection refLocalId="1"/>' for i in range(N))
c["x_conns.xml"]=head+pou(f'<FBD><inVariable localId="1"><position x="0" y="0"/><connectionPointOut/><expression>b</expression></inVariable><outVariable localId="2"><position x="0" y="0"/><connectionPointIn>{conns}</connectionPointIn><expression>b</expression></outVariable></FBD>')+tail
# LD: N rungs
ld=['<LD><leftPowerRail localId="1"><position x="0" y="0"/><connectionPointOut formalParameter=""/></leftPowerRail>']
for i in range(20000):
    a=10+3*i
    ld.append(f'<contact localId="{a}" negated="false"><position x="0" y="0"/><connectionPointIn><connection refLocalId="1"/></connectionPointIn><connectionPointOut/><variable>b</variable></contact><coil localId="{a+1}" negated="false"><position x="0" y="0"/><connectionPointIn><connection refLocalId="{a}"/></connectionPointIn><connectionPointOut/><variable>b</variable></coil>')
ld.append('</LD>')
c["x_ld_rungs.xml"]=head+pou("".join(ld))+tail
c["x_pous.xml"]=head+"".join(pou('<ST><xhtml:p><![CDATA[a := a + 1;]]></xhtml:p></ST>', name=f"p{i}") for i in range(5000))+tail
c["x_mb_end.xml"]=(head+pou('<ST><xhtml:p><![CDATA[a := 1;]]></xhtml:p></ST>')+tail)[:-30]+"€"
c["x_entity.xml"]=head+pou('<ST><xhtml:p>'+"&amp;"*N+'</xhtml:p></ST>')+tail
c["x_sfc_steps.xml"]=head+pou('<SFC>'+"".join(f'<step localId="{i}" name="S{i}" initialStep="{"true" if i==1 else "false"}"><position x="0" y="0"/></step>' for i in range(1,20000))+'</SFC>')+tail
if __name__=="__main__":
    sel=sys.argv[1:] or list(c)
    os.makedirs(D, exist_ok=True)
    for name in sel:
        open(os.path.join(D,name),"w").write(c[name])
    for name in sel:
        for mode in (["check"], ["build","-o",os.path.join(D,"out_"+name)]):
            code, dt, out, err, bad = run(name, ["--message-format","short"]+mode)
            first = err.splitlines()[0][:140] if err else ''
            print(f"{'BAD ' if bad else '    '}{name:20} {mode[0]:5} exit={code} {dt:6.2f}s out={out:>9}  {first}", flush=True)
