//! TwinCAT 3 LD and FBD bodies: the network list (`<Implementation><NWL><XmlArchive>`) that TwinCAT
//! 3 (and CODESYS V3) keep in a `.TcPOU` for a POU, method or action written in LD or FBD, read as ST.
//!
//! The archive is a serialized object graph: `<o t="NWLImplementationObject">` holds
//! `<l2 n="NetworkList">`, one `<o>` per network (in execution order) with its `Label` (the target
//! of jumps), `Comment`, `OutCommented` and `NetworkItems`. Each item is a tree evaluated as one
//! expression: `BoxTreeAssign` (an `RValue` tree written to its `OutputItems`: the coils of LD or
//! the assignments of FBD), `BoxTreeBox` (an operator, function, function block or action call,
//! `InputItems` aligned with `InputParam` names, `OutputItems` with `OutputParam` names: a null
//! output item is the one that flows on to the box's parent, an operand is a variable written from
//! that output; an `EXECUTE` box holds ST statements in its `STSnippet`, which run when its EN is
//! TRUE), `BoxTreeOperand` (a contact or input: variable or literal), `BoxTreeDemux` (a
//! branch of the power rail or a fork of a line: its `Input` evaluated once, named by `VarId`, and
//! each later `BoxTreeDemux` of that `VarId` reads it), `BoxTreeTerminator` (the left power rail:
//! TRUE; inside a closed parallel branch the line before it), `BoxTreeParallel` (a closed parallel
//! branch: its `Input`, the line before it, and its `Trees`, the branches, each powered by that
//! line; `Mode` `Sequential` or `BoxShortCircuit`).
//! An operand's `Flags` are the bits of CODESYS's `IFlags` (Negation 1, Set 2, Jump 4, Return 8,
//! Rtrig 16, Ftrig 32): on a contact or box input, 1 negated (`/`), 16 rising edge (`P`), 32 falling
//! edge (`N`); on an output, 0 a coil, 1 a negated coil, 2 a set coil (S), 3 a reset coil (R: a
//! negated set, as a first-scan flag reset at the end of its network is stored in a public project),
//! 4 a jump to the network of that label, 8 a return.
//!
//! Input: the `<NWL>` element and the name of the body (for messages). Output: [`NwlBody`], the ST
//! tokens in order, each with the byte offset of the archive element it stands for (the caller
//! writes each token into blank markup at or after that offset, so a diagnostic of the ST front end
//! points at the operand's or box's line in the `.TcPOU`), and the temporaries the tokens use (each
//! `EN` that is not the power rail, each branch, the jump state): `_nwl_...` variables the caller
//! declares in a VAR block before the body. Semantics (IEC 61131-3 edition 3, 8.2 and 8.3): the
//! networks run in order, each item's boxes in data-flow order (inputs first, as the tree nests
//! them); a box with `EN` runs only when EN is TRUE, its ENO is EN (standard functions raise no
//! error here), a value taken from its result is written only when EN is TRUE, and an element that
//! reads its result reads the initial value of its type when EN is FALSE (README "EN/ENO"); a
//! closed parallel branch is the OR of its branches, the line before it evaluated once (Beckhoff
//! Infosys "Closed line branch": in the short-circuit mode the branches with boxes run only when
//! no branch without one is TRUE); a set coil
//! writes TRUE and a reset coil FALSE when powered; a jump skips the items up to the network of its
//! label (forward only, as IEC 61131-3 8.2.7 draws it; a jump backwards is E0325). A network shown
//! as IL (`ILActive`: TwinCAT 3 keeps an IL body so, as a table of operator and operand rows) is
//! not read: one E0325 naming the body as IL.
//! Invariants: never panics; an element, call type or flag that is not understood is one E0325
//! naming it and its network (1-based, as TwinCAT numbers them), at the element; an operand whose
//! text is not one ST operand (a `;`, a comment, an assignment) is E0326 at it, so no markup text
//! becomes statements; nothing is dropped silently: commented-out networks (`OutCommented`, which
//! TwinCAT does not run either) and comments are the only things not lowered.

use crate::xml::Element;
use diagnostics::{code, Diagnostic, FileId, Span};
use std::collections::{HashMap, HashSet};

/// One ST token and where it comes from (a byte offset in the file; 0: anywhere after the previous).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Tok {
    /// The token's text (an operand, keyword or punctuation; never spans a line).
    pub text: String,
    /// The offset of the archive element it stands for.
    pub at: usize,
    /// Where the token stands in the file when that is not at `at` (a chart's condition taken
    /// from a `<Transition>` object: the word in the object's text): diagnostics are shown there.
    pub from: Option<usize>,
}

/// An LD/FBD body read as ST.
#[derive(Debug, Default)]
pub(crate) struct NwlBody {
    /// The name of the body (`P`, `P.Act`), for messages.
    pub what: String,
    /// The temporaries the statements use: name and type.
    pub temps: Vec<(String, String)>,
    /// The statements' tokens, in order.
    pub toks: Vec<Tok>,
}

/// A value flowing out of a tree node: an ST expression without side effects, and the EN temporary
/// whose box must have run for it to be written (`None`: always).
#[derive(Debug, Clone)]
struct Value {
    expr: Vec<Tok>,
    guard: Option<String>,
}

type Res<T> = Result<T, Box<Diagnostic>>;

/// Reads the `<NWL>` element `nwl` of the body named `what`; `declares`: whether the body can
/// declare variables (a POU's or method's can, an action's cannot: there an EN or branch that is
/// one variable no element of its network writes is read where it is used, and what needs a
/// variable of its own is E0327).
pub(crate) fn lower(file: FileId, nwl: &Element, what: &str, declares: bool) -> Res<NwlBody> {
    let mut l = Lowering {
        file,
        what: what.to_string(),
        network: None,
        body: NwlBody {
            what: what.to_string(),
            ..NwlBody::default()
        },
        splits: HashMap::new(),
        labels: HashMap::new(),
        jumps: false,
        declares,
        written: HashSet::new(),
        line: None,
    };
    let networks: Vec<&Element> = nwl
        .child("XmlArchive")
        .and_then(|a| a.child("Data"))
        .and_then(|d| d.child("o"))
        .and_then(|o| prop(o, "NetworkList"))
        .map(|list| list.children.iter().filter(|n| n.name() == "o").collect())
        .ok_or_else(|| {
            l.error_at(
                code::E0325,
                nwl,
                "its archive has no network list (`<o t=\"NWLImplementationObject\">` with \
                 `<l2 n=\"NetworkList\">`)"
                    .into(),
            )
        })?;
    for (k, nw) in networks.iter().enumerate() {
        let label = string(nw, "Label").unwrap_or_default();
        if !label.trim().is_empty() {
            l.labels.insert(label.trim().to_ascii_uppercase(), k);
        }
        l.jumps |= !commented_out(nw)
            && nw.walk().any(|e| {
                e.attr("n") == Some("OutputItems")
                    && e.name() == "l2"
                    && e.children
                        .iter()
                        .any(|o| operand_flags(o) == Some(FLAG_JUMP))
            });
    }
    if l.jumps {
        l.no_variables(nwl, "a jump")?;
        l.body.temps.push((JUMP.into(), "INT".into()));
        l.stmt(&[JUMP, ":=", "0", ";"], nwl.tag_start());
    }
    for (k, nw) in networks.iter().enumerate() {
        l.network = Some(k);
        l.network_body(nw)?;
    }
    Ok(l.body)
}

/// The temporary that holds the 1-based index of the network a jump goes to (0: none taken).
const JUMP: &str = "_nwl_jump";

struct Lowering {
    file: FileId,
    what: String,
    /// The network being read (`None` before the list is).
    network: Option<usize>,
    body: NwlBody,
    /// The branches read so far: `VarId` -> the temporary holding the value.
    splits: HashMap<String, String>,
    /// Network labels (upper case) -> network index.
    labels: HashMap<String, usize>,
    /// Whether any network jumps.
    jumps: bool,
    /// Whether the body can declare variables (not an action's).
    declares: bool,
    /// The names (upper case, up to the first `.` or `[`) that the network being read writes or
    /// calls.
    written: HashSet<String>,
    /// Inside a branch of a closed parallel branch (`BoxTreeParallel`): the line that powers it.
    line: Option<Line>,
}

/// The line that powers a branch of a closed parallel branch: the value of the element before the
/// branch (one token), which the branch's terminators stand for and its leftmost contact is in
/// series with.
#[derive(Debug, Clone)]
struct Line {
    expr: Vec<Tok>,
    /// The offset of the branch's leftmost operand (the contact the line enters), if it has one.
    left: Option<usize>,
}

impl Lowering {
    fn network_body(&mut self, nw: &Element) -> Res<()> {
        let k = self.network.unwrap_or(0);
        if self.jumps && self.labels.values().any(|&t| t == k) {
            // a jump to this network ends here
            let n = (k + 1).to_string();
            self.stmt(
                &[
                    "IF", JUMP, "=", &n, "THEN", JUMP, ":=", "0", ";", "END_IF", ";",
                ],
                nw.tag_start(),
            );
        }
        if commented_out(nw) {
            return Ok(());
        }
        if string(nw, "ILActive").as_deref() == Some("true") {
            // TwinCAT 3 keeps an IL body as this network list: per network a table of rows
            // (operator, prefix, operand, postfix), a call's arguments over several rows
            // (`CAL T(` / `IN := x,` / `)`) and operands that may be ST expressions: not IEC IL
            // text, and not read (README, TwinCAT row)
            return Err(Box::new(
                Diagnostic::error(
                    code::E0325,
                    format!(
                        "TwinCAT IL body of `{}`, network {}: TwinCAT 3's IL (a network shown as IL, \
                         `ILActive`, one table row per operator and operand) is not read by ladderc",
                        self.what,
                        k + 1
                    ),
                )
                .at(Span::new(self.file, nw.tag_start(), nw.tag_end()))
                .with_primary_label("an IL network")
                .with_hint(
                    "write the body in ST (or LD/FBD), which ladderc reads in a TwinCAT file; IL \
                     is read in .il and .st files and in PLCopen XML",
                ),
            ));
        }
        let Some(items) = prop(nw, "NetworkItems") else {
            return Ok(());
        };
        self.written = nw
            .walk()
            .flat_map(|e| {
                let outputs: Vec<&Element> =
                    if e.name() == "l2" && e.attr("n") == Some("OutputItems") {
                        e.children.iter().collect()
                    } else if e.attr("n") == Some("Instance") {
                        vec![e]
                    } else {
                        Vec::new()
                    };
                outputs
                    .into_iter()
                    .filter_map(|o| string(o, "Operand"))
                    .map(|t| root_name(&t))
            })
            .collect();
        let cet = items.attr("cet");
        for item in items.children {
            if self.jumps {
                self.stmt(&["IF", JUMP, "=", "0", "THEN"], item.tag_start());
            }
            match kind(item, cet) {
                "BoxTreeAssign" => {
                    self.assign(item, false)?;
                }
                "BoxTreeBox" => {
                    self.boxed(item)?;
                }
                "BoxTreeDemux" => {
                    self.value(item, cet)?;
                }
                "BoxTreeParallel" => {
                    self.parallel(item, false)?;
                }
                other => return Err(self.unsupported(item, other)),
            }
            if self.jumps {
                self.stmt(&["END_IF", ";"], 0);
            }
        }
        Ok(())
    }

    /// The value of a tree node (statements for its calls emitted first).
    fn value(&mut self, node: &Element, cet: Option<&str>) -> Res<Value> {
        match kind(node, cet) {
            "BoxTreeOperand" => {
                let op = prop(node, "Operand").ok_or_else(|| self.unsupported(node, "operand"))?;
                let v = self.operand(op)?;
                // the leftmost contact of a parallel branch is in series with the line before it
                match &self.line {
                    Some(Line {
                        expr,
                        left: Some(left),
                    }) if *left == node.tag_start() => {
                        let at = v.expr.first().map_or(node.tag_start(), |t| t.at);
                        let mut e = vec![tok("(", at)];
                        e.extend(expr.iter().cloned());
                        e.extend([tok(")", at), tok("AND", at), tok("(", at)]);
                        e.extend(v.expr);
                        e.push(tok(")", at));
                        Ok(Value {
                            expr: e,
                            guard: v.guard,
                        })
                    }
                    _ => Ok(v),
                }
            }
            "BoxTreeAssign" => self.assign(node, true),
            "BoxTreeTerminator" if prop(node, "Input").is_none_or(|i| i.name() == "n") => {
                // the power rail, or inside a parallel branch the line that powers the branch
                Ok(Value {
                    expr: match &self.line {
                        Some(l) => l.expr.clone(),
                        None => vec![tok("TRUE", node.tag_start())],
                    },
                    guard: None,
                })
            }
            "BoxTreeDemux" => self.split(node),
            "BoxTreeParallel" => self.parallel(node, true),
            "BoxTreeBox" => match self.boxed(node)? {
                Some(v) => Ok(v),
                None => Err(self.error_at(
                    code::E0325,
                    node,
                    format!(
                        "box `{}` feeds another element but none of its outputs is connected to it",
                        string(node, "BoxType").unwrap_or_default()
                    ),
                )),
            },
            other => Err(self.unsupported(node, other)),
        }
    }

    /// A contact or input: the operand's text, `NOT` when negated.
    fn operand(&mut self, op: &Element) -> Res<Value> {
        let at = prop(op, "Operand").map_or(op.tag_start(), |v| v.tag_start());
        let text = self.operand_text(op)?;
        if text.is_empty() {
            return Err(self.error_at(
                code::E0326,
                op,
                "an input of the network is not connected (its operand is empty)".into(),
            ));
        }
        let v = Value {
            expr: wrap(&text, at),
            guard: None,
        };
        self.input_flags(
            v,
            operand_flags(op).unwrap_or(0),
            op,
            &format!("operand `{text}`"),
        )
    }

    /// An input's value as its flags say: plain, negated (`/`), rising edge (`P`, 16) or falling
    /// edge (`N`, 32), each edge with a memory of its own that keeps the last scan's value (as
    /// R_TRIG and F_TRIG do: IEC 61131-3 edition 3, 6.6.3.5.3 and 8.2.3).
    fn input_flags(&mut self, v: Value, flags: u32, el: &Element, what: &str) -> Res<Value> {
        let at = v.expr.first().map_or(el.tag_start(), |t| t.at);
        match flags {
            0 => Ok(v),
            1 => {
                let mut expr = vec![tok("NOT", at), tok("(", at)];
                expr.extend(v.expr);
                expr.push(tok(")", at));
                Ok(Value {
                    expr,
                    guard: v.guard,
                })
            }
            FLAG_RISING | FLAG_FALLING => {
                self.no_guard(&v, el)?;
                self.no_variables(el, "an edge contact's memory")?;
                let n = self.body.temps.len() + 1;
                let (edge, mem) = (format!("_nwl_edge{n}"), format!("_nwl_mem{n}"));
                self.body.temps.push((edge.clone(), "BOOL".into()));
                self.body.temps.push((mem.clone(), "BOOL".into()));
                self.stmt(&[&edge, ":=", "("], at);
                if flags == FLAG_FALLING {
                    self.stmt(&["NOT", "("], at);
                }
                self.push_all(v.expr.clone());
                if flags == FLAG_FALLING {
                    self.stmt(&[")", ")", "AND", &mem, ";"], at);
                } else {
                    self.stmt(&[")", "AND", "NOT", &mem, ";"], at);
                }
                self.stmt(&[&mem, ":="], at);
                self.push_all(v.expr);
                self.push(";", at);
                Ok(Value {
                    expr: vec![tok(&edge, at)],
                    guard: None,
                })
            }
            f => Err(self.error_at(
                code::E0325,
                el,
                format!(
                    "{what} has flags {f} ({}), which ladderc does not read on an input",
                    flag_names(f)
                ),
            )),
        }
    }

    /// The operand text of an `Operand` object (its `"..."` quotes removed), checked to be one ST
    /// operand; empty when not connected.
    fn operand_text(&self, op: &Element) -> Res<String> {
        let text = string(op, "Operand").unwrap_or_default();
        let text = text.trim().to_string();
        let bad = [
            "(*", "*)", "//", "/*", ";", ":=", "=>", "\n", "\r", "{", "}",
        ];
        if let Some(b) = bad.iter().find(|b| text.contains(*b)) {
            let at = prop(op, "Operand").unwrap_or(op);
            return Err(self.error_at(
                code::E0326,
                at,
                format!("operand `{text}` is not one ST operand (it holds `{b}`)"),
            ));
        }
        // a quote only as one whole string literal (`'on'`, `"x"`): else it would open a string
        // that takes the following tokens
        let quoted = |q: char| {
            text.len() >= 2
                && text.starts_with(q)
                && text.ends_with(q)
                && !text[1..text.len() - 1]
                    .replace(&format!("${q}"), "")
                    .contains(q)
        };
        if text.contains(['\'', '"']) && !quoted('\'') && !quoted('"') {
            let at = prop(op, "Operand").unwrap_or(op);
            return Err(self.error_at(
                code::E0326,
                at,
                format!("operand `{text}` is not one ST operand (a quote that is not one string literal)"),
            ));
        }
        Ok(text)
    }

    /// [`Lowering::operand_text`] of what is written or called (a coil's variable, a block's
    /// instance): empty, or beginning with a name.
    fn target_text(&self, op: &Element) -> Res<String> {
        let text = self.operand_text(op)?;
        if text
            .chars()
            .next()
            .is_some_and(|c| !(c.is_ascii_alphabetic() || c == '_'))
            || ["TRUE", "FALSE"].contains(&text.to_ascii_uppercase().as_str())
        {
            let at = prop(op, "Operand").unwrap_or(op);
            return Err(self.error_at(
                code::E0326,
                at,
                format!("`{text}` is written or called here, and it is not a variable"),
            ));
        }
        Ok(text)
    }

    /// A `BoxTreeAssign`: its value, written to each of its outputs; the value flows on (`flows`:
    /// to a parent element). A value used more than once is read back from its first plain coil
    /// or, without one, kept in a temporary: a coil may write what the expression reads (a latch),
    /// and every output of the network takes the value of the one evaluation.
    fn assign(&mut self, node: &Element, flows: bool) -> Res<Value> {
        let rv = prop(node, "RValue").ok_or_else(|| self.unsupported(node, "assignment"))?;
        let mut v = self.value(rv, None)?;
        let outs: Vec<&Element> = output_items(node)
            .into_iter()
            .filter(|o| o.name() == "o")
            .filter(|o| {
                string(o, "Operand").is_some_and(|t| !t.trim().is_empty())
                    || operand_flags(o).unwrap_or(0) & (FLAG_JUMP | FLAG_RETURN) != 0
            })
            .collect();
        let first_plain = outs
            .first()
            .is_some_and(|o| operand_flags(o).unwrap_or(0) == 0);
        if outs.len() + usize::from(flows) > 1 && v.expr.len() > 1 && !first_plain {
            v = self.keep(rv, v)?;
        }
        for out in outs {
            if let Some(target) = self.coil(out, &v)? {
                if v.expr.len() > 1 {
                    v.expr = target;
                }
            }
        }
        Ok(v)
    }

    /// `v` stored in a new temporary (of the type of `node`'s value); the temporary as the value.
    fn keep(&mut self, node: &Element, v: Value) -> Res<Value> {
        self.no_guard(&v, node)?;
        self.no_variables(node, "a value written to several outputs")?;
        let ty = self.type_of(node, None)?;
        let name = format!("_nwl_value{}", self.body.temps.len() + 1);
        self.body.temps.push((name.clone(), ty));
        let at = node.tag_start();
        self.push(&name, at);
        self.push(":=", at);
        self.push_all(v.expr);
        self.push(";", at);
        Ok(Value {
            expr: vec![tok(&name, at)],
            guard: None,
        })
    }

    /// Writes `v` to the output operand `out` as its flags say (plain, negated, set, reset, jump);
    /// for a plain coil, the target (which then holds the value).
    fn coil(&mut self, out: &Element, v: &Value) -> Res<Option<Vec<Tok>>> {
        let flags = operand_flags(out).unwrap_or(0);
        let target = if flags & (FLAG_JUMP | FLAG_RETURN) != 0 {
            self.operand_text(out)?
        } else {
            self.target_text(out)?
        };
        if target.is_empty() && flags != FLAG_RETURN {
            return Ok(None);
        }
        let place = prop(out, "Operand").unwrap_or(out);
        let at = place.tag_start();
        if let Some(g) = &v.guard {
            self.stmt(&["IF", g, "THEN"], at);
        }
        match flags {
            0 | 1 => {
                self.push_all(wrap(&target, at));
                self.push(":=", at);
                if flags == 1 {
                    self.push("NOT", at);
                    self.push("(", at);
                }
                self.push_all(v.expr.clone());
                if flags == 1 {
                    self.push(")", at);
                }
                self.push(";", at);
            }
            // a reset coil is a negated set coil (CODESYS and TwinCAT store R as Set + Negation)
            FLAG_SET | FLAG_RESET => {
                self.push("IF", at);
                self.push_all(v.expr.clone());
                self.push("THEN", at);
                self.push_all(wrap(&target, at));
                self.stmt(
                    &[
                        ":=",
                        if flags == 2 { "TRUE" } else { "FALSE" },
                        ";",
                        "END_IF",
                        ";",
                    ],
                    at,
                );
            }
            FLAG_RETURN => {
                // IEC 61131-3 edition 3, 8.2.7: a conditional return ends the body
                self.push("IF", at);
                self.push_all(v.expr.clone());
                self.stmt(&["THEN", "RETURN", ";", "END_IF", ";"], at);
            }
            FLAG_JUMP => {
                let Some(&to) = self.labels.get(&target.to_ascii_uppercase()) else {
                    return Err(self.error_at(
                        code::E0325,
                        place,
                        format!(
                            "jump to `{target}`, which no network of the body has as its label"
                        ),
                    ));
                };
                if Some(to) <= self.network {
                    return Err(self.error_at(
                        code::E0325,
                        place,
                        format!(
                            "jump back to `{target}` (network {}): ladderc reads forward jumps only",
                            to + 1
                        ),
                    ));
                }
                self.push("IF", at);
                self.push_all(v.expr.clone());
                let n = (to + 1).to_string();
                self.stmt(&["THEN", JUMP, ":=", &n, ";", "END_IF", ";"], at);
            }
            f => {
                return Err(self.error_at(
                    code::E0325,
                    place,
                    format!(
                        "output `{target}` has flags {f} ({}), which ladderc does not read",
                        flag_names(f)
                    ),
                ))
            }
        }
        if v.guard.is_some() {
            self.stmt(&["END_IF", ";"], at);
        }
        Ok((flags == 0).then(|| wrap(&target, at)))
    }

    /// A branch: with an `Input`, its value stored in a temporary named after its `VarId`; without,
    /// that temporary.
    fn split(&mut self, node: &Element) -> Res<Value> {
        let id = string(node, "VarId").unwrap_or_default();
        let Some(input) = prop(node, "Input").filter(|i| i.name() == "o") else {
            return match self.splits.get(&id) {
                Some(t) => Ok(Value {
                    expr: vec![tok(t, node.tag_start())],
                    guard: None,
                }),
                None => Err(self.error_at(
                    code::E0325,
                    node,
                    format!("branch {id} is read before the network gives it a value"),
                )),
            };
        };
        if !self.declares {
            let v = self.value(input, None)?;
            let v = self.unguard(v, input, None)?;
            let Some(name) = self.read_in_place(&v) else {
                return Err(self.needs_variable(node, "a branch"));
            };
            self.splits.insert(id, name);
            return Ok(v);
        }
        let v = self.value(input, None)?;
        let v = self.unguard(v, input, None)?;
        let ty = self.type_of(input, None)?;
        let name = format!("_nwl_split{}", self.body.temps.len() + 1);
        self.body.temps.push((name.clone(), ty));
        self.push(&name, node.tag_start());
        self.push(":=", node.tag_start());
        self.push_all(v.expr);
        self.push(";", 0);
        self.splits.insert(id, name.clone());
        Ok(Value {
            expr: vec![tok(&name, node.tag_start())],
            guard: None,
        })
    }

    /// The type of the value of `node` (an element of a list of element type `cet`), for the
    /// temporary that keeps it.
    fn type_of(&self, node: &Element, cet: Option<&str>) -> Res<String> {
        let ty = match kind(node, cet) {
            "BoxTreeOperand" => prop(node, "Operand").and_then(|o| string(o, "Type")),
            "BoxTreeTerminator" | "BoxTreeParallel" => Some("BOOL".into()),
            "BoxTreeDemux" => {
                let id = string(node, "VarId").unwrap_or_default();
                self.splits.get(&id).and_then(|t| {
                    self.body
                        .temps
                        .iter()
                        .find(|(n, _)| n == t)
                        .map(|(_, ty)| ty.clone())
                })
            }
            "BoxTreeAssign" => match prop(node, "RValue") {
                Some(rv) => return self.type_of(rv, None),
                None => None,
            },
            "BoxTreeBox" => {
                let call = call_type(node);
                if BOOLEAN_OPERATORS.contains(&call.as_str()) {
                    Some("BOOL".into())
                } else {
                    let names = param(node, "OutputParam", "Names");
                    let types = param(node, "OutputParam", "Types");
                    let items = output_items(node);
                    let flowing = items
                        .iter()
                        .position(|i| i.name() == "n")
                        .or((items.is_empty() && names.len() == 1).then_some(0));
                    flowing
                        .and_then(|k| types.get(k).cloned())
                        .filter(|t| !t.trim().is_empty())
                        .or_else(|| operator_type(node, &call))
                }
            }
            _ => None,
        };
        match ty {
            Some(t)
                if !t.is_empty()
                    && t.chars()
                        .all(|c| c.is_ascii_alphanumeric() || "_.()#,[] ".contains(c)) =>
            {
                Ok(t)
            }
            _ => Err(self.error_at(
                code::E0325,
                node,
                "the type of this value, which the network keeps in a variable (a branch, or the \
                 result of a box with EN that feeds another element), is not given in the archive"
                    .into(),
            )),
        }
    }

    /// In a body without declarations: the one variable `v` is, when no element of the network
    /// writes or calls it (so reading it where it is used gives the value it had here).
    fn read_in_place(&self, v: &Value) -> Option<String> {
        match v.expr.as_slice() {
            [t] if v.guard.is_none()
                && t.text
                    .starts_with(|c: char| c.is_ascii_alphabetic() || c == '_')
                && !self.written.contains(&root_name(&t.text)) =>
            {
                Some(t.text.clone())
            }
            _ => None,
        }
    }

    /// E0327 at `el` when the body cannot declare the variable that `what` needs.
    fn no_variables(&self, el: &Element, what: &str) -> Res<()> {
        if self.declares {
            return Ok(());
        }
        Err(self.needs_variable(el, what))
    }

    /// E0327 at `el`: `what` needs a variable, and an action declares none.
    fn needs_variable(&self, el: &Element, what: &str) -> Box<Diagnostic> {
        self.error_at(
            code::E0327,
            el,
            format!(
                "{what} needs a variable of its own, and an action has no declarations (nor can \
                 it read the value where it is used: an element of the network writes it, or it \
                 is not one variable)"
            ),
        )
    }

    fn no_guard(&self, v: &Value, at: &Element) -> Res<()> {
        if v.guard.is_some() {
            return Err(self.error_at(
                code::E0325,
                at,
                "the result of a box with EN is written to several outputs, the first not a plain \
                 coil: ladderc writes such a result to its outputs only when a plain coil comes first"
                    .into(),
            ));
        }
        Ok(())
    }

    /// A value that an element reads from `node` (of a list of element type `cet`): when it comes
    /// from a box with EN, kept in a temporary that holds the box's result when EN is TRUE and
    /// the initial value of its type when EN is FALSE (the box did not run: README "EN/ENO", as
    /// matiec passes it on), read from a second temporary that nothing writes.
    fn unguard(&mut self, v: Value, node: &Element, cet: Option<&str>) -> Res<Value> {
        let Some(g) = v.guard.clone() else {
            return Ok(v);
        };
        if !self.declares {
            return Err(self.needs_variable(
                node,
                "the result of a box with EN that feeds another element",
            ));
        }
        let ty = self.type_of(node, cet)?;
        let n = self.body.temps.len() + 1;
        let (name, initial) = (format!("_nwl_result{n}"), format!("_nwl_initial{n}"));
        self.body.temps.push((name.clone(), ty.clone()));
        self.body.temps.push((initial.clone(), ty));
        let at = v.expr.first().map_or(node.tag_start(), |t| t.at);
        self.stmt(
            &[&name, ":=", &initial, ";", "IF", &g, "THEN", &name, ":="],
            at,
        );
        self.push_all(v.expr);
        self.stmt(&[";", "END_IF", ";"], at);
        Ok(Value {
            expr: vec![tok(&name, at)],
            guard: None,
        })
    }

    /// A closed parallel branch (`BoxTreeParallel`, Beckhoff Infosys "Closed line branch"): its
    /// `Input` (the line before it; none: the line its parent gives it) evaluated once, then its
    /// branches (`Trees`), each powered by that line (its terminators are the line, its leftmost
    /// contact is in series with it); its value is the OR of the branches'. Mode `Sequential`
    /// (a single vertical line) evaluates the branches top to bottom; mode `BoxShortCircuit` (a
    /// double line) first the branches without a box (contacts and logic only) and, only when
    /// none of them is TRUE, the branches with boxes top to bottom (all of them, their values
    /// OR-ed). `used`: whether the value flows on (a network item's does not).
    fn parallel(&mut self, node: &Element, used: bool) -> Res<Value> {
        let at = node.tag_start();
        let mode = string(node, "Mode").unwrap_or_default();
        let short = match mode.as_str() {
            "Sequential" => false,
            "BoxShortCircuit" => true,
            m => {
                return Err(self.error_at(
                    code::E0325,
                    node,
                    format!("closed parallel branch of mode `{m}`, which ladderc does not read"),
                ))
            }
        };
        let list = prop(node, "Trees")
            .filter(|t| t.name() == "l2")
            .ok_or_else(|| self.unsupported(node, "parallel branch without its branches"))?;
        let cet = list.attr("cet");
        let trees: Vec<&Element> = list.children.iter().filter(|t| t.name() == "o").collect();
        if trees.is_empty() {
            return Err(self.unsupported(node, "parallel branch without its branches"));
        }
        // the line that powers the branches, evaluated once (a box of a branch may write what it
        // reads)
        let line = match prop(node, "Input").filter(|i| i.name() == "o") {
            None => self.line.as_ref().map(|l| l.expr.clone()),
            Some(input) => {
                let v = self.value(input, None)?;
                let v = self.unguard(v, input, None)?;
                if is_true(&v) {
                    None
                } else if let Some(name) = self.read_in_place(&v) {
                    Some(vec![tok(&name, at)])
                } else {
                    self.no_variables(node, "the line before a closed parallel branch")?;
                    let name = format!("_nwl_line{}", self.body.temps.len() + 1);
                    self.body.temps.push((name.clone(), "BOOL".into()));
                    self.push(&name, at);
                    self.push(":=", at);
                    self.push_all(v.expr);
                    self.push(";", at);
                    Some(vec![tok(&name, at)])
                }
            }
        };
        // (a box is any call but the AND and OR that contacts in series and in parallel are)
        let has_box = |t: &Element| {
            std::iter::once(t).chain(t.walk()).any(|e| {
                string(e, "CallType").is_some_and(|c| !["And", "Or"].contains(&c.as_str()))
            })
        };
        let (first, then): (Vec<&Element>, Vec<&Element>) = if short {
            trees.iter().partition(|t| !has_box(t))
        } else {
            (trees, Vec::new())
        };
        // the value: a temporary that the branches are OR-ed into, or (an action's) their
        // expressions, each one variable read in place
        let result = if used && self.declares {
            let name = format!("_nwl_parallel{}", self.body.temps.len() + 1);
            self.body.temps.push((name.clone(), "BOOL".into()));
            Some(name)
        } else {
            None
        };
        let mut values: Vec<Vec<Tok>> = Vec::new();
        for t in &first {
            let v = self.branch(t, cet, &line)?;
            values.push(v.expr);
        }
        let or = |values: Vec<Vec<Tok>>| -> Vec<Tok> {
            let mut e = vec![tok("(", at)];
            for (k, v) in values.into_iter().enumerate() {
                if k > 0 {
                    e.push(tok("OR", at));
                }
                e.push(tok("(", at));
                e.extend(v);
                e.push(tok(")", at));
            }
            e.push(tok(")", at));
            e
        };
        if then.is_empty() {
            if let Some(r) = &result {
                self.stmt(&[r, ":="], at);
                self.push_all(or(values));
                self.push(";", at);
            } else if used {
                return self.in_place_or(node, values, or);
            }
        } else {
            if !used || result.is_some() {
                // a short circuit: the branches with boxes run only when no other one is TRUE
                let skip = if values.is_empty() {
                    None
                } else {
                    Some(or(std::mem::take(&mut values)))
                };
                let opened = match (&result, skip) {
                    (Some(r), None) => {
                        self.stmt(&[r, ":=", "FALSE", ";"], at);
                        false
                    }
                    (Some(r), Some(skip)) => {
                        self.stmt(&[r, ":="], at);
                        self.push_all(skip);
                        self.stmt(&[";", "IF", "NOT", r, "THEN"], at);
                        true
                    }
                    (None, Some(skip)) => {
                        self.stmt(&["IF", "NOT"], at);
                        self.push_all(skip);
                        self.push("THEN", at);
                        true
                    }
                    (None, None) => false,
                };
                for t in &then {
                    let v = self.branch(t, cet, &line)?;
                    if let Some(r) = &result {
                        self.stmt(&[r, ":=", r, "OR", "("], at);
                        self.push_all(v.expr);
                        self.stmt(&[")", ";"], at);
                    }
                }
                if opened {
                    self.stmt(&["END_IF", ";"], at);
                }
            } else {
                return Err(self.needs_variable(node, "a closed parallel branch with boxes"));
            }
        }
        Ok(Value {
            expr: match result {
                Some(r) => vec![tok(&r, at)],
                None => vec![tok("FALSE", at)],
            },
            guard: None,
        })
    }

    /// In an action (no declarations): the OR of a parallel branch's values, each one variable
    /// read where it is used.
    fn in_place_or(
        &self,
        node: &Element,
        values: Vec<Vec<Tok>>,
        or: impl Fn(Vec<Vec<Tok>>) -> Vec<Tok>,
    ) -> Res<Value> {
        for v in &values {
            let v = Value {
                expr: v.clone(),
                guard: None,
            };
            if !is_true(&v) && self.read_in_place(&v).is_none() {
                return Err(self.needs_variable(node, "a closed parallel branch"));
            }
        }
        Ok(Value {
            expr: or(values),
            guard: None,
        })
    }

    /// One branch of a closed parallel branch, powered by `line` (`None`: the power rail); a box
    /// whose outputs do not reach the closing line passes FALSE on.
    fn branch(&mut self, tree: &Element, cet: Option<&str>, line: &Option<Vec<Tok>>) -> Res<Value> {
        let outer = self.line.take();
        self.line = line.as_ref().map(|e| Line {
            expr: e.clone(),
            left: leftmost(tree, cet),
        });
        let v = if kind(tree, cet) == "BoxTreeBox" {
            self.boxed(tree).map(|v| {
                v.unwrap_or_else(|| Value {
                    expr: vec![tok("FALSE", tree.tag_start())],
                    guard: None,
                })
            })
        } else {
            self.value(tree, cet)
        };
        let v = v.and_then(|v| self.unguard(v, tree, cet));
        self.line = outer;
        v
    }

    /// A box: its inputs, then its call (under `IF en THEN` when it has an EN input), then its
    /// outputs written; the value that flows to its parent, if one does.
    fn boxed(&mut self, node: &Element) -> Res<Option<Value>> {
        let box_type = string(node, "BoxType").unwrap_or_default();
        let call = call_type(node);
        let at = prop(node, "BoxType").map_or(node.tag_start(), |e| e.tag_start());
        let en = string(node, "EN").as_deref() == Some("true");
        if let Some(f) = prop(node, "Flags").and_then(|f| string(f, "Flags")) {
            if f.trim() != "0" {
                return Err(self.error_at(
                    code::E0325,
                    node,
                    format!("box `{box_type}` has flags {f}, which ladderc does not read"),
                ));
            }
        }
        let in_names = param(node, "InputParam", "Names");
        let out_names = param(node, "OutputParam", "Names");
        let in_flags: Vec<Option<u32>> = prop(node, "InputFlags")
            .filter(|l| l.name() == "l2")
            .map(|l| l.children.iter().map(flags_value).collect())
            .unwrap_or_default();
        let inputs = prop(node, "InputItems");
        let cet = inputs.and_then(|i| i.attr("cet"));
        let mut args: Vec<(Option<String>, Option<Value>)> = Vec::new();
        for (k, input) in inputs.map_or(&[][..], |i| i.children).iter().enumerate() {
            let name = in_names.get(k).filter(|n| !n.is_empty()).cloned();
            let unconnected = input.name() == "n"
                || (kind(input, cet) == "BoxTreeOperand"
                    && prop(input, "Operand")
                        .and_then(|o| string(o, "Operand"))
                        .is_some_and(|t| t.trim().is_empty()))
                || (kind(input, cet) == "BoxTreeTerminator" && !(en && k == 0));
            if unconnected {
                args.push((name, None));
                continue;
            }
            let v = self.value(input, cet)?;
            let v = self.unguard(v, input, cet)?;
            let flags = in_flags.get(k).copied().flatten().unwrap_or(0);
            let v = self.input_flags(
                v,
                flags,
                input,
                &format!("input {} of box `{box_type}`", k + 1),
            )?;
            args.push((name, Some(v)));
        }
        // EN: the first input; the power rail (or nothing) is TRUE and needs no test
        let mut guard = None;
        if en {
            if args.is_empty() {
                return Err(self.unsupported(node, "box with EN but no input"));
            }
            let (_, en_value) = args.remove(0);
            let tested = en_value.filter(|v| !(v.expr.len() == 1 && v.expr[0].text == "TRUE"));
            if let Some(v) = tested {
                if self.declares {
                    let name = format!("_nwl_en{}", self.body.temps.len() + 1);
                    self.body.temps.push((name.clone(), "BOOL".into()));
                    self.push(&name, at);
                    self.push(":=", at);
                    self.push_all(v.expr);
                    self.push(";", at);
                    guard = Some(name);
                } else {
                    match self.read_in_place(&v) {
                        Some(t) => guard = Some(t),
                        None => {
                            let what = format!("the EN of box `{box_type}`");
                            return Err(self.needs_variable(node, &what));
                        }
                    }
                }
            }
        }
        let eno = |g: &Option<String>| Value {
            expr: vec![tok(g.as_deref().unwrap_or("TRUE"), at)],
            guard: None,
        };
        if let Some(g) = &guard {
            self.stmt(&["IF", g, "THEN"], at);
        }
        if box_type.eq_ignore_ascii_case("EXECUTE")
            && string(node, "ProvidesSTSnippet").as_deref() == Some("true")
        {
            // TwinCAT's EXECUTE box: its ST statements run when EN is TRUE; ENO is EN
            self.st_snippet(node)?;
            if guard.is_some() {
                self.stmt(&["END_IF", ";"], 0);
            }
            let flows = output_items(node).iter().any(|i| i.name() == "n");
            return Ok(flows.then(|| eno(&guard)));
        }
        // the expression of the box's result (operators and functions) or of its outputs (blocks)
        let instance = prop(node, "Instance")
            .map(|i| self.target_text(i))
            .transpose()?
            .unwrap_or_default();
        let result: Option<Vec<Tok>> = match call.as_str() {
            "FunctionBlock" => {
                if instance.is_empty() {
                    return Err(self.error_at(
                        code::E0326,
                        node,
                        format!("function block box `{box_type}` has no instance"),
                    ));
                }
                self.push_all(wrap_call(&instance, at));
                self.push("(", at);
                self.formal_args(&args, at, node, &box_type)?;
                self.stmt(&[")", ";"], at);
                None
            }
            "Action" | "Program" => {
                if args.iter().any(|(_, v)| v.is_some()) && call == "Action" {
                    return Err(self.unsupported(node, "action box with inputs"));
                }
                let name = if instance.is_empty() {
                    box_type.clone()
                } else {
                    format!("{instance}.{box_type}")
                };
                check_name(&name).map_err(|_| self.bad_name(node, &name))?;
                self.push(&name, at);
                self.push("(", at);
                if call == "Program" {
                    self.formal_args(&args, at, node, &box_type)?;
                }
                self.stmt(&[")", ";"], at);
                None
            }
            "Function" => {
                check_name(&box_type).map_err(|_| self.bad_name(node, &box_type))?;
                let mut e = vec![tok(&box_type, at), tok("(", at)];
                let named = args.iter().all(|(n, _)| n.is_some());
                let mut first = true;
                for (n, v) in &args {
                    let Some(v) = v else {
                        return Err(self.error_at(
                            code::E0326,
                            node,
                            format!("an input of function box `{box_type}` is not connected"),
                        ));
                    };
                    if !first {
                        e.push(tok(",", at));
                    }
                    first = false;
                    if let (true, Some(n)) = (named, n) {
                        e.push(tok(n, at));
                        e.push(tok(":=", at));
                    }
                    e.extend(v.expr.iter().cloned());
                }
                e.push(tok(")", at));
                Some(e)
            }
            op => Some(self.operator(op, &box_type, &args, at, node)?),
        };
        // outputs: written when connected to a variable; the null one flows to the parent
        let items = output_items(node);
        let mut flowing: Option<Value> = None;
        let value_of = |k: usize| -> Value {
            let name = out_names.get(k).cloned().unwrap_or_default();
            if name.eq_ignore_ascii_case("ENO") && en {
                return eno(&guard);
            }
            match &result {
                Some(e) => Value {
                    expr: e.clone(),
                    guard: None,
                },
                None => Value {
                    expr: vec![tok(&format!("{instance}.{name}"), at)],
                    guard: None,
                },
            }
        };
        let mut writes = Vec::new();
        for (k, item) in items.iter().enumerate() {
            if item.name() == "n" {
                let mut v = value_of(k);
                if !(en
                    && out_names
                        .get(k)
                        .is_some_and(|n| n.eq_ignore_ascii_case("ENO")))
                {
                    v.guard.clone_from(&guard);
                }
                flowing = Some(v);
            } else if item.name() == "o" {
                writes.push((*item, value_of(k)));
            }
        }
        if items.is_empty() {
            // an operator of a serial connection (AND of contacts) flows on without output items
            flowing = result.as_ref().map(|e| Value {
                expr: e.clone(),
                guard: guard.clone(),
            });
            if result.is_none() && out_names.len() == 1 && !instance.is_empty() {
                flowing = Some(Value {
                    guard: guard.clone(),
                    ..value_of(0)
                });
            }
        }
        for (item, v) in writes {
            if let Some(target) = self.coil(item, &v)? {
                // a result that flows on too is read back from the variable it was written to
                if let Some(f) = flowing
                    .as_mut()
                    .filter(|f| f.expr.len() > 1 && f.expr == v.expr)
                {
                    f.expr = target;
                }
            }
        }
        if guard.is_some() {
            self.stmt(&["END_IF", ";"], 0);
        }
        if call == "Action" || call == "Program" {
            // nothing but ENO flows from a call without a result
            flowing = flowing.filter(|v| v.guard.is_none());
        }
        Ok(flowing)
    }

    /// The ST statements of an EXECUTE box (`STSnippet` / `TextDocument` /
    /// `TextBlobForSerialisation`), as tokens at that element (a diagnostic in them points at its
    /// line); its text is ST the front end reads as any body's.
    fn st_snippet(&mut self, node: &Element) -> Res<()> {
        let document = prop(node, "STSnippet")
            .and_then(|s| prop(s, "STSnippet"))
            .and_then(|s| prop(s, "TextDocument"));
        let Some((document, blob)) =
            document.and_then(|d| prop(d, "TextBlobForSerialisation").map(|b| (d, b)))
        else {
            return Err(self.unsupported(node, "EXECUTE box without its ST text"));
        };
        let at = blob.tag_start();
        // (the archive writes line breaks in the string as `\r\n`)
        let text = string(document, "TextBlobForSerialisation")
            .unwrap_or_default()
            .replace("\\r\\n", "\n")
            .replace("\\n", "\n")
            .replace("\\t", " ");
        let (toks, problems) = il_frontend::st::lexer::lex(&text);
        if !problems.is_empty() {
            return Err(self.error_at(
                code::E0326,
                blob,
                "the ST statements of an EXECUTE box cannot be read (a character ST does not have)"
                    .into(),
            ));
        }
        for t in toks
            .iter()
            .filter(|t| !matches!(t.tok, il_frontend::st::lexer::Tok::Eof))
        {
            self.push(&text[t.range.clone()], at);
        }
        Ok(())
    }

    /// `name := value, ...` of a block call: the connected inputs.
    fn formal_args(
        &mut self,
        args: &[(Option<String>, Option<Value>)],
        at: usize,
        node: &Element,
        box_type: &str,
    ) -> Res<()> {
        let mut first = true;
        for (n, v) in args {
            let Some(v) = v else { continue };
            let Some(n) = n else {
                return Err(self.error_at(
                    code::E0325,
                    node,
                    format!("an input of box `{box_type}` has no parameter name in the archive"),
                ));
            };
            if !first {
                self.push(",", at);
            }
            first = false;
            // TwinCAT's names of the bistables' inputs (SR.SET1, RS.RESET1) are IEC's
            self.push(
                crate::catalogue::vendor_pin_alias(box_type, n).unwrap_or(n),
                at,
            );
            self.push(":=", at);
            self.push_all(v.expr.clone());
        }
        Ok(())
    }

    /// The expression of an operator box: infix for the logic, arithmetic and comparison
    /// operators, MOVE its input, any other a call of the standard function named by the box.
    fn operator(
        &self,
        op: &str,
        box_type: &str,
        args: &[(Option<String>, Option<Value>)],
        at: usize,
        node: &Element,
    ) -> Res<Vec<Tok>> {
        let mut values = Vec::new();
        for (_, v) in args {
            match v {
                Some(v) => values.push(v.expr.clone()),
                None => {
                    return Err(self.error_at(
                        code::E0326,
                        node,
                        format!("an input of box `{box_type}` is not connected"),
                    ))
                }
            }
        }
        let infix = match op {
            "And" => Some("AND"),
            "Or" => Some("OR"),
            "Xor" => Some("XOR"),
            "Add" => Some("+"),
            "Sub" => Some("-"),
            "Mul" => Some("*"),
            "Div" => Some("/"),
            "Mod" => Some("MOD"),
            "Gt" => Some(">"),
            "Ge" => Some(">="),
            "Eq" => Some("="),
            "Ne" => Some("<>"),
            "Le" => Some("<="),
            "Lt" => Some("<"),
            _ => None,
        };
        let comparison = matches!(
            op,
            "Gt" | "Ge" | "Eq" | "Ne" | "Le" | "Lt" | "Sub" | "Div" | "Mod"
        );
        let mut e = Vec::new();
        match (infix, values.len()) {
            (_, 0) => {
                return Err(self.error_at(
                    code::E0326,
                    node,
                    format!("box `{box_type}` has no input"),
                ))
            }
            (Some(_), n) if comparison && n != 2 => {
                return Err(self.error_at(
                    code::E0325,
                    node,
                    format!("box `{box_type}` with {n} inputs (ladderc reads it with 2)"),
                ))
            }
            (Some(sym), _) => {
                e.push(tok("(", at));
                for (k, v) in values.into_iter().enumerate() {
                    if k > 0 {
                        e.push(tok(sym, at));
                    }
                    e.push(tok("(", at));
                    e.extend(v);
                    e.push(tok(")", at));
                }
                e.push(tok(")", at));
            }
            (None, 1) if op == "Move" => e.extend(values.into_iter().flatten()),
            (None, 1) if op == "Not" => {
                e.extend([tok("NOT", at), tok("(", at)]);
                e.extend(values.into_iter().flatten());
                e.push(tok(")", at));
            }
            // another standard operator (SEL, MAX, LIMIT, MUX, SHL, ABS, SQRT, a conversion such as
            // INT_TO_REAL ...): the call type names it, or the box is a conversion; any other call
            // type (a method, ...) is not read as a function
            (None, _)
                if !op.eq_ignore_ascii_case(&box_type.replace('_', ""))
                    && !box_type.to_ascii_uppercase().contains("_TO_") =>
            {
                return Err(self.error_at(
                    code::E0325,
                    node,
                    format!("box `{box_type}` of call type `{op}`, which ladderc does not read"),
                ))
            }
            (None, _) => {
                check_name(box_type).map_err(|_| self.bad_name(node, box_type))?;
                e.extend([tok(box_type, at), tok("(", at)]);
                for (k, v) in values.into_iter().enumerate() {
                    if k > 0 {
                        e.push(tok(",", at));
                    }
                    e.extend(v);
                }
                e.push(tok(")", at));
            }
        }
        Ok(e)
    }

    fn push(&mut self, text: &str, at: usize) {
        self.body.toks.push(tok(text, at));
    }

    fn push_all(&mut self, toks: Vec<Tok>) {
        self.body.toks.extend(toks);
    }

    fn stmt(&mut self, words: &[&str], at: usize) {
        for w in words {
            self.push(w, at);
        }
    }

    fn error_at(&self, c: diagnostics::Code, el: &Element, what: String) -> Box<Diagnostic> {
        Box::new(
            Diagnostic::error(
                c,
                match self.network {
                    Some(k) => format!(
                        "TwinCAT LD/FBD body of `{}`, network {}: {what}",
                        self.what,
                        k + 1
                    ),
                    None => format!("TwinCAT LD/FBD body of `{}`: {what}", self.what),
                },
            )
            .at(Span::new(self.file, el.tag_start(), el.tag_end()))
            .with_hint(if c == code::E0326 {
                "open the network in TwinCAT and write a variable or literal at this place"
            } else if c == code::E0327 {
                "write the action as a METHOD (which declares its variables), or this network in ST"
            } else {
                "write this network in ST, or export the POU from TwinCAT as PLCopen XML \
                 (right-click > Export PLCopenXML), which ladderc reads"
            }),
        )
    }

    fn unsupported(&self, el: &Element, what: &str) -> Box<Diagnostic> {
        self.error_at(
            code::E0325,
            el,
            format!("element `{what}` is not one ladderc reads in a network list"),
        )
    }

    fn bad_name(&self, el: &Element, name: &str) -> Box<Diagnostic> {
        self.error_at(
            code::E0326,
            el,
            format!("box `{name}` does not name a function, block or action"),
        )
    }
}

/// The bits of an operand's `Flags` (CODESYS's `IFlags`: Negation, Set, Jump, Return, Rtrig,
/// Ftrig); a reset coil is Set + Negation.
const FLAG_NEGATION: u32 = 1;
const FLAG_SET: u32 = 2;
const FLAG_RESET: u32 = FLAG_SET | FLAG_NEGATION;
const FLAG_JUMP: u32 = 4;
const FLAG_RETURN: u32 = 8;
const FLAG_RISING: u32 = 16;
const FLAG_FALLING: u32 = 32;

/// The names of the bits set in `f` (`Set+Negation`), for messages.
fn flag_names(f: u32) -> String {
    let names = ["Negation", "Set", "Jump", "Return", "Rtrig", "Ftrig"];
    let mut out: Vec<String> = names
        .iter()
        .enumerate()
        .filter(|(k, _)| f & (1 << k) != 0)
        .map(|(_, n)| (*n).to_string())
        .collect();
    if f >> names.len() != 0 {
        out.push(format!("{:#x}", f >> names.len() << names.len()));
    }
    out.join("+")
}

/// Whether a value is the literal TRUE (the power rail).
fn is_true(v: &Value) -> bool {
    v.guard.is_none() && v.expr.len() == 1 && v.expr[0].text.eq_ignore_ascii_case("TRUE")
}

/// The offset of the leftmost operand of a branch `el` (of a list of element type `cet`): the
/// contact the line before the branch enters (following first inputs).
fn leftmost(el: &Element, cet: Option<&str>) -> Option<usize> {
    match kind(el, cet) {
        "BoxTreeOperand" => Some(el.tag_start()),
        "BoxTreeBox" => {
            let items = prop(el, "InputItems")?;
            leftmost(items.children.first()?, items.attr("cet"))
        }
        "BoxTreeParallel" | "BoxTreeDemux" => prop(el, "Input")
            .filter(|i| i.name() == "o")
            .and_then(|i| leftmost(i, None)),
        "BoxTreeAssign" => prop(el, "RValue").and_then(|r| leftmost(r, None)),
        _ => None,
    }
}

/// The type of the result of an operator box whose archive does not give it (MOVE, the
/// arithmetic, SEL, MAX ...): the type of its variable inputs when they agree.
fn operator_type(node: &Element, call: &str) -> Option<String> {
    const SAME_TYPE: &[&str] = &[
        "Move", "Add", "Sub", "Mul", "Div", "Mod", "Max", "Min", "Abs", "Neg",
    ];
    if !SAME_TYPE.contains(&call) {
        return None;
    }
    let en = string(node, "EN").as_deref() == Some("true");
    let items = prop(node, "InputItems")?;
    let cet = items.attr("cet");
    let mut types = items
        .children
        .iter()
        .skip(usize::from(en))
        .filter(|i| kind(i, cet) == "BoxTreeOperand")
        .filter_map(|i| prop(i, "Operand"))
        .filter(|o| {
            string(o, "Operand").is_some_and(|t| {
                t.trim()
                    .starts_with(|c: char| c.is_ascii_alphabetic() || c == '_')
            })
        })
        .map(|o| string(o, "Type").unwrap_or_default());
    let first = types.next()?;
    (!first.trim().is_empty() && types.all(|t| t == first)).then_some(first)
}

/// A box's call type, an operator saved under another name (`Minus` beside `-`, `Greater` beside
/// `>`) read as the short one later versions write (`Sub`, `Gt`): [`crate::twincat_operators`].
fn call_type(node: &Element) -> String {
    let call = string(node, "CallType").unwrap_or_default();
    let box_type = string(node, "BoxType").unwrap_or_default();
    crate::twincat_operators::call_type(&call, &box_type)
}

/// Operators whose result is BOOL.
const BOOLEAN_OPERATORS: &[&str] = &[
    "And", "Or", "Xor", "Not", "Gt", "Ge", "Eq", "Ne", "Le", "Lt",
];

pub(crate) fn tok(text: &str, at: usize) -> Tok {
    Tok {
        text: text.to_string(),
        at,
        from: None,
    }
}

/// An operand as tokens: one, in parentheses when it holds blanks (an expression).
pub(crate) fn wrap(text: &str, at: usize) -> Vec<Tok> {
    if text.contains(char::is_whitespace) {
        vec![tok("(", at), tok(text, at), tok(")", at)]
    } else {
        vec![tok(text, at)]
    }
}

/// An instance as the callee of a call (`fbs[i]`, `GVL.fb`): one token.
fn wrap_call(text: &str, at: usize) -> Vec<Tok> {
    vec![tok(text, at)]
}

/// A dotted name (`Act`, `inst.Act`, `INT_TO_REAL`).
pub(crate) fn check_name(name: &str) -> Result<(), ()> {
    let ok = !name.is_empty()
        && name.split('.').all(|p| {
            p.chars()
                .next()
                .is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
                && p.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
        });
    if ok {
        Ok(())
    } else {
        Err(())
    }
}

/// The element type of an archive object: its `t`, else its list's `cet`; `n` for null.
fn kind<'a>(el: &Element<'a>, cet: Option<&'a str>) -> &'a str {
    if el.name() == "n" {
        return "null";
    }
    el.attr("t").or(cet).unwrap_or("")
}

/// The child of an archive object with `n="name"`.
pub(crate) fn prop<'e, 'a>(o: &'e Element<'a>, name: &str) -> Option<&'e Element<'a>> {
    o.children.iter().find(|c| c.attr("n") == Some(name))
}

/// The text of the `<v n="name">` child, a `"..."` string unquoted.
pub(crate) fn string(o: &Element, name: &str) -> Option<String> {
    let v = prop(o, name).filter(|v| v.name() == "v")?;
    let raw = v.text_ref();
    let t = raw.trim();
    Some(
        match t.strip_prefix('"').and_then(|s| s.strip_suffix('"')) {
            Some(inner) => inner.replace("\\\"", "\"").replace("\\\\", "\\"),
            None => t.to_string(),
        },
    )
}

/// The `Flags` number of an `Operand` object or a `Flags` object.
fn operand_flags(o: &Element) -> Option<u32> {
    prop(o, "Flags").and_then(flags_value)
}

fn flags_value(f: &Element) -> Option<u32> {
    string(f, "Flags").and_then(|s| s.trim().parse().ok())
}

/// The names (or types) of a box's `InputParam`/`OutputParam` list.
fn param(node: &Element, list: &str, which: &str) -> Vec<String> {
    prop(node, list)
        .and_then(|p| prop(p, which))
        .map(|l| {
            l.children
                .iter()
                .map(|v| v.text_ref().trim().to_string())
                .collect()
        })
        .unwrap_or_default()
}

/// The items of a box's or assignment's `OutputItems` list (`o`: an operand, `n`: flows on).
fn output_items<'e, 'a>(node: &'e Element<'a>) -> Vec<&'e Element<'a>> {
    prop(node, "OutputItems")
        .and_then(|o| prop(o, "OutputItems"))
        .map(|l| l.children.iter().collect())
        .unwrap_or_default()
}

/// The name an operand starts with, upper case (`fb.Q` -> `FB`, `a[i].x` -> `A`).
fn root_name(text: &str) -> String {
    text.trim()
        .split(['.', '[', '^'])
        .next()
        .unwrap_or("")
        .trim()
        .to_ascii_uppercase()
}

/// Whether a network is commented out (TwinCAT does not run it).
fn commented_out(nw: &Element) -> bool {
    string(nw, "OutCommented").as_deref() == Some("true")
}
