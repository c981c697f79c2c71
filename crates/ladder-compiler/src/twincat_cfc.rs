//! TwinCAT 3 CFC bodies: the `<Implementation><CFC><XmlArchive>` of a `.TcPOU` (a POU, method or
//! action in the Continuous Function Chart editor), read as ST.
//!
//! The archive is a list of elements (`<o t="CFCImplementationObject">` > `Items` > `InnerList`):
//! `CFCBoxElement` (an operator, function, function block or program box: its input and output
//! pins, each with an `Id` and `Negated`, its `Texts` (the input names, the output names, the type,
//! the instance), its `KindOfCall`, `EnEno` and `Bounds` "x, y"), `CFCInputElement` (an operand
//! read: its `Output` pin and `Text`), `CFCOutputElement` (a variable written: its `Input` pin, with
//! `SetReset` None, Set or Reset, and `Text`), `CFCConnection` (`SourcePinId` -> `DestPinId`) and
//! `CFCComment` (`CFCCommentElement` in TwinCAT 4024). A method box (`KindOfCall` `Method`, type
//! `FB.Method`, instance the FB instance) is the call `inst.Method(...)`.
//!
//! Input: the `<CFC>` element and the body's name. Output: [`NwlBody`], the ST tokens of the chart,
//! each with the byte offset of the element it comes from (the caller writes them into the chart's
//! own markup, as for LD/FBD). Semantics: TwinCAT's default "automatic data flow mode" (Beckhoff
//! Infosys, TC3 PLC, "Automatic execution order by data flow"; `UseExplicitExecutionOrder` false):
//! a box runs after the boxes whose outputs it reads, and separate networks run from top to bottom,
//! then from left to right (by their topmost, leftmost element); so does an element with nothing
//! before it inside a network. A function block or program box is a call statement, its outputs read
//! as `inst.Q`; an operator or function box (an operator by its IEC name or its symbol, `SUB` or `-`:
//! `crate::twincat_operators`) is the expression of its result, written where an input
//! or output element reads it; an output element is an assignment (a set or reset output writes
//! TRUE or FALSE when its input is TRUE); a negated pin negates what passes it.
//! Invariants: never panics; an element, call kind, EN/ENO box, explicit execution order or
//! feedback loop ladderc does not read is one E0325 at the element, an open input of an operator or
//! an operand that is not one ST operand one E0326; nothing is dropped silently (comments are the
//! only elements not lowered). A function block box whose instance is `SUPER^` is the call of the
//! base block's body: its inputs (the instance's own) assigned, then `SUPER^()`.

use crate::twincat_nwl::{check_name, prop, string, tok, wrap, NwlBody, Tok};
use crate::xml::Element;
use diagnostics::{code, Diagnostic, FileId, Span};
use std::collections::{BTreeSet, HashMap};

type Res<T> = Result<T, Box<Diagnostic>>;

/// A pin of a box or element: its `Id` and whether it is negated.
#[derive(Debug, Clone)]
struct Pin {
    id: String,
    negated: bool,
}

#[derive(Debug)]
enum Kind {
    Box {
        call: String,
        type_name: String,
        instance: String,
        in_names: Vec<String>,
        out_names: Vec<String>,
        inputs: Vec<Pin>,
        outputs: Vec<Pin>,
    },
    Input {
        text: String,
        output: Pin,
    },
    Output {
        text: String,
        input: Pin,
        set_reset: String,
    },
}

struct Node<'e, 'a> {
    el: &'e Element<'a>,
    /// `Bounds` "x, y": (y, x), the order of networks and of elements without predecessors.
    pos: (i64, i64),
    kind: Kind,
}

/// Reads the `<CFC>` element `cfc` of the body named `what`.
pub(crate) fn lower(file: FileId, cfc: &Element, what: &str) -> Res<NwlBody> {
    let err = |c: diagnostics::Code, el: &Element, msg: String| -> Box<Diagnostic> {
        Box::new(
            Diagnostic::error(c, format!("TwinCAT CFC body of `{what}`: {msg}"))
                .at(Span::new(file, el.tag_start(), el.tag_end()))
                .with_hint(if c == code::E0326 {
                    "open the chart in TwinCAT and connect the input or write one variable or literal"
                } else {
                    "write this part of the chart in ST, or export the POU from TwinCAT as PLCopen \
                     XML (right-click > Export PLCopenXML), which ladderc reads"
                }),
        )
    };
    let root = cfc
        .child("XmlArchive")
        .and_then(|a| a.child("Data"))
        .and_then(|d| d.child("o"))
        .ok_or_else(|| err(code::E0325, cfc, "its archive has no chart".into()))?;
    if string(root, "UseExplicitExecutionOrder").as_deref() == Some("true") {
        return Err(err(
            code::E0325,
            cfc,
            "the chart has an explicit execution order, which ladderc does not read".into(),
        ));
    }
    let items = prop(root, "Items")
        .and_then(|i| prop(i, "InnerList"))
        .ok_or_else(|| err(code::E0325, cfc, "its archive has no element list".into()))?;
    let mut nodes: Vec<Node> = Vec::new();
    // destination pin -> source pin
    let mut wires: HashMap<String, String> = HashMap::new();
    for el in items.children.iter().filter(|e| e.name() == "o") {
        let t = el.attr("t").unwrap_or("");
        let pos = bounds(el);
        let text_of = |e: &Element| {
            prop(e, "Text")
                .map(|t| string(t, "Text").unwrap_or_default())
                .unwrap_or_default()
                .trim()
                .to_string()
        };
        match t {
            "CFCConnection" => {
                let (Some(s), Some(d)) = (string(el, "SourcePinId"), string(el, "DestPinId"))
                else {
                    return Err(err(code::E0325, el, "a connection without its pins".into()));
                };
                wires.insert(d, s);
            }
            // a comment has no semantics (TwinCAT 4024 writes `CFCCommentElement`)
            "CFCComment" | "CFCCommentElement" => {}
            "CFCInputElement" => {
                let output = prop(el, "Output").and_then(pin).ok_or_else(|| {
                    err(code::E0325, el, "an input element without its pin".into())
                })?;
                nodes.push(Node {
                    el,
                    pos,
                    kind: Kind::Input {
                        text: text_of(el),
                        output,
                    },
                });
            }
            "CFCOutputElement" => {
                let input = prop(el, "Input").and_then(pin).ok_or_else(|| {
                    err(code::E0325, el, "an output element without its pin".into())
                })?;
                let set_reset = prop(el, "Input")
                    .and_then(|i| string(i, "SetReset"))
                    .unwrap_or_else(|| "None".into());
                nodes.push(Node {
                    el,
                    pos,
                    kind: Kind::Output {
                        text: text_of(el),
                        input,
                        set_reset,
                    },
                });
            }
            "CFCBoxElement" => {
                let pins = |name: &str| -> Vec<Pin> {
                    prop(el, name)
                        .and_then(|l| prop(l, "InnerList"))
                        .map(|l| l.children.iter().filter_map(pin).collect())
                        .unwrap_or_default()
                };
                let (inputs, outputs) = (pins("Inputs"), pins("Outputs"));
                let texts: Vec<String> = prop(el, "Texts")
                    .and_then(|l| prop(l, "InnerList"))
                    .map(|l| {
                        l.children
                            .iter()
                            .map(|t| string(t, "Text").unwrap_or_default().trim().to_string())
                            .collect()
                    })
                    .unwrap_or_default();
                let (ni, no) = (inputs.len(), outputs.len());
                if texts.len() != ni + no + 2 {
                    return Err(err(
                        code::E0325,
                        el,
                        format!(
                            "a box with {ni} inputs and {no} outputs has {} texts (ladderc reads \
                             the input names, the output names, the type and the instance)",
                            texts.len()
                        ),
                    ));
                }
                if string(el, "EnEno").as_deref() == Some("true") {
                    return Err(err(
                        code::E0325,
                        el,
                        format!(
                            "box `{}` with EN/ENO, which ladderc does not read in a chart",
                            texts[ni + no]
                        ),
                    ));
                }
                nodes.push(Node {
                    el,
                    pos,
                    kind: Kind::Box {
                        call: string(el, "KindOfCall").unwrap_or_default(),
                        type_name: texts[ni + no].clone(),
                        instance: texts[ni + no + 1].clone(),
                        in_names: texts[..ni].to_vec(),
                        out_names: texts[ni..ni + no].to_vec(),
                        inputs,
                        outputs,
                    },
                });
            }
            other => {
                return Err(err(
                    code::E0325,
                    el,
                    format!("element `{other}` is not one ladderc reads in a chart"),
                ))
            }
        }
    }
    // source pin -> (node, output index)
    let mut sources: HashMap<String, (usize, usize)> = HashMap::new();
    for (k, n) in nodes.iter().enumerate() {
        match &n.kind {
            Kind::Box { outputs, .. } => {
                for (j, p) in outputs.iter().enumerate() {
                    sources.insert(p.id.clone(), (k, j));
                }
            }
            Kind::Input { output, .. } => {
                sources.insert(output.id.clone(), (k, 0));
            }
            Kind::Output { .. } => {}
        }
    }
    let inputs_of = |n: &Node| -> Vec<Pin> {
        match &n.kind {
            Kind::Box { inputs, .. } => inputs.clone(),
            Kind::Output { input, .. } => vec![input.clone()],
            Kind::Input { .. } => Vec::new(),
        }
    };
    let before: Vec<Vec<usize>> = nodes
        .iter()
        .map(|n| {
            inputs_of(n)
                .iter()
                .filter_map(|p| wires.get(&p.id).and_then(|s| sources.get(s)).map(|s| s.0))
                .collect()
        })
        .collect();
    let order = execution_order(&nodes, &before).map_err(|k| {
        err(
            code::E0325,
            nodes[k].el,
            "a feedback loop (ladderc reads charts without feedback)".into(),
        )
    })?;
    let mut l = Chart {
        nodes: &nodes,
        wires: &wires,
        sources: &sources,
        toks: Vec::new(),
        err: &err,
    };
    for k in order {
        l.statement(k)?;
    }
    Ok(NwlBody {
        what: what.to_string(),
        temps: Vec::new(),
        toks: l.toks,
    })
}

/// Data-flow order: the networks (connected elements) by their topmost, then leftmost element,
/// each in dependency order with ties by position; `Err(k)` at an element of a loop.
fn execution_order(nodes: &[Node], before: &[Vec<usize>]) -> Result<Vec<usize>, usize> {
    let n = nodes.len();
    // networks: union-find over the wires
    let mut parent: Vec<usize> = (0..n).collect();
    fn find(p: &mut [usize], mut k: usize) -> usize {
        while p[k] != k {
            p[k] = p[p[k]];
            k = p[k];
        }
        k
    }
    for (k, b) in before.iter().enumerate() {
        for &j in b {
            let (a, c) = (find(&mut parent, k), find(&mut parent, j));
            parent[a] = c;
        }
    }
    let mut key: HashMap<usize, (i64, i64)> = HashMap::new();
    for (k, node) in nodes.iter().enumerate() {
        let r = find(&mut parent, k);
        let e = key.entry(r).or_insert(node.pos);
        *e = (*e).min(node.pos);
    }
    let mut waiting: Vec<usize> = before.iter().map(Vec::len).collect();
    let mut after: Vec<Vec<usize>> = vec![Vec::new(); n];
    for (k, b) in before.iter().enumerate() {
        for &j in b {
            after[j].push(k);
        }
    }
    // (the network's place, the element's place, the element): the next to run is the least
    let mut ready: BTreeSet<(Place, Place, usize)> = BTreeSet::new();
    for k in 0..n {
        if waiting[k] == 0 {
            let r = find(&mut parent, k);
            ready.insert((key[&r], nodes[k].pos, k));
        }
    }
    let mut order = Vec::with_capacity(n);
    while let Some(first) = ready.pop_first() {
        let k = first.2;
        order.push(k);
        for &m in &after[k] {
            waiting[m] -= 1;
            if waiting[m] == 0 {
                let r = find(&mut parent, m);
                ready.insert((key[&r], nodes[m].pos, m));
            }
        }
    }
    match (0..n).find(|&k| waiting[k] > 0) {
        Some(k) => Err(k),
        None => Ok(order),
    }
}

/// A place on the chart: (y, x).
type Place = (i64, i64);

type ErrFn<'f> = dyn Fn(diagnostics::Code, &Element, String) -> Box<Diagnostic> + 'f;

struct Chart<'n, 'e, 'a, 'f> {
    nodes: &'n [Node<'e, 'a>],
    wires: &'n HashMap<String, String>,
    sources: &'n HashMap<String, (usize, usize)>,
    toks: Vec<Tok>,
    err: &'f ErrFn<'f>,
}

impl Chart<'_, '_, '_, '_> {
    /// The statement of element `k`, if it has one (block and program calls, output elements).
    fn statement(&mut self, k: usize) -> Res<()> {
        let node = &self.nodes[k];
        let at = node.el.tag_start();
        match &node.kind {
            Kind::Input { .. } => Ok(()),
            Kind::Output {
                text,
                input,
                set_reset,
            } => {
                let target = self.operand(text, node.el, true)?;
                let v = self.input(input, node.el, "the output element")?;
                match set_reset.as_str() {
                    "None" => {
                        self.toks.extend(target);
                        self.toks.push(tok(":=", at));
                        self.toks.extend(v);
                        self.toks.push(tok(";", at));
                    }
                    "Set" | "Reset" => {
                        self.toks.push(tok("IF", at));
                        self.toks.extend(v);
                        self.toks.push(tok("THEN", at));
                        self.toks.extend(target);
                        let value = if set_reset == "Set" { "TRUE" } else { "FALSE" };
                        for w in [":=", value, ";", "END_IF", ";"] {
                            self.toks.push(tok(w, at));
                        }
                    }
                    other => {
                        return Err((self.err)(
                            code::E0325,
                            node.el,
                            format!(
                            "output `{text}` with SetReset `{other}`, which ladderc does not read"
                        ),
                        ))
                    }
                }
                Ok(())
            }
            Kind::Box {
                call,
                type_name,
                instance,
                in_names,
                inputs,
                ..
            } => match call.as_str() {
                "FunctionBlock" | "Program" | "Method" => {
                    let callee = match call.as_str() {
                        "Program" => type_name.clone(),
                        // a method box: its type `FB.Method`, its instance the FB instance
                        "Method" => format!(
                            "{instance}.{}",
                            type_name.rsplit('.').next().unwrap_or_default()
                        ),
                        // a box whose instance is `SUPER^` (TF8040's templates: the base
                        // block's type, `FB_BA_View`, over `SUPER^`) is the call of the base's
                        // body, `SUPER^(...)`, as in ST (Beckhoff Infosys, TC3 PLC, "SUPER":
                        // "SUPER^() calls the body of the base function block")
                        _ if is_super(instance) => "SUPER^".to_string(),
                        _ => instance.clone(),
                    };
                    if callee != "SUPER^" && check_name(&callee).is_err() {
                        return Err((self.err)(
                            code::E0326,
                            node.el,
                            format!("box `{type_name}` does not name its instance or program (`{callee}`)"),
                        ));
                    }
                    // `SUPER^`'s inputs are the instance's own: written before the call of the
                    // base's body, `nStep := x; SUPER^();` (the inputs an FB call passes are
                    // assigned before its body runs, IEC 61131-3 ed. 3, 6.6.1.9)
                    let to_super = callee == "SUPER^";
                    let mut assigned = Vec::new();
                    let mut call_toks = vec![tok(&callee, at), tok("(", at)];
                    let mut first = true;
                    for (j, p) in inputs.iter().enumerate() {
                        if !self.wires.contains_key(&p.id) {
                            continue;
                        }
                        let name = in_names.get(j).cloned().unwrap_or_default();
                        if check_name(&name).is_err() {
                            return Err((self.err)(
                                code::E0325,
                                node.el,
                                format!(
                                    "input {} of box `{type_name}` has no parameter name",
                                    j + 1
                                ),
                            ));
                        }
                        let v =
                            self.input(p, node.el, &format!("input `{name}` of `{type_name}`"))?;
                        if to_super {
                            assigned.push(tok(&name, at));
                            assigned.push(tok(":=", at));
                            assigned.extend(v);
                            assigned.push(tok(";", at));
                            continue;
                        }
                        if !first {
                            call_toks.push(tok(",", at));
                        }
                        first = false;
                        // TwinCAT's names of the bistables' inputs (SR.SET1, RS.RESET1) are IEC's
                        let pin =
                            crate::catalogue::vendor_pin_alias(type_name, &name).unwrap_or(&name);
                        call_toks.push(tok(pin, at));
                        call_toks.push(tok(":=", at));
                        call_toks.extend(v);
                    }
                    call_toks.push(tok(")", at));
                    call_toks.push(tok(";", at));
                    self.toks.extend(assigned);
                    self.toks.extend(call_toks);
                    Ok(())
                }
                "Operator" | "Function" => Ok(()),
                other => Err((self.err)(
                    code::E0325,
                    node.el,
                    format!(
                        "box `{type_name}` of call kind `{other}`, which ladderc does not read"
                    ),
                )),
            },
        }
    }

    /// The expression that reaches input pin `p` of `el` (through its wire), negated as its pins say.
    fn input(&self, p: &Pin, el: &Element, what: &str) -> Res<Vec<Tok>> {
        let Some(&(k, j)) = self.wires.get(&p.id).and_then(|s| self.sources.get(s)) else {
            return Err((self.err)(
                code::E0326,
                el,
                format!("{what} is not connected"),
            ));
        };
        let mut v = self.output(k, j)?;
        if p.negated {
            v = negate(v, el.tag_start());
        }
        Ok(v)
    }

    /// The value of output `j` of element `k`.
    fn output(&self, k: usize, j: usize) -> Res<Vec<Tok>> {
        let node = &self.nodes[k];
        let at = node.el.tag_start();
        let (v, negated) = match &node.kind {
            Kind::Input { text, output } => (self.operand(text, node.el, false)?, output.negated),
            Kind::Output { .. } => unreachable_output(),
            Kind::Box {
                call,
                type_name,
                instance,
                in_names,
                out_names,
                inputs,
                outputs,
            } => {
                let negated = outputs.get(j).is_some_and(|p| p.negated);
                let v = match call.as_str() {
                    "FunctionBlock" | "Program" => {
                        let owner = if call == "Program" {
                            type_name
                        } else {
                            instance
                        };
                        let name = out_names.get(j).cloned().unwrap_or_default();
                        vec![tok(&format!("{owner}.{name}"), at)]
                    }
                    "Method" => {
                        let name = out_names.get(j).cloned().unwrap_or_default();
                        return Err((self.err)(
                            code::E0325,
                            node.el,
                            format!(
                                "output `{name}` of method box `{type_name}` is read: ladderc \
                                 reads method boxes whose outputs are not connected"
                            ),
                        ));
                    }
                    _ => {
                        let mut args = Vec::new();
                        for (i, p) in inputs.iter().enumerate() {
                            args.push(self.input(
                                p,
                                node.el,
                                &format!("input {} of `{type_name}`", i + 1),
                            )?);
                        }
                        let named = call == "Function"
                            && !in_names.is_empty()
                            && in_names.iter().all(|n| check_name(n).is_ok());
                        self.operator(type_name, args, named.then_some(in_names), node.el)?
                    }
                };
                (v, negated)
            }
        };
        Ok(if negated { negate(v, at) } else { v })
    }

    /// An operator's or function's result: infix for the logic, arithmetic and comparison operators.
    fn operator(
        &self,
        type_name: &str,
        args: Vec<Vec<Tok>>,
        names: Option<&Vec<String>>,
        el: &Element,
    ) -> Res<Vec<Tok>> {
        let at = el.tag_start();
        // an operator box shows its IEC name or its symbol (`-` is SUB): `twincat_operators`
        let upper = crate::twincat_operators::iec_name(type_name)
            .map_or_else(|| type_name.to_ascii_uppercase(), str::to_string);
        let infix = match upper.as_str() {
            "AND" => Some("AND"),
            "OR" => Some("OR"),
            "XOR" => Some("XOR"),
            "ADD" => Some("+"),
            "SUB" => Some("-"),
            "MUL" => Some("*"),
            "DIV" => Some("/"),
            "MOD" => Some("MOD"),
            "GT" => Some(">"),
            "GE" => Some(">="),
            "EQ" => Some("="),
            "NE" => Some("<>"),
            "LE" => Some("<="),
            "LT" => Some("<"),
            _ => None,
        };
        let two = matches!(
            upper.as_str(),
            "SUB" | "DIV" | "MOD" | "GT" | "GE" | "EQ" | "NE" | "LE" | "LT"
        );
        let mut e = Vec::new();
        match (infix, args.len()) {
            (_, 0) => {
                return Err((self.err)(
                    code::E0326,
                    el,
                    format!("box `{type_name}` has no input"),
                ))
            }
            (Some(_), n) if two && n != 2 => {
                return Err((self.err)(
                    code::E0325,
                    el,
                    format!("box `{type_name}` with {n} inputs (ladderc reads it with 2)"),
                ))
            }
            (Some(sym), _) => {
                e.push(tok("(", at));
                for (k, a) in args.into_iter().enumerate() {
                    if k > 0 {
                        e.push(tok(sym, at));
                    }
                    e.push(tok("(", at));
                    e.extend(a);
                    e.push(tok(")", at));
                }
                e.push(tok(")", at));
            }
            (None, 1) if upper == "MOVE" => e.extend(args.into_iter().flatten()),
            (None, 1) if upper == "NOT" => e = negate(args.into_iter().flatten().collect(), at),
            (None, _) => {
                if check_name(type_name).is_err() {
                    return Err((self.err)(
                        code::E0326,
                        el,
                        format!("box `{type_name}` does not name a function"),
                    ));
                }
                e.extend([tok(type_name, at), tok("(", at)]);
                for (k, a) in args.into_iter().enumerate() {
                    if k > 0 {
                        e.push(tok(",", at));
                    }
                    if let Some(n) = names.and_then(|n| n.get(k)) {
                        e.extend([tok(n, at), tok(":=", at)]);
                    }
                    e.extend(a);
                }
                e.push(tok(")", at));
            }
        }
        Ok(e)
    }

    /// An input or output element's text as tokens, checked to be one ST operand (a variable when
    /// `written`).
    fn operand(&self, text: &str, el: &Element, written: bool) -> Res<Vec<Tok>> {
        let bad = [
            "(*", "*)", "//", "/*", ";", ":=", "=>", "\n", "\r", "{", "}", "'", "\"",
        ];
        let quoted = text.len() >= 2
            && ((text.starts_with('\'') && text.ends_with('\''))
                || (text.starts_with('"') && text.ends_with('"')))
            && !text[1..text.len() - 1].contains(['\'', '"']);
        let bad = bad
            .iter()
            .find(|b| text.contains(*b) && !(quoted && (**b == "'" || **b == "\"")));
        let not_a_name = written
            && !text
                .chars()
                .next()
                .is_some_and(|c| c.is_ascii_alphabetic() || c == '_');
        if text.is_empty() || bad.is_some() || not_a_name {
            return Err((self.err)(
                code::E0326,
                el,
                format!(
                    "`{text}` is not one ST {}",
                    if written { "variable" } else { "operand" }
                ),
            ));
        }
        let at = prop(el, "Text")
            .and_then(|t| prop(t, "Text"))
            .map_or(el.tag_start(), |v| v.tag_start());
        Ok(wrap(text, at))
    }
}

/// An output element has no output: never asked for (no wire starts at it).
fn unreachable_output() -> (Vec<Tok>, bool) {
    (vec![tok("FALSE", 0)], false)
}

fn negate(v: Vec<Tok>, at: usize) -> Vec<Tok> {
    let mut e = vec![tok("NOT", at), tok("(", at)];
    e.extend(v);
    e.push(tok(")", at));
    e
}

/// A pin object: its `Id` and `Negated`.
fn pin(o: &Element) -> Option<Pin> {
    Some(Pin {
        id: string(o, "Id")?,
        negated: string(o, "Negated").as_deref() == Some("true"),
    })
}

/// `Bounds` "x, y, w, h" as (y, x).
fn bounds(el: &Element) -> (i64, i64) {
    let b = string(el, "Bounds").unwrap_or_default();
    let mut n = b.split(',').map(|s| s.trim().parse::<i64>().unwrap_or(0));
    let x = n.next().unwrap_or(0);
    let y = n.next().unwrap_or(0);
    (y, x)
}

/// A box's instance text `SUPER^` (any case, blanks around it): the box calls the base block's
/// body.
fn is_super(instance: &str) -> bool {
    let t: String = instance.chars().filter(|c| !c.is_whitespace()).collect();
    t.eq_ignore_ascii_case("SUPER^")
}
