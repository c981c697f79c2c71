//! The seven IL files of the corpus, parsed and analysed: no spurious diagnostics. Files 18 and 19 are
//! bundled; the others are read from `$LADDERC_CORPUS` (skipped when it is unset).

mod sema_support;
use diagnostics::{Diagnostics, SourceMap};
use il_frontend::sema::{analyze, Callee, Model, Type};

/// A corpus file of `il/` (see the `test-corpus` crate): `None` after a skip line when it is neither
/// bundled nor in `$LADDERC_CORPUS`.
fn corpus(name: &str) -> Option<String> {
    test_corpus::read(&format!("il/{name}"))
}

/// Parses and analyses corpus files together; returns the model, the source of the last file, and the
/// diagnostics in short form (one per line); `None` when a file is unavailable (skipped).
fn analyse(names: &[&str]) -> Option<(Model, String, Vec<String>)> {
    let mut map = SourceMap::new();
    let mut diags = Diagnostics::new();
    let mut units = Vec::new();
    let mut last = String::new();
    for n in names {
        let src = corpus(n)?;
        let f = map.add(*n, src.clone());
        units.push(il_frontend::parse(f, &src, &mut diags));
        last = src;
    }
    let model = analyze(&units, &mut diags);
    let lines = diags
        .into_sorted()
        .iter()
        .map(|d| diagnostics::render_short(&map, d))
        .collect();
    Some((model, last, lines))
}

/// The semantic diagnostics only (the parser's own are the parser's business).
fn sema_only(d: &[String]) -> Vec<String> {
    d.iter()
        .filter(|l| l.contains("[E1") || l.contains("[W1"))
        .cloned()
        .collect()
}

const CMD_MONITOR: &str = "17_matiec_AnnexF_cmd_monitor_il.st";
const FWD_REV_MON: &str = "17_matiec_AnnexF_fwd_rev_mon_il.st";
const STACK_INT: &str = "17_matiec_AnnexF_stack_int_il.st";
const WEIGH: &str = "17_matiec_AnnexF_weigh_il.st";
const TEST1: &str = "18_il_parser_test1.il";
const TEST2: &str = "19_il_parser_test2.il";
const STATE_DISPLAY: &str = "20_strucpp_state-display.il";

#[test]
fn annex_f_cmd_monitor_is_clean() {
    let Some((_, _, d)) = analyse(&[CMD_MONITOR]) else {
        return;
    };
    assert_eq!(d, Vec::<String>::new());
}

#[test]
fn annex_f_weigh_is_clean() {
    let Some((_, _, d)) = analyse(&[WEIGH]) else {
        return;
    };
    assert_eq!(d, Vec::<String>::new());
}

#[test]
fn strucpp_state_display_is_clean() {
    let Some((_, _, d)) = analyse(&[STATE_DISPLAY]) else {
        return;
    };
    assert_eq!(d, Vec::<String>::new());
}

#[test]
fn annex_f_stack_int_is_clean() {
    let Some((m, src, d)) = analyse(&[STACK_INT]) else {
        return;
    };
    assert_eq!(sema_only(&d), Vec::<String>::new(), "{d:#?}");
    let at = |text: &str| {
        let start = src.find(text).unwrap_or_else(|| panic!("{text}")) as u32;
        m.instrs
            .iter()
            .find(|(_, i)| i.span.start == start)
            .unwrap_or_else(|| panic!("no instruction at {text}"))
            .1
    };
    // `ZRO_OUT: LD 0` falls through into `SET_OUT: ST OUT`, which jumps reach with an INT.
    assert_eq!(at("LD\t0\t(* OUT=0").cr_after, Some(Type::INT));
    // `CAL LIMIT(...)` calls a function: its result is the current result.
    let call = at("CAL\tLIMIT");
    assert!(
        matches!(call.callee, Some(Callee::Std { name: "LIMIT", .. })),
        "{call:?}"
    );
    assert_eq!(call.cr_after, Some(Type::INT));
}

/// FWD_REV_MON instantiates CMD_MONITOR: both files form one program. The Annex F text reads
/// `FWD_REV_FF.Q`, but the IEC SR block's output is `Q1` (an erratum of the standard's example): that
/// line is the only diagnostic.
#[test]
fn annex_f_fwd_rev_mon_with_cmd_monitor_reports_only_the_sr_output_erratum() {
    let Some((m, _, d)) = analyse(&[CMD_MONITOR, FWD_REV_MON]) else {
        return;
    };
    assert_eq!(d.len(), 1, "{d:#?}");
    assert!(
        d[0].contains("E1011") && d[0].contains("SR has no input or output `Q`"),
        "{d:#?}"
    );
    assert_eq!(m.pous.len(), 2);
}

/// The missing block type of two declarations is one E1003 at the first, counting its uses (round
/// 27 of issue #13: one cause, one diagnostic; before: one per declaration).
#[test]
fn annex_f_fwd_rev_mon_alone_reports_the_missing_fb_type_once() {
    let Some((_, _, d)) = analyse(&[FWD_REV_MON]) else {
        return;
    };
    let unknown: Vec<&String> = d
        .iter()
        .filter(|l| l.contains("unknown type `CMD_MONITOR`"))
        .collect();
    assert_eq!(unknown.len(), 1, "{d:#?}");
    assert!(unknown[0].contains("`CMD_MONITOR` (2 uses)"), "{d:#?}");
    // Plus the SR erratum; nothing follows from the unknown type.
    assert_eq!(d.len(), 2, "{d:#?}");
}

#[test]
fn il_parser_test1_reports_only_the_s_without_operand() {
    let Some((_, _, d)) = analyse(&[TEST1]) else {
        return;
    };
    let sema = sema_only(&d);
    assert_eq!(sema.len(), 1, "{d:#?}");
    assert!(sema[0].contains("E1016"), "{d:#?}");
}

/// The file declares almost nothing: each undeclared name is one E1001 at its first use in the POU
/// (its other uses are not reported, as C compilers report an undeclared identifier once per
/// function; no cascade from the unknown type of the current result); the remaining errors are
/// genuine type errors of the file (`LD 450` compared with a bit, UINT compared with BOOL, SUB of
/// BOOL), and the warnings are results loaded and replaced before use.
#[test]
fn il_parser_test2_reports_each_undeclared_name_once_per_pou() {
    let Some((_, src, d)) = analyse(&[TEST2]) else {
        return;
    };
    insta::assert_snapshot!(d.join("\n"));
    // One E1001 per undeclared name (the file's one POU uses each several times).
    for name in ["Limit", "FO1", "FO2"] {
        let uses = src.matches(&format!("{name},")).count()
            + src.matches(&format!("{name})")).count()
            + src.matches(&format!("{name}\n")).count();
        assert!(uses > 1, "{name}: {uses}");
        let reported = d
            .iter()
            .filter(|l| l.contains(&format!("undeclared name `{name}`")))
            .count();
        assert_eq!(reported, 1, "{name}: {d:#?}");
    }
}
