//! Compiler acceptance tests: pool sizes, the paper's statement, the program text round trip.

use drive_script::*;

fn script(name: &str) -> String {
    std::fs::read_to_string(format!(
        "{}/tests/scripts/{name}",
        env!("CARGO_MANIFEST_DIR")
    ))
    .unwrap()
}

fn ok(text: &str) -> Program {
    let (map, r) = compile_str("t.ds", text);
    match r {
        Ok(c) => c.program,
        Err(d) => panic!("{}", diagnostics::render_human(&map, &d.into_sorted())),
    }
}

#[test]
fn three_motions_of_5_5_3_events_fill_13_event_pool_entries() {
    let p = ok(&script("three_motions.ds"));
    assert_eq!(p.motions.len(), 3);
    assert_eq!(p.events.len(), 13);
    let counts: Vec<u16> = p.motions.iter().map(|m| m.event_count).collect();
    assert_eq!(counts, vec![5, 5, 3]);
    let firsts: Vec<u16> = p.motions.iter().map(|m| m.first_event).collect();
    assert_eq!(firsts, vec![0, 5, 10]);
    assert_eq!(p.params[0], 10000);
    assert_eq!(p.settings.events_per_cycle, 16);
    assert_eq!(p.settings.velocity, 100000);
}

#[test]
fn paper_statement_sets_do0_then_moves_relative_10000() {
    let p = ok("S:: MOTION 0;\nS:: EVENT 0;\nS:: IF TRUE;\nS:: THEN DO_0=HIGH AND RelativeTargetPosition=10000;\n");
    let ev = &p.events[0];
    assert_eq!(ev.act_count, 2);
    assert_eq!(
        ev.actions[0],
        Action {
            kind: ActionKind::WriteOutput,
            index: 0,
            value: Value::konst(1)
        }
    );
    assert_eq!(
        ev.actions[1],
        Action {
            kind: ActionKind::RelativeMove,
            index: 0,
            value: Value::konst(10000)
        }
    );
}

#[test]
fn names_are_case_insensitive_and_comments_are_ignored() {
    let a = ok("S:: MOTION 0; S:: EVENT 0; S:: IF di_3 = high; // c\n S:: THEN do_1 = Low AND relativemove = -5;");
    let b = ok("s:: motion 0; S:: EVENT 0; S:: IF DI_3 == HIGH; S:: THEN DO_1=LOW AND RelativeTargetPosition=-5;");
    assert_eq!(a, b);
}

#[test]
fn values_have_one_operator_and_unary_minus_and_not_lower_to_it() {
    let p = ok(
        "S:: MOTION 0; S:: EVENT 0; S:: IF ActualPosition - MD0 >= -7 AND MD1 & 0xFF <> 0;\n\
                S:: THEN MD2 = -MD3 AND MD4 = ~MD5 AND MD6 = 0xFFFFFFFF AND MD7 = -2147483648;",
    );
    let e = &p.events[0];
    assert_eq!(e.conditions[0].to_string(), "ActualPosition - MD0 >= -7");
    assert_eq!(e.conditions[1].to_string(), "MD1 & 255 <> 0");
    let acts: Vec<String> = e.actions().iter().map(|a| a.to_string()).collect();
    assert_eq!(
        acts,
        vec!["MD2=0 - MD3", "MD4=MD5 ^ -1", "MD6=-1", "MD7=-2147483648"]
    );
}

#[test]
fn a_lone_value_as_condition_means_not_zero() {
    let p = ok("S:: MOTION 0; S:: EVENT 0; S:: IF TimerDone_2; S:: THEN Jump = 0;");
    let c = p.events[0].conditions[0];
    assert_eq!(c.cmp, Compare::Ne);
    assert_eq!(
        c.lhs.a,
        Operand {
            source: Source::TimerDone,
            arg: 2
        }
    );
    assert_eq!(c.rhs, Value::konst(0));
}

#[test]
fn disassembly_compiles_back_to_the_same_program() {
    let p = ok(&script("three_motions.ds"));
    let text = p.to_string();
    assert_eq!(ok(&text), p);
}

#[test]
fn compiler_never_panics_on_mutated_scripts() {
    let base = script("three_motions.ds");
    let chars: Vec<char> = base.chars().collect();
    let mut rejected = 0;
    for i in (0..chars.len()).step_by(3) {
        for m in 0..4 {
            let mut c = chars.clone();
            match m {
                0 => {
                    c.remove(i);
                }
                1 => c.insert(i, ';'),
                2 => c[i] = '9',
                _ => c.insert(i, 'S'),
            }
            let text: String = c.into_iter().collect();
            let (_, r) = compile_str("m.ds", &text);
            if let Err(d) = r {
                rejected += 1;
                assert!(
                    d.iter().all(|d| d.span.is_some()),
                    "every compile error has a position"
                );
            }
        }
    }
    assert!(rejected > 100, "mutations are mostly rejected: {rejected}");
}

#[test]
fn every_e6_code_used_by_the_crate_has_an_explanation() {
    for n in (6001..=6015).chain(6020..=6023) {
        let code = format!("E{n}");
        let info =
            diagnostics::lookup(&code).unwrap_or_else(|| panic!("{code} has no explanation"));
        assert!(info.explanation.contains("## How to fix"), "{code}");
    }
}

#[test]
fn missing_semicolon_at_end_of_file_points_after_the_last_token() {
    let (map, r) = compile_str(
        "t.ds",
        "S:: MOTION 0;\nS:: EVENT 0;\nS:: IF TRUE;\nS:: THEN Stop",
    );
    let d = r.unwrap_err().into_sorted();
    assert_eq!(d.len(), 1);
    assert_eq!(
        diagnostics::render_short(&map, &d[0]),
        "t.ds:4:14: error[E6002]: statement is not terminated by `;` (hint: end every statement with `;`)"
    );
}
