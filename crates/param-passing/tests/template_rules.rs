//! Templates can only do what paper A's rules allow (issue #12, point 5): every construct that could put
//! code outside the rules into the generated C is refused on load, at its line and column in the template
//! file. Templates are loaded as users load them (`Library::add_dir`: schema, body checks, the function
//! compiled alone with the system C compiler).

use diagnostics::{render, Diagnostics, MessageFormat, SourceMap};
use param_passing::library::Library;
use param_passing::template;

/// A user template with `local` as its `<local>` element and `body` as its body (line 8 of the file).
fn template(block: &str, params: &str, local: &str, body: &str) -> String {
    format!(
        "<blockTemplate name=\"{block}\" funcNum=\"90\">\n  <parameters>\n    <param name=\"Execute\" abbr=\"Ex\" direction=\"input\" class=\"bool\" type=\"BOOL\" required=\"true\"/>\n    <param name=\"Position\" abbr=\"Pos\" direction=\"input\" class=\"lreal\" type=\"LREAL\" default=\"0.0\"/>\n    <param name=\"Done\" abbr=\"Dn\" direction=\"output\" class=\"bool\" type=\"BOOL\"/>{params}\n  </parameters>\n  {local}\n  <body><![CDATA[\n{body}\n]]></body>\n</blockTemplate>\n"
    )
}

fn body(b: &str) -> String {
    template("ACME_Demo", "", r#"<local name="tmp" ctype="double"/>"#, b)
}

/// Loads `text` from a user directory; the short diagnostics (paths relative to the directory) and
/// whether the block is in the library afterwards.
fn load_user(text: &str) -> (String, bool) {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("ACME_Demo.xml"), text).unwrap();
    let mut map = SourceMap::new();
    let mut diags = Diagnostics::new();
    let mut lib = Library::new();
    lib.add_dir(dir.path(), &mut map, &mut diags);
    let out = render(&map, &diags.into_sorted(), MessageFormat::Short);
    let prefix = format!("{}/", dir.path().display());
    (out.replace(&prefix, ""), lib.get("ACME_Demo").is_some())
}

/// Asserts that `text` is refused with `code` at `line:col` of the template file.
fn refused(text: &str, code: &str, line_col: &str) -> String {
    let (out, present) = load_user(text);
    assert!(!present, "a refused template must not be used:\n{out}");
    let want = format!("ACME_Demo.xml:{line_col}: error[{code}]");
    assert!(
        out.lines().any(|l| l.starts_with(&want)),
        "want {want}, got:\n{out}"
    );
    out
}

#[test]
fn a_good_user_template_loads_and_compiles() {
    let (out, present) = load_user(&body("tmp = Pos * 2.0;\nDn = (uint8_t)(Ex && tmp > 0.0);"));
    assert_eq!(out, "");
    assert!(present);
}

#[test]
fn a_local_ctype_outside_the_closed_list_is_refused_at_the_attribute() {
    // The issue's injection: a ctype that closes the function and calls system() at run time.
    let evil = r#"<local name="tmp" ctype="double tmp; } void evil(void) { system(&quot;id&quot;); } void more(void) { double"/>"#;
    let out = refused(
        &template("ACME_Demo", "", evil, "tmp = 1.0; (void)tmp;"),
        "E4200",
        "7:21",
    );
    assert!(
        out.contains("is not a C type a template local may have"),
        "{out}"
    );
    for bad in [
        "int",
        "char *",
        "double[4]",
        "McEngine",
        "struct MC_Power_C",
        "uint8_t ",
    ] {
        let l = format!(r#"<local name="tmp" ctype="{bad}"/>"#);
        refused(&template("ACME_Demo", "", &l, "tmp = 1;"), "E4200", "7:21");
    }
    // A motion-library block struct is on the list.
    let l = r#"<local name="fb" ctype="MC_Power_C"/>"#;
    let (out, present) = load_user(&template("ACME_Demo", "", l, "fb.Enable = (bool)Ex; mc_power(ladderc_motion_engine(), 0u, &fb); Dn = (uint8_t)fb.Status;"));
    assert_eq!(out, "");
    assert!(present);
}

#[test]
fn preprocessor_directives_are_refused_in_every_spelling() {
    for (b, line_col) in [
        ("#include \"/etc/hostname\"", "9:1"),
        ("#define Pos 0\nDn = (uint8_t)(Pos > 1.0);", "9:1"),
        ("   /* hidden */ #if 0\nDn = 1;\n#endif", "9:17"),
        (
            "Dn = 1;\n  # pragma GCC diagnostic ignored \"-Wall\"",
            "10:3",
        ),
        ("%:include <stdio.h>", "9:1"),
        ("_Pragma(\"GCC poison Dn\") Dn = 1;", "9:1"),
        ("Dn = 1; #", "9:9"),
        // Found by the fuzzer: `#` right before a multi-byte character (the span must not cut it).
        ("Dn = 1; #€", "9:9"),
    ] {
        refused(&body(b), "E4201", line_col);
    }
}

#[test]
fn trigraphs_splices_and_backslashes_are_refused() {
    refused(&body("??=include <stdio.h>"), "E4202", "9:1");
    refused(&body("Dn = 1; /* ??/ */"), "E4202", "9:12");
    // A splice continues a comment over code the checks would otherwise see as code, or joins a name.
    refused(&body("Dn = 1; // note \\\nDn = 0;"), "E4203", "9:17");
    refused(&body("Dn = 1; // note \\  \nDn = 0;"), "E4203", "9:17");
    refused(&body("sys\\\ntem(\"id\");"), "E4203", "9:4");
    refused(&body("D\\u006e = 1;"), "E4203", "9:2");
}

#[test]
fn dollars_non_ascii_names_and_digraphs_are_refused() {
    refused(&body("Dn$x = 1;"), "E4204", "9:3");
    refused(&body("Dné = 1;"), "E4204", "9:3");
    refused(&body("Dn = 1; @"), "E4204", "9:9");
    // `%>` closes the function for the compiler while the braces look balanced.
    refused(&body("Dn = 1; %> void evil(void) <%"), "E4205", "9:9");
    refused(&body("double v <: 2 :>;"), "E4205", "9:10");
}

#[test]
fn names_follow_the_abbreviation_rules() {
    let p = r#"
    <param name="Extra" abbr="E$x" direction="input" class="bool" type="BOOL"/>"#;
    refused(
        &template(
            "ACME_Demo",
            p,
            r#"<local name="tmp" ctype="double"/>"#,
            "tmp = 0.0;",
        ),
        "E4206",
        "6:25",
    );
    let p = r#"
    <param name="Extra" abbr="Ex_1" direction="input" class="bool" type="BOOL"/>"#;
    refused(
        &template(
            "ACME_Demo",
            p,
            r#"<local name="tmp" ctype="double"/>"#,
            "tmp = 0.0;",
        ),
        "E4206",
        "6:25",
    );
    refused(
        &template(
            "ACME_Demo",
            "",
            r#"<local name="t$mp" ctype="double"/>"#,
            "Dn = 1;",
        ),
        "E4206",
        "7:10",
    );
    refused(
        &template(
            "ACME_Demo",
            "",
            r#"<local name="self" ctype="double"/>"#,
            "Dn = 1;",
        ),
        "E4206",
        "7:10",
    );
    refused(
        &template(
            "ACME_Demo",
            "",
            r#"<local name="mc_power" ctype="double"/>"#,
            "Dn = 1;",
        ),
        "E4206",
        "7:10",
    );
    // Locals the body declares follow the same rules.
    refused(&body("double self = 0.0; (void)self;"), "E4206", "9:8");
    refused(
        &body("double ladderc_M = 0.0; (void)ladderc_M;"),
        "E4206",
        "9:8",
    );
    refused(&body("double Pos = 0.0;"), "E4206", "9:8");
}

#[test]
fn block_parameter_names_and_defaults_cannot_inject_code() {
    for name in [
        "puts",
        "mc_power",
        "MC_Power_C",
        "ladderc_Main",
        "A$B",
        "MC__X",
        "MC_X; int",
    ] {
        let t = template(name, "", r#"<local name="tmp" ctype="double"/>"#, "Dn = 1;");
        let (out, present) = load_user(&t);
        assert!(!present && out.contains("error[E4207]"), "{name}: {out}");
    }
    let p = r#"
    <param name="Jerk; END_VAR" abbr="Jrk" direction="input" class="lreal" type="LREAL"/>"#;
    refused(&template("ACME_Demo", p, "", "Dn = 1;"), "E4207", "6:12");
    for d in [
        "0.0; END_VAR VAR_GLOBAL x : INT",
        "1e999",
        "abc",
        "0x10",
        "",
    ] {
        let p = format!(
            "\n    <param name=\"Jerk\" abbr=\"Jrk\" direction=\"input\" class=\"lreal\" type=\"LREAL\" default=\"{d}\"/>"
        );
        refused(&template("ACME_Demo", &p, "", "Dn = 1;"), "E4209", "6:80");
    }
    let p = "\n    <param name=\"Count\" abbr=\"Cnt\" direction=\"input\" class=\"byte\" type=\"USINT\" default=\"256\"/>";
    refused(&template("ACME_Demo", p, "", "Dn = 1;"), "E4209", "6:80");
}

#[test]
fn the_body_cannot_leave_the_function_or_call_an_undeclared_function() {
    let out = refused(&body("Dn = 1; } void evil(void) { Dn = 0;"), "E4008", "9:9");
    assert!(out.contains("unmatched `}`"), "{out}");
    let out = refused(&body("system(\"id\");"), "E4007", "9:1");
    assert!(out.contains("uses `system`"), "{out}");
    refused(&body("exit(1);"), "E4007", "9:1");
    refused(&body("__builtin_trap();"), "E4007", "9:1");
    refused(&body("__asm__(\"nop\");"), "E4007", "9:1");
    // Pointers, casts to pointers, functions and types of its own.
    refused(&body("uint32_t *p = 0; (void)p;"), "E4208", "9:10");
    refused(&body("*(uint32_t *)4096u = 1u;"), "E4208", "9:12");
    refused(&body("int f(void) { return 1; }"), "E4208", "9:5");
    refused(&body("typedef int T;"), "E4208", "9:1");
}

#[test]
fn c_errors_are_reported_at_their_line_and_column_in_the_template() {
    let out = refused(&body("tmp = 1.0;\nDn = Pos > ;"), "E4210", "10:12");
    assert!(
        out.contains("the C compiler rejects template `ACME_Demo`"),
        "{out}"
    );
    // An unused template local is a -Wextra warning, an error with -Werror: it points at the <local>.
    refused(&body("Dn = 1;"), "E4210", "7:3");
    // A wrong argument of a library call.
    refused(&body("tmp = 0.0; mc_power(tmp);"), "E4210", "9:12");
}

#[test]
fn short_template_files_with_non_ascii_text_never_panic() {
    let samples = [
        "<a/>é",
        "<é/>",
        "<b x=\"€\"/>",
        "<€",
        "<blockTemplate name=\"MC_€\" funcNum=\"1\"><parameters/><body>é</body></blockTemplate>",
        "<blockTemplate name=\"€\"/>",
    ];
    for s in samples {
        for end in (0..=s.len()).filter(|&e| s.is_char_boundary(e)) {
            let text = &s[..end];
            let mut map = SourceMap::new();
            let f = map.add("t.xml", text);
            let mut diags = Diagnostics::new();
            let _ = template::load(f, text, &mut diags);
            for d in diags.into_vec() {
                if let Some(span) = d.span {
                    let r = span.range();
                    assert!(
                        r.end <= text.len()
                            && text.is_char_boundary(r.start)
                            && text.is_char_boundary(r.end),
                        "{text:?}: {r:?}"
                    );
                }
            }
        }
    }
}
