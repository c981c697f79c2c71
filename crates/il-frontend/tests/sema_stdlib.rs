//! The standard library catalogue: every function and conversion is callable from IL on a value of its
//! class, and the catalogue answers what the IEC standard says.

mod sema_support;
use il_frontend::sema::stdlib::{self, Class, ConvTarget, Dir, ParamTy, Ret};
use il_frontend::sema::{Callee, Elementary, StdFb, Type};
use sema_support::analyze_src;

/// A type of the class, for generated calls.
fn sample(class: Class) -> &'static str {
    match class {
        Class::AnyReal => "REAL",
        Class::AnyBit => "WORD",
        Class::AnyString => "STRING",
        _ => "INT",
    }
}

#[test]
fn the_catalogue_lists_the_iec_functions() {
    for name in [
        "ADD", "SUB", "MUL", "DIV", "MOD", "EXPT", "ABS", "SQRT", "LN", "LOG", "EXP", "SIN", "COS",
        "TAN", "ASIN", "ACOS", "ATAN", "GT", "GE", "EQ", "NE", "LE", "LT", "AND", "OR", "XOR",
        "NOT", "SHL", "SHR", "ROL", "ROR", "SEL", "MAX", "MIN", "LIMIT", "MUX", "MOVE", "LEN",
        "LEFT", "RIGHT", "MID", "CONCAT", "INSERT", "DELETE", "REPLACE", "FIND",
    ] {
        assert!(stdlib::function(name).is_some(), "{name} missing");
        assert!(
            stdlib::function(&name.to_ascii_lowercase()).is_some(),
            "lookup is case-insensitive"
        );
    }
    assert!(stdlib::function("CLAMP").is_none());
    let mux = stdlib::function("MUX").unwrap();
    assert_eq!(mux.param_name(3), "IN2");
    assert_eq!(mux.param_index("in5"), Some(6));
    let add = stdlib::function("ADD").unwrap();
    assert_eq!(add.param_name(2), "IN3");
    assert_eq!(stdlib::function("SUB").unwrap().param_index("IN3"), None);
}

#[test]
fn every_standard_function_is_callable_on_its_class() {
    // `TIME()`, without inputs, is called in ST (tests/tests/unseen_projects_r21.rs): an IL call
    // gives the current result as the first input
    for f in stdlib::FUNCTIONS.iter().filter(|f| !f.params.is_empty()) {
        let mut vars = String::new();
        let mut args = Vec::new();
        let mut first = None;
        for (i, p) in f.params.iter().enumerate() {
            let ty = match p.ty {
                ParamTy::T(c) | ParamTy::Own(c) => sample(c),
                ParamTy::Fixed(e) => e.name(),
            };
            vars.push_str(&format!("  a{i} : {ty};\n"));
            if i == 0 {
                first = Some(format!("a{i}"));
            } else {
                args.push(format!("a{i}"));
            }
        }
        let result = match f.result {
            Ret::T => f
                .params
                .iter()
                .find_map(|p| match p.ty {
                    ParamTy::T(c) => Some(sample(c)),
                    _ => None,
                })
                .unwrap(),
            Ret::Fixed(e) => e.name(),
        };
        let src = format!(
            "PROGRAM P\nVAR\n{vars}  r : {result};\nEND_VAR\n  LD {}\n  {} {}\n  ST r\nEND_PROGRAM\n",
            first.unwrap(),
            f.name,
            args.join(", ")
        );
        let (m, d) = analyze_src(&src);
        assert!(d.is_empty(), "{src}\n{d}");
        let at = src.find(&format!("  {} ", f.name)).unwrap() as u32 + 2;
        let info = m.instrs.iter().find(|(_, i)| i.span.start == at).unwrap().1;
        match &info.callee {
            Some(Callee::Std { name, .. }) => assert_eq!(*name, f.name),
            other => panic!("{}: callee {other:?}", f.name),
        }
        // IL operators (`ADD x`) carry their operand; function calls bind every input.
        let operator = [
            "ADD", "SUB", "MUL", "DIV", "MOD", "GT", "GE", "EQ", "NE", "LE", "LT", "AND", "OR",
            "XOR", "NOT",
        ]
        .contains(&f.name);
        if operator {
            assert!(info.args.is_empty(), "{}", f.name);
            assert_eq!(info.operand.is_some(), f.name != "NOT", "{}", f.name);
        } else {
            assert_eq!(info.args.len(), f.params.len(), "{}", f.name);
        }
    }
}

#[test]
fn every_conversion_between_elementary_types_is_callable() {
    let mut vars = String::new();
    for e in Elementary::ALL {
        vars.push_str(&format!("  v_{} : {};\n", e.name(), e.name()));
    }
    let mut body = String::new();
    let mut count = 0;
    for from in Elementary::ALL {
        for to in Elementary::ALL {
            let name = format!("{}_TO_{}", from.name(), to.name());
            let Some(c) = stdlib::conversion(&name) else {
                continue;
            };
            assert_eq!(c.to, ConvTarget::Fixed(Type::Elementary(to)));
            body.push_str(&format!(
                "  LD v_{}\n  {name}\n  ST v_{}\n",
                from.name(),
                to.name()
            ));
            count += 1;
        }
    }
    assert!(count > 200, "only {count} conversions");
    let src = format!("PROGRAM P\nVAR\n{vars}END_VAR\n{body}END_PROGRAM\n");
    let (_, d) = analyze_src(&src);
    assert!(d.is_empty(), "{d}");
    // Some conversions do not exist.
    assert!(stdlib::conversion("DATE_TO_CHAR").is_none());
    assert!(stdlib::conversion("DATE_TO_UDINT").is_some());
    // CODESYS's TIME_TO_TOD, TOD_TO_TIME and DATE_TO_DT exist (round 26), and since round 27
    // every date and time type converts to every other (CODESYS's tables 16 and 17: TOD_TO_DATE,
    // TOD_TO_DT, DATE_TO_TIME ...)
    assert!(stdlib::conversion("TIME_TO_TOD").is_some());
    assert!(stdlib::conversion("TOD_TO_TIME").is_some());
    assert!(stdlib::conversion("DATE_TO_DT").is_some());
    assert!(stdlib::conversion("TOD_TO_DATE").is_some());
    assert!(stdlib::conversion("TOD_TO_DT").is_some());
    assert!(stdlib::conversion("DATE_TO_TIME").is_some());
    assert!(stdlib::conversion("FOO_TO_INT").is_none());
    assert!(stdlib::conversion("INT_TO_STRING").is_some());
    assert!(stdlib::conversion("TRUNC").is_some());
    assert!(matches!(
        stdlib::conversion("DINT_TO_BCD").unwrap().to,
        ConvTarget::BcdOfWidth
    ));
    assert_eq!(
        stdlib::conversion("WORD_BCD_TO_INT").unwrap().from,
        Some(Type::Elementary(Elementary::Word))
    );
}

#[test]
fn standard_function_blocks_have_their_iec_parameters() {
    let sig = |fb: StdFb| -> String {
        stdlib::fb_params(fb)
            .iter()
            .map(|p| {
                format!(
                    "{}{}:{}",
                    if p.dir == Dir::Input { ">" } else { "<" },
                    p.name,
                    p.ty.name()
                )
            })
            .collect::<Vec<_>>()
            .join(" ")
    };
    let all: Vec<String> = StdFb::ALL
        .iter()
        .map(|f| format!("{}: {}", f.name(), sig(*f)))
        .collect();
    insta::assert_snapshot!(all.join("\n"));
    assert_eq!(StdFb::from_name("ctu_int"), Some(StdFb::Ctu));
    assert_eq!(StdFb::from_name("r_trig"), Some(StdFb::RTrig));
    assert_eq!(
        StdFb::from_name("ctud_ulint").and_then(StdFb::counter),
        Some((il_frontend::sema::CounterKind::UpDown, Elementary::Ulint))
    );
    assert_eq!(
        StdFb::Ctd.counter(),
        Some((il_frontend::sema::CounterKind::Down, Elementary::Int))
    );
    assert_eq!(StdFb::Ton.counter(), None);
    for fb in StdFb::ALL {
        assert!(!stdlib::fb_doc(fb).is_empty());
    }
}

#[test]
fn type_classes_contain_what_iec_says() {
    use Elementary as E;
    let t = Type::Elementary;
    assert!(Class::AnyNum.contains(&t(E::Usint)) && !Class::AnyNum.contains(&t(E::Word)));
    assert!(Class::AnyBit.contains(&t(E::Bool)) && !Class::AnyBit.contains(&t(E::Int)));
    assert!(Class::AnyReal.contains(&t(E::Lreal)) && !Class::AnyReal.contains(&t(E::Dint)));
    assert!(Class::AnyInt.contains(&t(E::Ulint)) && !Class::AnyInt.contains(&t(E::Time)));
    assert!(Class::AnyElementary.contains(&Type::String {
        wide: false,
        len: 5
    }));
    assert!(
        !Class::AnyElementary.contains(&Type::Fb(il_frontend::sema::FbType::Standard(StdFb::Ton)))
    );
    assert_eq!(E::Int.bit_width(), 16);
    assert_eq!(E::Bool.size_bytes(), 1);
    assert_eq!(E::Lreal.size_bytes(), 8);
    assert!(E::Dint.is_signed() && !E::Udint.is_signed());
    assert_eq!(E::Sint.int_range(), Some((-128, 127)));
    assert_eq!(E::from_name("time_of_day"), Some(E::Tod));
}
