//! Test support for the sema tests: a deliberately small, line-based reader of a subset of IL that builds
//! `ast` values with real byte spans (the tests were written before the real parser existed; `analyze_src`
//! uses the real `il_frontend::parse` when the `real_parser` cfg is set), and rendering of diagnostics
//! with the source for snapshots.
//!
//! Subset: one declaration or instruction per line; `PROGRAM`/`FUNCTION_BLOCK`/`FUNCTION name [: T]`,
//! `VAR*` blocks with `name : T [:= literal];` lines, `TYPE name : (a, b); END_TYPE` enums and aliases,
//! `label:` (alone or before an instruction), operators with one operand, `OP(` ... `)`, `JMP*`, `RET*`,
//! `CAL* inst [(args)]`, function calls `NAME a, b` / `NAME(f := x)`, FB input operators, `FUNC N()`.
#![allow(dead_code)]

use diagnostics::{render_human, Diagnostics, FileId, SourceMap, Span};
use il_frontend::ast::*;
use il_frontend::sema::{analyze, Model};

/// Analyses one source text; returns the model and the rendered diagnostics (human form, sorted).
pub fn analyze_src(src: &str) -> (Model, String) {
    let mut map = SourceMap::new();
    let file = map.add("test.il", src.to_string());
    let unit = read(file, src);
    let mut diags = Diagnostics::new();
    let model = analyze(&[unit], &mut diags);
    let list = diags.into_sorted();
    (model, render_human(&map, &list))
}

/// Source and diagnostics together, for snapshots.
pub fn check(src: &str) -> String {
    let (_, diags) = analyze_src(src);
    format!(
        "{src}\n---- diagnostics ----\n{}",
        if diags.is_empty() {
            "(none)\n".into()
        } else {
            diags
        }
    )
}

/// The codes of the diagnostics, in order.
pub fn codes(src: &str) -> Vec<String> {
    let mut map = SourceMap::new();
    let file = map.add("test.il", src.to_string());
    let unit = read(file, src);
    let mut diags = Diagnostics::new();
    analyze(&[unit], &mut diags);
    diags
        .into_sorted()
        .into_iter()
        .map(|d| d.code.0.to_string())
        .collect()
}

struct Reader<'s> {
    file: FileId,
    src: &'s str,
}

/// A token with its byte range.
#[derive(Debug, Clone)]
struct Tok {
    text: String,
    start: usize,
    end: usize,
}

fn tokenize(line: &str, base: usize) -> Vec<Tok> {
    let b = line.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while i < b.len() {
        let c = b[i] as char;
        if c.is_whitespace() {
            i += 1;
            continue;
        }
        if c == '(' && b.get(i + 1) == Some(&b'*') {
            // comment to end of line or `*)`
            match line[i..].find("*)") {
                Some(e) => {
                    i += e + 2;
                    continue;
                }
                None => break,
            }
        }
        let start = i;
        if c == '\'' || c == '"' {
            i += 1;
            while i < b.len() && b[i] as char != c {
                i += 1;
            }
            i += 1;
        } else if matches!(
            (c, b.get(i + 1)),
            (':', Some(b'=')) | ('=', Some(b'>')) | ('.', Some(b'.'))
        ) {
            i += 2;
        } else if "(),;:[]".contains(c) {
            i += 1;
        } else {
            while i < b.len() {
                let d = b[i] as char;
                if d.is_whitespace()
                    || "(),;[]".contains(d)
                    || (d == ':' && b.get(i + 1) != Some(&b'=') && !line[start..i].contains('#'))
                {
                    break;
                }
                if d == ':' && b.get(i + 1) == Some(&b'=') {
                    break;
                }
                if d == '.' && b.get(i + 1) == Some(&b'.') {
                    break;
                }
                if d == '=' && b.get(i + 1) == Some(&b'>') {
                    break;
                }
                i += 1;
            }
        }
        out.push(Tok {
            text: line[start..i.min(b.len())].to_string(),
            start: base + start,
            end: base + i.min(b.len()),
        });
    }
    out
}

pub fn read(file: FileId, src: &str) -> CompilationUnit {
    let r = Reader { file, src };
    r.unit()
}

impl Reader<'_> {
    fn span(&self, s: usize, e: usize) -> Span {
        Span::new(self.file, s, e)
    }
    fn ident(&self, t: &Tok) -> Ident {
        Ident::new(t.text.clone(), self.span(t.start, t.end))
    }

    fn lines(&self) -> Vec<Vec<Tok>> {
        let mut out = Vec::new();
        let mut off = 0;
        for l in self.src.split_inclusive('\n') {
            let toks = tokenize(l.trim_end_matches(['\n', '\r']), off);
            off += l.len();
            if !toks.is_empty() {
                out.push(toks);
            }
        }
        out
    }

    fn unit(&self) -> CompilationUnit {
        let lines = self.lines();
        let mut items = Vec::new();
        let mut i = 0;
        while i < lines.len() {
            let kw = lines[i][0].text.to_ascii_uppercase();
            match kw.as_str() {
                "PROGRAM" | "FUNCTION_BLOCK" | "FUNCTION" => {
                    let (pou, next) = self.pou(&lines, i);
                    items.push(LibraryElement::Pou(pou));
                    i = next;
                }
                "TYPE" => {
                    i += 1;
                    let mut decls = Vec::new();
                    while !lines[i][0].text.eq_ignore_ascii_case("END_TYPE") {
                        let l = &lines[i];
                        let name = self.ident(&l[0]);
                        let span = self.span(l[0].start, l[l.len() - 1].end);
                        let def = if l[2].text == "(" {
                            let values = l[3..]
                                .iter()
                                .filter(|t| !matches!(t.text.as_str(), "," | ")" | ";"))
                                .map(|t| EnumValue {
                                    name: self.ident(t),
                                    value: None,
                                })
                                .collect();
                            TypeDef::Enum { values, init: None }
                        } else if l[2].text.eq_ignore_ascii_case("STRUCT") {
                            let mut fields = Vec::new();
                            i += 1;
                            while !lines[i][0].text.eq_ignore_ascii_case("END_STRUCT") {
                                fields.push(self.var_decl(&lines[i]));
                                i += 1;
                            }
                            TypeDef::Struct { fields }
                        } else {
                            let (ty, rest) = self.type_ref(&l[2..]);
                            let init = rest
                                .iter()
                                .position(|t| t.text == ":=")
                                .map(|p| Initializer::Value(self.operand(&rest[p + 1..])));
                            TypeDef::Alias { ty, init }
                        };
                        decls.push(TypeDecl { name, def, span });
                        i += 1;
                    }
                    items.push(LibraryElement::DataTypes(decls));
                    i += 1;
                }
                "VAR_GLOBAL" => {
                    let (b, next) = self.var_block(&lines, i);
                    items.push(LibraryElement::GlobalVars(b));
                    i = next;
                }
                "CONFIGURATION" => {
                    let (c, next) = self.configuration(&lines, i);
                    items.push(LibraryElement::Configuration(c));
                    i = next;
                }
                _ => panic!("test reader: unexpected line starting {kw}"),
            }
        }
        CompilationUnit { items }
    }

    /// `CONFIGURATION` with `VAR_GLOBAL` blocks and `RESOURCE`s holding `TASK name(INTERVAL := T#.., PRIORITY := n);`
    /// and `PROGRAM inst [WITH task] : Type [(a := x, b => y)];` lines.
    fn configuration(&self, lines: &[Vec<Tok>], mut i: usize) -> (Configuration, usize) {
        let name = self.ident(&lines[i][1]);
        let start = lines[i][0].start;
        i += 1;
        let mut globals = Vec::new();
        let mut resources = Vec::new();
        while !lines[i][0].text.eq_ignore_ascii_case("END_CONFIGURATION") {
            let kw = lines[i][0].text.to_ascii_uppercase();
            if kw == "VAR_GLOBAL" {
                let (b, next) = self.var_block(lines, i);
                globals.push(b);
                i = next;
                continue;
            }
            assert_eq!(kw, "RESOURCE", "test reader: configuration line");
            let rname = self.ident(&lines[i][1]);
            let rstart = lines[i][0].start;
            i += 1;
            let mut tasks = Vec::new();
            let mut programs = Vec::new();
            let mut rglobals = Vec::new();
            while !lines[i][0].text.eq_ignore_ascii_case("END_RESOURCE") {
                let l = &lines[i];
                let span = self.span(l[0].start, l[l.len() - 1].end);
                match l[0].text.to_ascii_uppercase().as_str() {
                    "VAR_GLOBAL" => {
                        let (b, next) = self.var_block(lines, i);
                        rglobals.push(b);
                        i = next;
                        continue;
                    }
                    "TASK" => {
                        let find = |k: &str| {
                            l.iter()
                                .position(|t| t.text.eq_ignore_ascii_case(k))
                                .map(|p| &l[p + 2])
                        };
                        tasks.push(Task {
                            name: self.ident(&l[1]),
                            interval: find("INTERVAL")
                                .map(|t| self.operand(std::slice::from_ref(t))),
                            single: find("SINGLE").map(|t| self.operand(std::slice::from_ref(t))),
                            priority: find("PRIORITY").and_then(|t| t.text.parse().ok()),
                            span,
                        });
                    }
                    _ => {
                        let task =
                            (l[2].text.eq_ignore_ascii_case("WITH")).then(|| self.ident(&l[3]));
                        let colon = l.iter().position(|t| t.text == ":").unwrap();
                        let args = match self.args(&l[colon + 2..l.len() - 1]) {
                            CallArgs::Formal(a) => a,
                            _ => Vec::new(),
                        };
                        programs.push(ProgramInstance {
                            name: self.ident(&l[1]),
                            retain: false,
                            task,
                            type_name: self.ident(&l[colon + 1]),
                            args,
                            span,
                        });
                    }
                }
                i += 1;
            }
            resources.push(Resource {
                name: rname,
                on: None,
                globals: rglobals,
                tasks,
                programs,
                span: self.span(rstart, lines[i][0].end),
            });
            i += 1;
        }
        let end = lines[i][0].end;
        (
            Configuration {
                name,
                globals,
                resources,
                span: self.span(start, end),
            },
            i + 1,
        )
    }

    fn pou(&self, lines: &[Vec<Tok>], mut i: usize) -> (Pou, usize) {
        let head = &lines[i];
        let kind = match head[0].text.to_ascii_uppercase().as_str() {
            "PROGRAM" => PouKind::Program,
            "FUNCTION_BLOCK" => PouKind::FunctionBlock,
            _ => PouKind::Function,
        };
        let name = self.ident(&head[1]);
        let return_type =
            (head.len() > 3 && head[2].text == ":").then(|| self.type_ref(&head[3..]).0);
        let start = head[0].start;
        i += 1;
        let mut var_blocks = Vec::new();
        while lines[i][0].text.to_ascii_uppercase().starts_with("VAR") {
            let (b, next) = self.var_block(lines, i);
            var_blocks.push(b);
            i = next;
        }
        let mut body_lines = Vec::new();
        while !lines[i][0].text.to_ascii_uppercase().starts_with("END_") {
            body_lines.push(lines[i].clone());
            i += 1;
        }
        let end = lines[i][0].end;
        let mut pos = 0;
        let body = self.stmts(&body_lines, &mut pos, false);
        (
            Pou {
                kind,
                name,
                return_type,
                var_blocks,
                body,
                span: self.span(start, end),
            },
            i + 1,
        )
    }

    fn var_block(&self, lines: &[Vec<Tok>], mut i: usize) -> (VarBlock, usize) {
        let head = &lines[i];
        let kind = match head[0].text.to_ascii_uppercase().as_str() {
            "VAR_INPUT" => VarKind::Input,
            "VAR_OUTPUT" => VarKind::Output,
            "VAR_IN_OUT" => VarKind::InOut,
            "VAR_TEMP" => VarKind::Temp,
            "VAR_GLOBAL" => VarKind::Global,
            "VAR_EXTERNAL" => VarKind::External,
            _ => VarKind::Local,
        };
        let constant = head.iter().any(|t| t.text.eq_ignore_ascii_case("CONSTANT"));
        let retain = head.iter().any(|t| t.text.eq_ignore_ascii_case("RETAIN"));
        let start = head[0].start;
        i += 1;
        let mut vars = Vec::new();
        while !lines[i][0].text.eq_ignore_ascii_case("END_VAR") {
            // `a, b : INT;` declares two.
            let l = &lines[i];
            if l[1].text.eq_ignore_ascii_case("AT") {
                vars.push(self.var_decl(l));
                i += 1;
                continue;
            }
            let colon = l
                .iter()
                .position(|t| t.text == ":")
                .expect("`:` in declaration");
            let rest: Vec<Tok> = l[colon..].to_vec();
            for t in l[..colon].iter().filter(|t| t.text != ",") {
                let mut line = vec![t.clone()];
                line.extend(rest.iter().cloned());
                vars.push(self.var_decl(&line));
            }
            i += 1;
        }
        let end = lines[i][0].end;
        (
            VarBlock {
                kind,
                constant,
                retain,
                vars,
                span: self.span(start, end),
            },
            i + 1,
        )
    }

    fn var_decl(&self, l: &[Tok]) -> VarDecl {
        let name = self.ident(&l[0]);
        let mut k = 2;
        let mut location = None;
        if l[1].text.eq_ignore_ascii_case("AT") {
            location = match self.operand(&l[2..3]) {
                Operand::Address(a) => Some(a),
                _ => None,
            };
            k = 4; // name AT %addr : type
        }
        let (ty, rest) = self.type_ref(&l[k..]);
        let init = rest.iter().position(|t| t.text == ":=").map(|p| {
            let r = &rest[p + 1..];
            if r[0].text == "[" {
                let elems = r[1..]
                    .iter()
                    .filter(|t| !matches!(t.text.as_str(), "," | "]" | ";"))
                    .map(|t| ArrayInitElement {
                        repeat: None,
                        value: Initializer::Value(self.operand(std::slice::from_ref(t))),
                    })
                    .collect();
                Initializer::Array(elems, self.span(r[0].start, r[r.len() - 1].end))
            } else if r[0].text == "(" {
                let mut fields = Vec::new();
                let mut j = 1;
                while j + 2 < r.len() {
                    fields.push((
                        self.ident(&r[j]),
                        Initializer::Value(self.operand(&r[j + 2..j + 3])),
                    ));
                    j += 4;
                }
                Initializer::Struct(fields, self.span(r[0].start, r[r.len() - 1].end))
            } else {
                Initializer::Value(self.operand(&r[..1]))
            }
        });
        let end = l[l.len() - 1].end;
        VarDecl {
            name,
            location,
            ty,
            init,
            span: self.span(l[0].start, end),
        }
    }

    /// A type: `INT`, `STRING[10]`, `ARRAY [0..9] OF INT`, `INT (0..10)`; returns the rest.
    fn type_ref<'t>(&self, t: &'t [Tok]) -> (TypeRef, &'t [Tok]) {
        let first = &t[0];
        if first.text.eq_ignore_ascii_case("ARRAY") {
            let mut dims = Vec::new();
            let mut j = 2;
            loop {
                let lo: i128 = t[j].text.parse().unwrap();
                let hi: i128 = t[j + 2].text.parse().unwrap();
                dims.push(ArrayDim {
                    lower: lo,
                    upper: hi,
                    span: self.span(t[j].start, t[j + 2].end),
                });
                j += 3;
                if t[j].text == "]" {
                    break;
                }
                j += 1;
            }
            let (el, rest) = self.type_ref(&t[j + 2..]);
            let span = self.span(first.start, el.span().end as usize);
            return (
                TypeRef::Array {
                    dims,
                    element: Box::new(el),
                    span,
                },
                rest,
            );
        }
        if (first.text.eq_ignore_ascii_case("STRING") || first.text.eq_ignore_ascii_case("WSTRING"))
            && t.get(1).is_some_and(|x| x.text == "[")
        {
            return (
                TypeRef::String {
                    wide: first.text.eq_ignore_ascii_case("WSTRING"),
                    length: t[2].text.parse().ok(),
                    span: self.span(first.start, t[3].end),
                },
                &t[4..],
            );
        }
        if t.get(1).is_some_and(|x| x.text == "(") && t.get(3).is_some_and(|x| x.text == "..") {
            return (
                TypeRef::Subrange {
                    base: self.ident(first),
                    lower: t[2].text.parse().unwrap(),
                    upper: t[4].text.parse().unwrap(),
                    span: self.span(first.start, t[5].end),
                },
                &t[6..],
            );
        }
        (TypeRef::Named(self.ident(first)), &t[1..])
    }

    fn literal(&self, t: &Tok) -> Option<Literal> {
        let span = self.span(t.start, t.end);
        let text = t.text.replace('_', "");
        let (prefix, body) = match text.split_once('#') {
            Some((p, b)) if !p.chars().all(|c| c.is_ascii_digit()) => {
                (Some(p.to_string()), b.to_string())
            }
            _ => (None, text.clone()),
        };
        let up = prefix.as_deref().map(str::to_ascii_uppercase);
        let kind = match up.as_deref() {
            Some("T" | "TIME" | "LTIME") => LiteralKind::Duration(parse_duration(&body)),
            _ => {
                if body.eq_ignore_ascii_case("TRUE") {
                    LiteralKind::Bool(true)
                } else if body.eq_ignore_ascii_case("FALSE") {
                    LiteralKind::Bool(false)
                } else if let Some(s) = body.strip_prefix('\'') {
                    LiteralKind::String {
                        wide: false,
                        value: s.trim_end_matches('\'').to_string(),
                    }
                } else if let Some((base, digits)) = body.split_once('#') {
                    LiteralKind::Int(i128::from_str_radix(digits, base.parse().ok()?).ok()?)
                } else if let Ok(v) = body.parse::<i128>() {
                    LiteralKind::Int(v)
                } else if body.starts_with(|c: char| c.is_ascii_digit() || c == '-') {
                    LiteralKind::Real(body.parse().ok()?)
                } else {
                    return None;
                }
            }
        };
        let type_prefix = match up.as_deref() {
            None | Some("T") => None,
            Some(_) => prefix
                .map(|p| Ident::new(p, self.span(t.start, t.start + t.text.find('#').unwrap()))),
        };
        Some(Literal {
            kind,
            type_prefix,
            span,
        })
    }

    fn operand(&self, t: &[Tok]) -> Operand {
        let first = &t[0];
        if let Some(l) = self.literal(first) {
            return Operand::Literal(l);
        }
        if let Some(a) = first.text.strip_prefix('%') {
            let mut ch = a.chars();
            let area = match ch.next().unwrap().to_ascii_uppercase() {
                'I' => Area::Input,
                'Q' => Area::Output,
                _ => Area::Memory,
            };
            let rest: String = ch.collect();
            let (size, nums) = match rest.chars().next().unwrap().to_ascii_uppercase() {
                'X' => (AddressSize::Bit, &rest[1..]),
                'B' => (AddressSize::Byte, &rest[1..]),
                'W' => (AddressSize::Word, &rest[1..]),
                'D' => (AddressSize::DWord, &rest[1..]),
                'L' => (AddressSize::LWord, &rest[1..]),
                _ => (AddressSize::Bit, &rest[..]),
            };
            return Operand::Address(DirectAddress {
                area,
                size,
                path: nums.split('.').filter_map(|n| n.parse().ok()).collect(),
                span: self.span(first.start, first.end),
            });
        }
        if let Some((ty, val)) = first.text.split_once('#') {
            let s = first.start;
            return Operand::EnumValue {
                type_name: Ident::new(ty, self.span(s, s + ty.len())),
                value: Ident::new(val, self.span(s + ty.len() + 1, first.end)),
                span: self.span(s, first.end),
            };
        }
        // x, a.b, arr[i]
        let mut parts = first.text.split('.');
        let base_text = parts.next().unwrap();
        let base = Ident::new(
            base_text,
            self.span(first.start, first.start + base_text.len()),
        );
        let mut accessors = Vec::new();
        let mut off = first.start + base_text.len();
        for p in parts {
            off += 1;
            accessors.push(Accessor::Field(Ident::new(
                p,
                self.span(off, off + p.len()),
            )));
            off += p.len();
        }
        let mut end = first.end;
        if t.get(1).is_some_and(|x| x.text == "[") {
            let close = t.iter().position(|x| x.text == "]").unwrap();
            let idx = t[2..close]
                .iter()
                .filter(|x| x.text != ",")
                .map(|x| self.operand(std::slice::from_ref(x)))
                .collect();
            accessors.push(Accessor::Index(idx));
            end = t[close].end;
        }
        Operand::Var(VarRef {
            base,
            accessors,
            span: self.span(first.start, end),
        })
    }

    fn var_ref(&self, t: &[Tok]) -> VarRef {
        match self.operand(t) {
            Operand::Var(v) => v,
            _ => panic!("test reader: expected a variable"),
        }
    }

    fn args(&self, t: &[Tok]) -> CallArgs {
        // t starts after the callee; `( ... )` formal or `a, b` non-formal
        if t.is_empty() {
            return CallArgs::None;
        }
        if t[0].text == "(" {
            let inner = &t[1..t.len() - 1];
            if inner.is_empty() {
                return CallArgs::None;
            }
            if inner.iter().any(|x| x.text == ":=" || x.text == "=>") {
                let mut out = Vec::new();
                for part in inner.split(|x| x.text == ",") {
                    let negated = part[0].text.eq_ignore_ascii_case("NOT");
                    let p = if negated { &part[1..] } else { part };
                    let dir = if p[1].text == "=>" {
                        ArgDir::Output { negated }
                    } else {
                        ArgDir::Input
                    };
                    out.push(FormalArg {
                        name: self.ident(&p[0]),
                        dir,
                        value: self.operand(&p[2..]),
                        span: self.span(part[0].start, part[part.len() - 1].end),
                    });
                }
                return CallArgs::Formal(out);
            }
            return CallArgs::NonFormal(
                inner
                    .split(|x| x.text == ",")
                    .map(|p| self.operand(p))
                    .collect(),
            );
        }
        CallArgs::NonFormal(
            t.split(|x| x.text == ",")
                .map(|p| self.operand(p))
                .collect(),
        )
    }

    /// Statements until the end or (when `nested`) a line `)`.
    fn stmts(&self, lines: &[Vec<Tok>], pos: &mut usize, nested: bool) -> Vec<IlStmt> {
        let mut out = Vec::new();
        while *pos < lines.len() {
            let mut l: &[Tok] = &lines[*pos];
            if nested && l[0].text == ")" {
                return out;
            }
            *pos += 1;
            if l.len() >= 2 && l[1].text == ":" {
                out.push(IlStmt::Label(self.ident(&l[0])));
                l = &l[2..];
                if l.is_empty() {
                    continue;
                }
            }
            let start = l[0].start;
            let end = l[l.len() - 1].end;
            let span = self.span(start, end);
            let kw = l[0].text.to_ascii_uppercase();
            let kind = if l.len() >= 2
                && l[1].text == "("
                && simple_op(&kw).is_some()
                && !l.iter().any(|x| x.text == ":=")
            {
                let (op, negate) = simple_op(&kw).unwrap();
                let operand = (l.len() > 2).then(|| self.operand(&l[2..]));
                let body = self.stmts(lines, pos, true);
                let close_tok = &lines[*pos][0];
                *pos += 1;
                let close = self.span(close_tok.start, close_tok.end);
                out.push(IlStmt::Instr(Instruction {
                    kind: InstrKind::Deferred {
                        op,
                        negate,
                        operand,
                        body,
                        close,
                    },
                    span: self.span(start, close.end as usize),
                }));
                continue;
            } else if let Some((op, negate)) = simple_op(&kw) {
                InstrKind::Simple {
                    op,
                    negate,
                    operand: (l.len() > 1).then(|| self.operand(&l[1..])),
                }
            } else if let Some(cond) = cond_of(&kw, "JMP") {
                InstrKind::Jump {
                    cond,
                    label: self.ident(&l[1]),
                }
            } else if let Some(cond) = cond_of(&kw, "RET") {
                InstrKind::Return { cond }
            } else if let Some(cond) = cond_of(&kw, "CAL") {
                InstrKind::Call {
                    cond,
                    instance: self.var_ref(&l[1..2]),
                    args: self.args(&l[2..]),
                }
            } else if kw == "FUNC" {
                InstrKind::EmbeddedC {
                    name: self.ident(&l[1]),
                }
            } else if let Some(op) = fb_input_op(&kw) {
                InstrKind::FbInput {
                    op,
                    instance: self.var_ref(&l[1..]),
                }
            } else {
                InstrKind::FunctionCall {
                    name: self.ident(&l[0]),
                    args: self.args(&l[1..]),
                }
            };
            out.push(IlStmt::Instr(Instruction { kind, span }));
        }
        out
    }
}

fn simple_op(kw: &str) -> Option<(Op, bool)> {
    let (base, neg) = match kw {
        "LDN" | "STN" | "ANDN" | "ORN" | "XORN" => (&kw[..kw.len() - 1], true),
        _ => (kw, false),
    };
    let op = match base {
        "LD" => Op::Ld,
        "ST" => Op::St,
        "S" => Op::S,
        "R" => Op::R,
        "AND" => Op::And,
        "OR" => Op::Or,
        "XOR" => Op::Xor,
        "NOT" => Op::Not,
        "ADD" => Op::Add,
        "SUB" => Op::Sub,
        "MUL" => Op::Mul,
        "DIV" => Op::Div,
        "MOD" => Op::Mod,
        "GT" => Op::Gt,
        "GE" => Op::Ge,
        "EQ" => Op::Eq,
        "NE" => Op::Ne,
        "LE" => Op::Le,
        "LT" => Op::Lt,
        _ => return None,
    };
    Some((op, neg))
}

fn cond_of(kw: &str, base: &str) -> Option<Condition> {
    let rest = kw.strip_prefix(base)?;
    match rest {
        "" => Some(Condition::Always),
        "C" => Some(Condition::IfTrue),
        "CN" | "NC" => Some(Condition::IfFalse),
        _ => None,
    }
}

fn fb_input_op(kw: &str) -> Option<FbInputOp> {
    Some(match kw {
        "S1" => FbInputOp::S1,
        "R1" => FbInputOp::R1,
        "CLK" => FbInputOp::Clk,
        "CU" => FbInputOp::Cu,
        "CD" => FbInputOp::Cd,
        "PV" => FbInputOp::Pv,
        "IN" => FbInputOp::In,
        "PT" => FbInputOp::Pt,
        _ => return None,
    })
}

fn parse_duration(body: &str) -> i128 {
    let mut total: f64 = 0.0;
    let mut num = String::new();
    let b = body.to_ascii_lowercase();
    let mut chars = b.chars().peekable();
    while let Some(c) = chars.next() {
        if c.is_ascii_digit() || c == '.' {
            num.push(c);
            continue;
        }
        let unit = if c == 'm' && chars.peek() == Some(&'s') {
            chars.next();
            1e6
        } else if c == 'm' {
            60e9
        } else if c == 's' {
            1e9
        } else if c == 'h' {
            3600e9
        } else if c == 'd' {
            86400e9
        } else {
            0.0
        };
        total += num.parse::<f64>().unwrap_or(0.0) * unit;
        num.clear();
    }
    total as i128
}
