//! The IL files of the shared corpus analyse without spurious diagnostics.

mod sema_support;
use sema_support::analyze_src;

/// A corpus file: `shared/` lies beside the repository (one level further up from a git worktree).
fn corpus(name: &str) -> String {
    let dir = env!("CARGO_MANIFEST_DIR");
    let paths = [
        format!("{dir}/../../../shared/corpus/il/{name}"),
        format!("{dir}/../../../../shared/corpus/il/{name}"),
    ];
    paths
        .iter()
        .find_map(|p| std::fs::read_to_string(p).ok())
        .unwrap_or_else(|| panic!("corpus file {name} not found at {paths:?}"))
}

/// Blanks comments and puts a declaration that follows `VAR...` on its own line, keeping every byte
/// offset (the test reader reads one declaration per line).
fn normalize(src: &str) -> String {
    let mut b: Vec<u8> = src.as_bytes().to_vec();
    let mut i = 0;
    while i + 1 < b.len() {
        if b[i] == b'(' && b[i + 1] == b'*' {
            while i + 1 < b.len() && !(b[i] == b'*' && b[i + 1] == b')') {
                if b[i] != b'\n' {
                    b[i] = b' ';
                }
                i += 1;
            }
            b[i] = b' ';
            b[i + 1] = b' ';
        }
        i += 1;
    }
    let mut s = String::from_utf8(b).unwrap();
    for kw in ["VAR_INPUT ", "VAR_OUTPUT ", "VAR "] {
        s = s.replace(kw, &format!("{}\n", kw.trim_end()));
    }
    s
}

fn diagnostics_of(name: &str) -> String {
    analyze_src(&normalize(&corpus(name))).1
}

#[test]
fn annex_f_cmd_monitor_is_clean() {
    assert_eq!(diagnostics_of("17_matiec_AnnexF_cmd_monitor_il.st"), "");
}

#[test]
fn annex_f_stack_int_is_clean() {
    let src = normalize(&corpus("17_matiec_AnnexF_stack_int_il.st"));
    let (m, d) = analyze_src(&src);
    assert_eq!(d, "");
    // `ZRO_OUT: LD 0` falls through into `SET_OUT: ST OUT`, which jumps reach with an INT.
    let at = src
        .find("LD\t0\t(* OUT=0")
        .or_else(|| src.find("ZRO_OUT:\tLD"))
        .unwrap();
    let zro = m
        .instrs
        .iter()
        .find(|(s, _)| s.start as usize >= at && (s.start as usize) < at + 12)
        .unwrap()
        .1;
    assert_eq!(zro.cr_after, Some(il_frontend::sema::Type::INT));
    // `CAL LIMIT(...)` is a function call whose result is the current result.
    let lim = src.find("CAL\tLIMIT").unwrap();
    let call = m
        .instrs
        .iter()
        .find(|(s, _)| s.start as usize == lim)
        .unwrap()
        .1;
    assert!(matches!(
        call.callee,
        Some(il_frontend::sema::Callee::Std { name: "LIMIT", .. })
    ));
    assert_eq!(call.cr_after, Some(il_frontend::sema::Type::INT));
}

#[test]
fn annex_f_weigh_is_clean() {
    assert_eq!(diagnostics_of("17_matiec_AnnexF_weigh_il.st"), "");
}

#[test]
fn strucpp_state_display_is_clean() {
    assert_eq!(diagnostics_of("20_strucpp_state-display.il"), "");
}

/// The Annex F text reads `FWD_REV_FF.Q`, but the IEC SR block's output is `Q1` (an erratum of the
/// standard's example): that one line is the only diagnostic.
#[test]
fn annex_f_fwd_rev_mon_with_cmd_monitor_reports_only_the_sr_output_erratum() {
    // FWD_REV_MON instantiates CMD_MONITOR: both files form one program.
    let a = normalize(&corpus("17_matiec_AnnexF_cmd_monitor_il.st"));
    let b = normalize(&corpus("17_matiec_AnnexF_fwd_rev_mon_il.st"));
    let mut map = diagnostics::SourceMap::new();
    let fa = map.add("cmd_monitor", a.clone());
    let fb = map.add("fwd_rev_mon", b.clone());
    let units = [sema_support::read(fa, &a), sema_support::read(fb, &b)];
    let mut diags = diagnostics::Diagnostics::new();
    let model = il_frontend::sema::analyze(&units, &mut diags);
    let list = diags.into_sorted();
    let text = diagnostics::render_human(&map, &list);
    assert_eq!(list.len(), 1, "{text}");
    assert_eq!(list[0].code, diagnostics::code::E1011);
    assert!(
        text.contains("SR has no input or output `Q`") && text.contains("Q1"),
        "{text}"
    );
    assert_eq!(model.pous.len(), 2);
}

#[test]
fn annex_f_fwd_rev_mon_alone_reports_the_missing_fb_type_once_per_declaration() {
    let d = diagnostics_of("17_matiec_AnnexF_fwd_rev_mon_il.st");
    assert_eq!(d.matches("unknown type `CMD_MONITOR`").count(), 2, "{d}");
    // Plus the SR erratum (see above); nothing follows from the unknown type.
    assert_eq!(d.matches("error[").count(), 3, "{d}");
}
