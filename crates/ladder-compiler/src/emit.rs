//! IL text for a compilation unit: what `ladderc` shows for a lowered XML project.
//!
//! Input: an [`ast::CompilationUnit`]. Output: IEC 61131-3 IL source (TYPE, POUs with their variable
//! blocks and instruction lists, CONFIGURATION), one instruction per line, nested lists indented.
//! Invariants: every construct of the tree is printed in the standard's syntax, so the text parses back
//! to the same tree (spans aside); hidden names keep their `__` prefix.

use il_frontend::ast::*;
use std::fmt::Write as _;

pub fn unit(u: &CompilationUnit) -> String {
    let mut out = String::new();
    for (i, item) in u.items.iter().enumerate() {
        if i > 0 {
            out.push('\n');
        }
        match item {
            LibraryElement::DataTypes(ts) => types(ts, &mut out),
            LibraryElement::Pou(p) => pou(p, &mut out),
            LibraryElement::Configuration(c) => configuration(c, &mut out),
            LibraryElement::GlobalVars(b) => var_block(b, "", &mut out),
        }
    }
    out
}

fn types(ts: &[TypeDecl], out: &mut String) {
    out.push_str("TYPE\n");
    for t in ts {
        let _ = write!(out, "  {} : ", t.name.name);
        match &t.def {
            TypeDef::Alias { ty, init } => {
                out.push_str(&type_ref(ty));
                if let Some(i) = init {
                    let _ = write!(out, " := {}", initializer(i));
                }
            }
            TypeDef::Struct { fields } => {
                out.push_str("STRUCT\n");
                for f in fields {
                    let _ = writeln!(out, "    {}", var_decl(f));
                }
                out.push_str("  END_STRUCT");
            }
            TypeDef::Enum { values, init } => {
                let vs: Vec<String> = values
                    .iter()
                    .map(|v| match v.value {
                        Some(n) => format!("{} := {n}", v.name.name),
                        None => v.name.name.clone(),
                    })
                    .collect();
                let _ = write!(out, "({})", vs.join(", "));
                if let Some(i) = init {
                    let _ = write!(out, " := {}", i.name);
                }
            }
        }
        out.push_str(";\n");
    }
    out.push_str("END_TYPE\n");
}

fn pou(p: &Pou, out: &mut String) {
    let (kw, end) = match p.kind {
        PouKind::Program => ("PROGRAM", "END_PROGRAM"),
        PouKind::FunctionBlock => ("FUNCTION_BLOCK", "END_FUNCTION_BLOCK"),
        PouKind::Function => ("FUNCTION", "END_FUNCTION"),
    };
    let _ = write!(out, "{kw} {}", p.name.name);
    if let Some(r) = &p.return_type {
        let _ = write!(out, " : {}", type_ref(r));
    }
    out.push('\n');
    for b in &p.var_blocks {
        var_block(b, "", out);
    }
    body(&p.body, 1, out);
    let _ = writeln!(out, "{end}");
}

fn var_block(b: &VarBlock, indent: &str, out: &mut String) {
    let kw = match b.kind {
        VarKind::Local => "VAR",
        VarKind::Input => "VAR_INPUT",
        VarKind::Output => "VAR_OUTPUT",
        VarKind::InOut => "VAR_IN_OUT",
        VarKind::Temp => "VAR_TEMP",
        VarKind::Global => "VAR_GLOBAL",
        VarKind::External => "VAR_EXTERNAL",
    };
    let _ = write!(out, "{indent}{kw}");
    if b.constant {
        out.push_str(" CONSTANT");
    }
    if b.retain {
        out.push_str(" RETAIN");
    }
    out.push('\n');
    for v in &b.vars {
        let _ = writeln!(out, "{indent}  {}", var_decl(v));
    }
    let _ = writeln!(out, "{indent}END_VAR");
}

fn var_decl(v: &VarDecl) -> String {
    let mut s = v.name.name.clone();
    if let Some(a) = &v.location {
        let _ = write!(s, " AT {}", address(a));
    }
    let _ = write!(s, " : {}", type_ref(&v.ty));
    if let Some(i) = &v.init {
        let _ = write!(s, " := {}", initializer(i));
    }
    s.push(';');
    s
}

pub fn type_ref(t: &TypeRef) -> String {
    match t {
        TypeRef::Named(n) => n.name.clone(),
        TypeRef::String { wide, length, .. } => {
            let kw = if *wide { "WSTRING" } else { "STRING" };
            match length {
                Some(l) => format!("{kw}[{l}]"),
                None => kw.to_string(),
            }
        }
        TypeRef::Array { dims, element, .. } => {
            let ds: Vec<String> = dims
                .iter()
                .map(|d| format!("{}..{}", d.lower, d.upper))
                .collect();
            format!("ARRAY [{}] OF {}", ds.join(", "), type_ref(element))
        }
        TypeRef::Subrange {
            base, lower, upper, ..
        } => format!("{} ({lower}..{upper})", base.name),
        TypeRef::Enum { values, .. } => {
            let vs: Vec<&str> = values.iter().map(|v| v.name.as_str()).collect();
            format!("({})", vs.join(", "))
        }
    }
}

fn initializer(i: &Initializer) -> String {
    match i {
        Initializer::Value(o) => operand(o),
        Initializer::Array(es, _) => {
            let parts: Vec<String> = es
                .iter()
                .map(|e| match e.repeat {
                    Some(n) => format!("{n}({})", initializer(&e.value)),
                    None => initializer(&e.value),
                })
                .collect();
            format!("[{}]", parts.join(", "))
        }
        Initializer::Struct(fs, _) => {
            let parts: Vec<String> = fs
                .iter()
                .map(|(n, v)| format!("{} := {}", n.name, initializer(v)))
                .collect();
            format!("({})", parts.join(", "))
        }
    }
}

fn body(stmts: &[IlStmt], depth: usize, out: &mut String) {
    let pad = "  ".repeat(depth);
    for s in stmts {
        match s {
            IlStmt::Label(l) => {
                let _ = writeln!(out, "{}{}:", "  ".repeat(depth.saturating_sub(1)), l.name);
            }
            IlStmt::Instr(i) => instruction(&i.kind, depth, &pad, out),
        }
    }
}

fn op_name(op: Op) -> &'static str {
    match op {
        Op::Ld => "LD",
        Op::St => "ST",
        Op::S => "S",
        Op::R => "R",
        Op::And => "AND",
        Op::Or => "OR",
        Op::Xor => "XOR",
        Op::Not => "NOT",
        Op::Add => "ADD",
        Op::Sub => "SUB",
        Op::Mul => "MUL",
        Op::Div => "DIV",
        Op::Mod => "MOD",
        Op::Gt => "GT",
        Op::Ge => "GE",
        Op::Eq => "EQ",
        Op::Ne => "NE",
        Op::Le => "LE",
        Op::Lt => "LT",
    }
}

fn cond_suffix(c: Condition) -> &'static str {
    match c {
        Condition::Always => "",
        Condition::IfTrue => "C",
        Condition::IfFalse => "CN",
    }
}

fn instruction(k: &InstrKind, depth: usize, pad: &str, out: &mut String) {
    match k {
        InstrKind::Simple {
            op,
            negate,
            operand: o,
        } => {
            let _ = write!(
                out,
                "{pad}{}{}",
                op_name(*op),
                if *negate { "N" } else { "" }
            );
            if let Some(o) = o {
                let _ = write!(out, " {}", operand(o));
            }
            out.push('\n');
        }
        InstrKind::Deferred {
            op,
            negate,
            operand: o,
            body: b,
            ..
        } => {
            let _ = write!(
                out,
                "{pad}{}{}(",
                op_name(*op),
                if *negate { "N" } else { "" }
            );
            if let Some(o) = o {
                let _ = write!(out, " {}", operand(o));
            }
            out.push('\n');
            body(b, depth + 1, out);
            let _ = writeln!(out, "{pad})");
        }
        InstrKind::Jump { cond, label } => {
            let _ = writeln!(out, "{pad}JMP{} {}", cond_suffix(*cond), label.name);
        }
        InstrKind::Return { cond } => {
            let _ = writeln!(out, "{pad}RET{}", cond_suffix(*cond));
        }
        InstrKind::Call {
            cond,
            instance,
            args,
        } => {
            let _ = writeln!(
                out,
                "{pad}CAL{} {}{}",
                cond_suffix(*cond),
                var_ref(instance),
                call_args(args, true)
            );
        }
        InstrKind::FunctionCall { name, args } => {
            let _ = writeln!(out, "{pad}{}{}", name.name, call_args(args, false));
        }
        InstrKind::FbInput { op, instance } => {
            let _ = writeln!(out, "{pad}{} {}", op.input_name(), var_ref(instance));
        }
        InstrKind::EmbeddedC { name } => {
            let _ = writeln!(out, "{pad}FUNC {}()", name.name);
        }
    }
}

fn call_args(a: &CallArgs, is_cal: bool) -> String {
    match a {
        CallArgs::None => String::new(),
        CallArgs::NonFormal(os) => {
            let parts: Vec<String> = os.iter().map(operand).collect();
            if is_cal {
                format!("({})", parts.join(", "))
            } else {
                format!(" {}", parts.join(", "))
            }
        }
        CallArgs::Formal(fs) => {
            let parts: Vec<String> = fs
                .iter()
                .map(|f| match f.dir {
                    ArgDir::Input => format!("{} := {}", f.name.name, operand(&f.value)),
                    ArgDir::Output { negated } => format!(
                        "{}{} => {}",
                        if negated { "NOT " } else { "" },
                        f.name.name,
                        operand(&f.value)
                    ),
                })
                .collect();
            format!("({})", parts.join(", "))
        }
    }
}

pub fn operand(o: &Operand) -> String {
    match o {
        Operand::Literal(l) => literal(l),
        Operand::Var(v) => var_ref(v),
        Operand::Address(a) => address(a),
        Operand::EnumValue {
            type_name, value, ..
        } => format!("{}#{}", type_name.name, value.name),
    }
}

fn var_ref(v: &VarRef) -> String {
    let mut s = v.base.name.clone();
    for a in &v.accessors {
        match a {
            Accessor::Field(f) => {
                s.push('.');
                s.push_str(&f.name);
            }
            Accessor::Index(is) => {
                let parts: Vec<String> = is.iter().map(operand).collect();
                let _ = write!(s, "[{}]", parts.join(", "));
            }
        }
    }
    s
}

fn address(a: &DirectAddress) -> String {
    let area = match a.area {
        Area::Input => 'I',
        Area::Output => 'Q',
        Area::Memory => 'M',
    };
    let size = match a.size {
        AddressSize::Bit => 'X',
        AddressSize::Byte => 'B',
        AddressSize::Word => 'W',
        AddressSize::DWord => 'D',
        AddressSize::LWord => 'L',
    };
    if a.path.is_empty() {
        return format!("%{area}*");
    }
    let path: Vec<String> = a.path.iter().map(|p| p.to_string()).collect();
    format!("%{area}{size}{}", path.join("."))
}

fn literal(l: &Literal) -> String {
    let body = match &l.kind {
        LiteralKind::Int(i) => i.to_string(),
        LiteralKind::Real(r) => {
            let s = format!("{r:?}");
            if s.contains(['.', 'e', 'E']) || !r.is_finite() {
                s
            } else {
                format!("{s}.0")
            }
        }
        LiteralKind::Bool(b) => if *b { "TRUE" } else { "FALSE" }.to_string(),
        LiteralKind::Duration(ns) => format!("T#{}", duration(*ns)),
        LiteralKind::Date(d) => format!("D#{}", date(*d)),
        LiteralKind::TimeOfDay(ns) => format!("TOD#{}", time_of_day(*ns)),
        LiteralKind::DateAndTime(ns) => {
            let day = 86_400_000_000_000i128;
            let days = ns.div_euclid(day) as i64;
            let rest = ns.rem_euclid(day) as i64;
            format!("DT#{}-{}", date(days), time_of_day(rest))
        }
        LiteralKind::String { wide, value } => string(value, *wide),
    };
    match &l.type_prefix {
        Some(p) => format!("{}#{body}", p.name),
        None => body,
    }
}

fn duration(ns: i128) -> String {
    if ns == 0 {
        return "0s".into();
    }
    let mut rest = ns.unsigned_abs();
    let mut s = String::new();
    if ns < 0 {
        s.push('-');
    }
    for (unit, size) in [
        ("d", 86_400_000_000_000u128),
        ("h", 3_600_000_000_000),
        ("m", 60_000_000_000),
        ("s", 1_000_000_000),
        ("ms", 1_000_000),
        ("us", 1_000),
        ("ns", 1),
    ] {
        let n = rest / size;
        if n > 0 {
            let _ = write!(s, "{n}{unit}");
            rest -= n * size;
        }
    }
    s
}

fn date(days: i64) -> String {
    // Civil from days (Howard Hinnant's algorithm).
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z - era * 146_097;
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let y = yoe + era * 400;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = doy - (153 * mp + 2) / 5 + 1;
    let m = if mp < 10 { mp + 3 } else { mp - 9 };
    let y = if m <= 2 { y + 1 } else { y };
    format!("{y:04}-{m:02}-{d:02}")
}

fn time_of_day(ns: i64) -> String {
    let secs = ns / 1_000_000_000;
    let frac = ns % 1_000_000_000;
    let base = format!("{:02}:{:02}:{:02}", secs / 3600, secs / 60 % 60, secs % 60);
    if frac == 0 {
        base
    } else {
        let f = format!("{frac:09}");
        format!("{base}.{}", f.trim_end_matches('0'))
    }
}

fn string(v: &str, wide: bool) -> String {
    let q = if wide { '"' } else { '\'' };
    let mut s = String::new();
    s.push(q);
    for c in v.chars() {
        match c {
            '$' => s.push_str("$$"),
            '\n' => s.push_str("$N"),
            '\r' => s.push_str("$R"),
            '\t' => s.push_str("$T"),
            '\x0c' => s.push_str("$P"),
            c if c == q => {
                s.push('$');
                s.push(c);
            }
            c if (c as u32) < 0x20 => {
                let _ = write!(s, "${:02X}", c as u32);
            }
            c => s.push(c),
        }
    }
    s.push(q);
    s
}

fn configuration(c: &Configuration, out: &mut String) {
    let _ = writeln!(out, "CONFIGURATION {}", c.name.name);
    for g in &c.globals {
        var_block(g, "  ", out);
    }
    for r in &c.resources {
        let _ = write!(out, "  RESOURCE {}", r.name.name);
        if let Some(on) = &r.on {
            let _ = write!(out, " ON {}", on.name);
        }
        out.push('\n');
        for g in &r.globals {
            var_block(g, "    ", out);
        }
        for t in &r.tasks {
            let mut parts = Vec::new();
            if let Some(s) = &t.single {
                parts.push(format!("SINGLE := {}", operand(s)));
            }
            if let Some(i) = &t.interval {
                parts.push(format!("INTERVAL := {}", operand(i)));
            }
            if let Some(p) = t.priority {
                parts.push(format!("PRIORITY := {p}"));
            }
            let _ = writeln!(out, "    TASK {}({});", t.name.name, parts.join(", "));
        }
        for p in &r.programs {
            let _ = write!(
                out,
                "    PROGRAM {}{}",
                if p.retain { "RETAIN " } else { "" },
                p.name.name
            );
            if let Some(t) = &p.task {
                let _ = write!(out, " WITH {}", t.name);
            }
            let _ = write!(out, " : {}", p.type_name.name);
            if !p.args.is_empty() {
                let _ = write!(
                    out,
                    "{}",
                    call_args(&CallArgs::Formal(p.args.clone()), true)
                );
            }
            out.push_str(";\n");
        }
        out.push_str("  END_RESOURCE\n");
    }
    out.push_str("END_CONFIGURATION\n");
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn prints_literals_in_iec_syntax() {
        assert_eq!(duration(3_723_004_000_000), "1h2m3s4ms");
        assert_eq!(duration(-500_000), "-500us");
        assert_eq!(date(0), "1970-01-01");
        assert_eq!(date(19_723), "2024-01-01");
        assert_eq!(time_of_day(45_296_500_000_000), "12:34:56.5");
        assert_eq!(string("a'b$\n", false), "'a$'b$$$N'");
    }
}
