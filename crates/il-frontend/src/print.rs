//! Writes a syntax tree back as readable IL.
//!
//! Input: a [`CompilationUnit`] or an instruction list. Output: IEC 61131-3 text with upper-case keywords,
//! names as the user wrote them, declarations and instructions indented by 4 spaces, labels on their own
//! line at the left margin, each `a, b : T` declaration as one line per name.
//! Invariant: parsing the output gives back an equal tree (spans aside), and printing that tree gives the
//! same text (a fixed point); literals print in a canonical form (`T#1h2m3s500ms`, `16#..` as decimal).

use crate::ast::*;
use crate::literal::{NS_PER_DAY, NS_PER_S};
use std::fmt::Write as _;

const INDENT: &str = "    ";

/// The whole compilation unit as IL text.
pub fn unit(u: &CompilationUnit) -> String {
    let mut out = String::new();
    for (i, item) in u.items.iter().enumerate() {
        if i > 0 {
            out.push('\n');
        }
        match item {
            LibraryElement::Pou(p) => pou(&mut out, p),
            LibraryElement::DataTypes(types) => type_block(&mut out, types),
            LibraryElement::Configuration(c) => configuration(&mut out, c),
            LibraryElement::GlobalVars(v) => var_block(&mut out, v, 0),
            LibraryElement::Action(_) => {}
        }
    }
    out
}

/// An instruction list alone: instructions indented by 4 spaces, labels at the margin.
pub fn body(stmts: &[IlStmt]) -> String {
    let mut out = String::new();
    stmt_list(&mut out, stmts, 1);
    out
}

fn indent(out: &mut String, level: usize) {
    for _ in 0..level {
        out.push_str(INDENT);
    }
}

fn pou(out: &mut String, p: &Pou) {
    let (kw, end) = match p.kind {
        PouKind::Program => ("PROGRAM", "END_PROGRAM"),
        PouKind::FunctionBlock => ("FUNCTION_BLOCK", "END_FUNCTION_BLOCK"),
        PouKind::Function => ("FUNCTION", "END_FUNCTION"),
    };
    let _ = write!(out, "{kw} {}", p.name.name);
    if let Some(t) = &p.return_type {
        out.push_str(" : ");
        type_ref(out, t);
    }
    out.push('\n');
    for v in &p.var_blocks {
        var_block(out, v, 0);
    }
    stmt_list(out, &p.body, 1);
    out.push_str(end);
    out.push('\n');
}

fn stmt_list(out: &mut String, stmts: &[IlStmt], level: usize) {
    for s in stmts {
        match s {
            IlStmt::Label(l) => {
                indent(out, level.saturating_sub(1));
                let _ = writeln!(out, "{}:", l.name);
            }
            IlStmt::Instr(i) => instruction(out, i, level),
        }
    }
}

fn op_name(op: Op, negate: bool) -> &'static str {
    match (op, negate) {
        (Op::Ld, false) => "LD",
        (Op::Ld, true) => "LDN",
        (Op::St, false) => "ST",
        (Op::St, true) => "STN",
        (Op::S, _) => "S",
        (Op::R, _) => "R",
        (Op::And, false) => "AND",
        (Op::And, true) => "ANDN",
        (Op::Or, false) => "OR",
        (Op::Or, true) => "ORN",
        (Op::Xor, false) => "XOR",
        (Op::Xor, true) => "XORN",
        (Op::Not, _) => "NOT",
        (Op::Add, _) => "ADD",
        (Op::Sub, _) => "SUB",
        (Op::Mul, _) => "MUL",
        (Op::Div, _) => "DIV",
        (Op::Mod, _) => "MOD",
        (Op::Gt, _) => "GT",
        (Op::Ge, _) => "GE",
        (Op::Eq, _) => "EQ",
        (Op::Ne, _) => "NE",
        (Op::Le, _) => "LE",
        (Op::Lt, _) => "LT",
    }
}

fn cond_suffix(c: Condition) -> &'static str {
    match c {
        Condition::Always => "",
        Condition::IfTrue => "C",
        Condition::IfFalse => "CN",
    }
}

fn instruction(out: &mut String, i: &Instruction, level: usize) {
    indent(out, level);
    match &i.kind {
        InstrKind::Simple {
            op,
            negate,
            operand: o,
        } => {
            out.push_str(op_name(*op, *negate));
            if let Some(o) = o {
                out.push(' ');
                operand(out, o);
            }
        }
        InstrKind::Deferred {
            op,
            negate,
            operand: o,
            body,
            ..
        } => {
            out.push_str(op_name(*op, *negate));
            out.push('(');
            if let Some(o) = o {
                out.push(' ');
                operand(out, o);
            }
            out.push('\n');
            stmt_list(out, body, level + 1);
            indent(out, level);
            out.push(')');
        }
        InstrKind::Jump { cond, label } => {
            let _ = write!(out, "JMP{} {}", cond_suffix(*cond), label.name);
        }
        InstrKind::Return { cond } => {
            let _ = write!(out, "RET{}", cond_suffix(*cond));
        }
        InstrKind::Call {
            cond,
            instance,
            args,
        } => {
            let _ = write!(out, "CAL{} ", cond_suffix(*cond));
            var_ref(out, instance);
            match args {
                CallArgs::None => {}
                CallArgs::NonFormal(ops) => {
                    out.push('(');
                    operand_list(out, ops);
                    out.push(')');
                }
                CallArgs::Formal(f) => formal_args(out, f),
            }
        }
        InstrKind::FunctionCall { name, args } => {
            out.push_str(&name.name);
            match &**args {
                CallArgs::None => {}
                CallArgs::NonFormal(ops) => {
                    out.push(' ');
                    operand_list(out, ops);
                }
                CallArgs::Formal(f) => formal_args(out, f),
            }
        }
        InstrKind::FbInput { op, instance } => {
            let _ = write!(out, "{} ", op.input_name());
            var_ref(out, instance);
        }
        InstrKind::EmbeddedC { name } => {
            let _ = write!(out, "FUNC {}()", name.name);
        }
    }
    out.push('\n');
}

fn operand_list(out: &mut String, ops: &[Operand]) {
    for (i, o) in ops.iter().enumerate() {
        if i > 0 {
            out.push_str(", ");
        }
        operand(out, o);
    }
}

fn formal_args(out: &mut String, args: &[FormalArg]) {
    out.push('(');
    for (i, a) in args.iter().enumerate() {
        if i > 0 {
            out.push_str(", ");
        }
        match a.dir {
            ArgDir::Input => {
                let _ = write!(out, "{} := ", a.name.name);
            }
            ArgDir::Output { negated } => {
                let _ = write!(
                    out,
                    "{}{} => ",
                    if negated { "NOT " } else { "" },
                    a.name.name
                );
            }
        }
        operand(out, &a.value);
    }
    out.push(')');
}

/// A variable access as IL text (`s.a[i]^.b`), for messages.
pub fn var_ref_text(v: &VarRef) -> String {
    let mut s = String::new();
    var_ref(&mut s, v);
    s
}

fn var_ref(out: &mut String, v: &VarRef) {
    out.push_str(&v.base.name);
    for a in &v.accessors {
        match a {
            Accessor::Field(f) => {
                out.push('.');
                out.push_str(&f.name);
            }
            Accessor::Index(ix) => {
                out.push('[');
                operand_list(out, ix);
                out.push(']');
            }
            Accessor::Deref(_) => out.push('^'),
        }
    }
}

/// An operand in IL syntax.
pub fn operand(out: &mut String, o: &Operand) {
    match o {
        Operand::Literal(l) => literal(out, l),
        Operand::Var(v) => var_ref(out, v),
        Operand::Address(a) => address(out, a),
        Operand::EnumValue(e) => {
            let _ = write!(out, "{}#{}", e.type_name.name, e.value.name);
        }
        Operand::Ref(r) => match &r.of {
            Some(v) => {
                out.push_str("REF(");
                var_ref(out, v);
                out.push(')');
            }
            None => out.push_str("NULL"),
        },
        Operand::SizeOf(s) => {
            out.push_str("SIZEOF(");
            var_ref(out, &s.of);
            out.push(')');
        }
        Operand::Mem(m) => {
            out.push_str(m.func.name());
            out.push_str("(ADR(");
            var_ref(out, &m.dest);
            out.push(')');
            if let Some(o) = &m.offsets[0] {
                out.push_str(" + ");
                operand(out, o);
            }
            out.push_str(", ");
            if let Some(s) = &m.src {
                out.push_str("ADR(");
                var_ref(out, s);
                out.push(')');
                if let Some(o) = &m.offsets[1] {
                    out.push_str(" + ");
                    operand(out, o);
                }
                out.push_str(", ");
            }
            if let Some(f) = &m.fill {
                operand(out, f);
                out.push_str(", ");
            }
            operand(out, &m.count);
            out.push(')');
        }
    }
}

fn address(out: &mut String, a: &DirectAddress) {
    out.push('%');
    out.push(match a.area {
        Area::Input => 'I',
        Area::Output => 'Q',
        Area::Memory => 'M',
    });
    out.push(match a.size {
        AddressSize::Bit => 'X',
        AddressSize::Byte => 'B',
        AddressSize::Word => 'W',
        AddressSize::DWord => 'D',
        AddressSize::LWord => 'L',
    });
    if a.path.is_empty() {
        out.push('*');
    }
    for (i, n) in a.path.iter().enumerate() {
        if i > 0 {
            out.push('.');
        }
        let _ = write!(out, "{n}");
    }
}

/// A literal in canonical IL syntax.
pub fn literal(out: &mut String, l: &Literal) {
    let time_prefix = |long: &str, short: &str| {
        if l.type_prefix.is_some() {
            long.to_string()
        } else {
            short.to_string()
        }
    };
    match &l.kind {
        LiteralKind::Duration(ns) => {
            out.push_str(&time_prefix("LTIME#", "T#"));
            duration(out, *ns);
            return;
        }
        LiteralKind::Date(days) => {
            out.push_str(&time_prefix("LDATE#", "D#"));
            date(out, *days);
            return;
        }
        LiteralKind::TimeOfDay(ns) => {
            out.push_str(&time_prefix("LTOD#", "TOD#"));
            time_of_day(out, *ns as i128);
            return;
        }
        LiteralKind::DateAndTime(ns) => {
            out.push_str(&time_prefix("LDT#", "DT#"));
            date(out, ns.div_euclid(NS_PER_DAY) as i64);
            out.push('-');
            time_of_day(out, ns.rem_euclid(NS_PER_DAY));
            return;
        }
        _ => {}
    }
    if let Some(p) = &l.type_prefix {
        let _ = write!(out, "{}#", p.name);
    }
    match &l.kind {
        LiteralKind::Int(v) => {
            let _ = write!(out, "{v}");
        }
        LiteralKind::Real(v) => {
            let _ = write!(out, "{v:?}");
        }
        LiteralKind::Bool(b) => out.push_str(if *b { "TRUE" } else { "FALSE" }),
        LiteralKind::String { wide, value } => string(out, value, *wide),
        _ => {}
    }
}

fn duration(out: &mut String, ns: i128) {
    if ns < 0 {
        out.push('-');
    }
    let mut rest = ns.unsigned_abs();
    if rest == 0 {
        out.push_str("0s");
        return;
    }
    let units: [(u128, &str); 7] = [
        (NS_PER_DAY as u128, "d"),
        (3_600 * NS_PER_S as u128, "h"),
        (60 * NS_PER_S as u128, "m"),
        (NS_PER_S as u128, "s"),
        (1_000_000, "ms"),
        (1_000, "us"),
        (1, "ns"),
    ];
    for (size, name) in units {
        let n = rest / size;
        if n > 0 {
            let _ = write!(out, "{n}{name}");
            rest -= n * size;
        }
    }
}

fn date(out: &mut String, days: i64) {
    // Howard Hinnant's civil_from_days.
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z.rem_euclid(146_097);
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = doy - (153 * mp + 2) / 5 + 1;
    let m = if mp < 10 { mp + 3 } else { mp - 9 };
    let y = yoe + era * 400 + if m <= 2 { 1 } else { 0 };
    let _ = write!(out, "{y:04}-{m:02}-{d:02}");
}

fn time_of_day(out: &mut String, ns: i128) {
    let secs = ns / NS_PER_S;
    let frac = ns % NS_PER_S;
    let _ = write!(
        out,
        "{:02}:{:02}:{:02}",
        secs / 3600,
        secs / 60 % 60,
        secs % 60
    );
    if frac != 0 {
        let digits = format!("{frac:09}");
        let _ = write!(out, ".{}", digits.trim_end_matches('0'));
    }
}

fn string(out: &mut String, value: &str, wide: bool) {
    let quote = if wide { '"' } else { '\'' };
    out.push(quote);
    for c in value.chars() {
        match c {
            '$' => out.push_str("$$"),
            '\n' => out.push_str("$N"),
            '\r' => out.push_str("$R"),
            '\t' => out.push_str("$T"),
            '\u{0C}' => out.push_str("$P"),
            c if c == quote => {
                out.push('$');
                out.push(c);
            }
            c if c.is_control() => {
                if wide {
                    let _ = write!(out, "${:04X}", c as u32);
                } else {
                    let _ = write!(out, "${:02X}", c as u32);
                }
            }
            c => out.push(c),
        }
    }
    out.push(quote);
}

// ---------------------------------------------------------------- declarations

fn var_block(out: &mut String, v: &VarBlock, level: usize) {
    indent(out, level);
    out.push_str(match v.kind {
        VarKind::Local => "VAR",
        VarKind::Input => "VAR_INPUT",
        VarKind::Output => "VAR_OUTPUT",
        VarKind::InOut => "VAR_IN_OUT",
        VarKind::Temp => "VAR_TEMP",
        VarKind::Global => "VAR_GLOBAL",
        VarKind::External => "VAR_EXTERNAL",
    });
    if v.constant {
        out.push_str(" CONSTANT");
    }
    if v.retain {
        out.push_str(" RETAIN");
    }
    out.push('\n');
    for d in &v.vars {
        var_decl(out, d, level + 1);
    }
    indent(out, level);
    out.push_str("END_VAR\n");
}

fn var_decl(out: &mut String, d: &VarDecl, level: usize) {
    indent(out, level);
    out.push_str(&d.name.name);
    if let Some(a) = &d.location {
        out.push_str(" AT ");
        address(out, a);
    }
    out.push_str(" : ");
    type_ref(out, &d.ty);
    if let Some(e) = d.edge {
        out.push(' ');
        out.push_str(e.keyword());
    }
    if let Some(i) = &d.init {
        out.push_str(" := ");
        initializer(out, i);
    }
    out.push_str(";\n");
}

fn type_ref(out: &mut String, t: &TypeRef) {
    match t {
        TypeRef::Named(n) => out.push_str(&n.name),
        TypeRef::Ref { kind, target, .. } => {
            out.push_str(kind.keyword());
            out.push(' ');
            type_ref(out, target);
        }
        TypeRef::String { wide, length, .. } => {
            out.push_str(if *wide { "WSTRING" } else { "STRING" });
            if let Some(n) = length {
                let _ = write!(out, "[{n}]");
            }
        }
        TypeRef::Array { dims, element, .. } => {
            out.push_str("ARRAY [");
            for (i, d) in dims.iter().enumerate() {
                if i > 0 {
                    out.push_str(", ");
                }
                let _ = write!(out, "{}..{}", d.lower, d.upper);
            }
            out.push_str("] OF ");
            type_ref(out, element);
        }
        TypeRef::Subrange {
            base, lower, upper, ..
        } => {
            let _ = write!(out, "{} ({lower}..{upper})", base.name);
        }
        TypeRef::Enum { values, .. } => {
            out.push('(');
            for (i, v) in values.iter().enumerate() {
                if i > 0 {
                    out.push_str(", ");
                }
                out.push_str(&v.name.name);
                if let Some(n) = v.value {
                    let _ = write!(out, " := {n}");
                }
            }
            out.push(')');
        }
    }
}

fn initializer(out: &mut String, i: &Initializer) {
    match i {
        Initializer::Value(o) => operand(out, o),
        Initializer::Array(elems, _) => {
            out.push('[');
            for (k, e) in elems.iter().enumerate() {
                if k > 0 {
                    out.push_str(", ");
                }
                match e.repeat {
                    Some(n) => {
                        let _ = write!(out, "{n}(");
                        initializer(out, &e.value);
                        out.push(')');
                    }
                    None => initializer(out, &e.value),
                }
            }
            out.push(']');
        }
        Initializer::Struct(fields, _) => {
            out.push('(');
            for (k, (name, value)) in fields.iter().enumerate() {
                if k > 0 {
                    out.push_str(", ");
                }
                let _ = write!(out, "{} := ", name.name);
                initializer(out, value);
            }
            out.push(')');
        }
    }
}

fn type_block(out: &mut String, types: &[TypeDecl]) {
    out.push_str("TYPE\n");
    for t in types {
        indent(out, 1);
        let _ = write!(out, "{} : ", t.name.name);
        match &t.def {
            TypeDef::Alias { ty, init } => {
                type_ref(out, ty);
                if let Some(i) = init {
                    out.push_str(" := ");
                    initializer(out, i);
                }
            }
            TypeDef::Struct { fields } => {
                let (open, close) = if t.union {
                    ("UNION\n", "END_UNION")
                } else {
                    ("STRUCT\n", "END_STRUCT")
                };
                out.push_str(open);
                for f in fields {
                    var_decl(out, f, 2);
                }
                indent(out, 1);
                out.push_str(close);
            }
            TypeDef::Enum { values, init } => {
                out.push('(');
                for (i, v) in values.iter().enumerate() {
                    if i > 0 {
                        out.push_str(", ");
                    }
                    out.push_str(&v.name.name);
                    if let Some(n) = v.value {
                        let _ = write!(out, " := {n}");
                    }
                }
                out.push(')');
                if let Some(i) = init {
                    let _ = write!(out, " := {}", i.name);
                }
            }
        }
        out.push_str(";\n");
    }
    out.push_str("END_TYPE\n");
}

fn configuration(out: &mut String, c: &Configuration) {
    let _ = writeln!(out, "CONFIGURATION {}", c.name.name);
    for g in &c.globals {
        var_block(out, g, 1);
    }
    for r in &c.resources {
        indent(out, 1);
        let _ = write!(out, "RESOURCE {}", r.name.name);
        if let Some(on) = &r.on {
            let _ = write!(out, " ON {}", on.name);
        }
        out.push('\n');
        for g in &r.globals {
            var_block(out, g, 2);
        }
        for t in &r.tasks {
            indent(out, 2);
            let _ = write!(out, "TASK {} (", t.name.name);
            let mut first = true;
            let mut sep = |out: &mut String| {
                if !first {
                    out.push_str(", ");
                }
                first = false;
            };
            if let Some(i) = &t.interval {
                sep(out);
                out.push_str("INTERVAL := ");
                operand(out, i);
            }
            if let Some(s) = &t.single {
                sep(out);
                out.push_str("SINGLE := ");
                operand(out, s);
            }
            if let Some(p) = t.priority {
                sep(out);
                let _ = write!(out, "PRIORITY := {p}");
            }
            out.push_str(");\n");
        }
        for p in &r.programs {
            indent(out, 2);
            out.push_str("PROGRAM ");
            if p.retain {
                out.push_str("RETAIN ");
            }
            out.push_str(&p.name.name);
            if let Some(t) = &p.task {
                let _ = write!(out, " WITH {}", t.name);
            }
            let _ = write!(out, " : {}", p.type_name.name);
            if !p.args.is_empty() {
                formal_args(out, &p.args);
            }
            out.push_str(";\n");
        }
        indent(out, 1);
        out.push_str("END_RESOURCE\n");
    }
    out.push_str("END_CONFIGURATION\n");
}
