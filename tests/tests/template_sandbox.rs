//! End to end (issue #12, point 5): no template can reach file scope of the generated C or call a function
//! the rules do not allow. Hostile user templates are refused by `ladderc build --templates DIR` with a
//! diagnostic in the template file (exit 1, nothing written); a legal user template of a vendor block builds,
//! its C compiles with -Werror, and the program runs with it under both methods.

mod common;

use common::ladderc;
use std::path::Path;

const PROGRAM: &str = "PROGRAM main
VAR
    blk : ACME_Demo;
    go : BOOL := TRUE;
    done : BOOL;
END_VAR
    CAL blk(Execute := go, Position := 2.5)
    LD blk.Done
    ST done
END_PROGRAM
";

fn template(local: &str, body: &str) -> String {
    format!(
        "<blockTemplate name=\"ACME_Demo\" funcNum=\"90\">\n  <parameters>\n    <param name=\"Execute\" abbr=\"Ex\" direction=\"input\" class=\"bool\" type=\"BOOL\" required=\"true\"/>\n    <param name=\"Position\" abbr=\"Pos\" direction=\"input\" class=\"lreal\" type=\"LREAL\" default=\"0.0\"/>\n    <param name=\"Done\" abbr=\"Dn\" direction=\"output\" class=\"bool\" type=\"BOOL\"/>\n  </parameters>\n  {local}\n  <body><![CDATA[\n{body}\n]]></body>\n</blockTemplate>\n"
    )
}

/// Writes the program and the template into a fresh directory; runs `ladderc ARGS... --templates tpl main.il`.
fn ladderc_with(template_text: &str, args: &[&str]) -> (tempfile::TempDir, std::process::Output) {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("main.il"), PROGRAM).unwrap();
    let tpl = dir.path().join("tpl");
    std::fs::create_dir(&tpl).unwrap();
    std::fs::write(tpl.join("ACME_Demo.xml"), template_text).unwrap();
    let out = ladderc()
        .args(args)
        .args(["--message-format", "short", "--templates", "tpl", "main.il"])
        .current_dir(dir.path())
        .output()
        .unwrap();
    (dir, out)
}

fn assert_refused_in_template(template_text: &str, code: &str) {
    let (dir, out) = ladderc_with(template_text, &["build", "-o", "out"]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{err}");
    assert!(
        err.lines()
            .any(|l| l.starts_with("tpl/ACME_Demo.xml:") && l.contains(&format!("error[{code}]"))),
        "want {code} in the template file:\n{err}"
    );
    assert!(!dir.path().join("out").exists(), "no C may be written");
}

#[test]
fn hostile_templates_are_refused_in_their_file_and_no_c_is_written() {
    let ok_local = r#"<local name="tmp" ctype="double"/>"#;
    let attacks: &[(&str, &str, &str)] = &[
        // The issue's findings: a ctype pasted into the C, a directive, a #define of a declared name, `$`.
        (
            r#"<local name="tmp" ctype="double tmp; } int evil(void) { return system(&quot;id&quot;); } static void more(void) { double"/>"#,
            "tmp = 0.0;",
            "E4200",
        ),
        (ok_local, "tmp = 0.0;\n#include \"/etc/hostname\"", "E4201"),
        (ok_local, "#define Dn tmp\ntmp = 0.0;", "E4201"),
        (ok_local, "tmp = 0.0;\n#if 0\nDn = 1;\n#endif", "E4201"),
        (r#"<local name="t$mp" ctype="double"/>"#, "Dn = 1;", "E4206"),
        // Leaving the function: a brace, a digraph, a trigraph, a splice into a directive.
        (ok_local, "tmp = 0.0; } int evil(void) { return 0;", "E4008"),
        (
            ok_local,
            "tmp = 0.0; %> int evil(void) <% return 0;",
            "E4205",
        ),
        (
            ok_local,
            "tmp = 0.0; ??> int evil(void) ??< return 0;",
            "E4202",
        ),
        (ok_local, "tmp = 0.0; /* x *\\\n/ Dn = 1;", "E4203"),
        // Calling what the rules do not allow.
        (ok_local, "tmp = 0.0; system(\"id\");", "E4007"),
        (ok_local, "tmp = 0.0; ((void (*)(void))0)();", "E4208"),
        (ok_local, "tmp = 0.0; static int n; (void)n;", "E4010"),
        // Macros of the C headers as names: `isnan` as a local let the body call the macro `isnan(x)`.
        (
            r#"<local name="isnan" ctype="double"/>"#,
            "isnan = Pos; Dn = (uint8_t)isnan(isnan);",
            "E4206",
        ),
        (
            ok_local,
            "double signbit = Pos; tmp = signbit; Dn = (uint8_t)signbit(tmp);",
            "E4206",
        ),
        // A 4 GB array on the scan's stack; brackets nested 100,000 deep (gcc ran for minutes).
        (
            ok_local,
            "double big[536870912]; big[0] = Pos; tmp = big[0];",
            "E4208",
        ),
        (
            ok_local,
            "double big[64][64][2]; big[0][0][0] = Pos; tmp = big[0][0][0];",
            "E4208",
        ),
        (
            ok_local,
            &format!(
                "tmp = 0.0; {}Dn = 1;{}",
                "{".repeat(100_000),
                "}".repeat(100_000)
            ),
            "E4008",
        ),
        // A C error is the template's, not the user's build's.
        (ok_local, "tmp = Pos +;", "E4210"),
    ];
    for (local, body, code) in attacks {
        assert_refused_in_template(&template(local, body), code);
    }
    // A block named like a macro of the C headers: the IL method defines `void NAN(void)`.
    for name in ["NAN", "EOF", "INFINITY", "FILE"] {
        let text =
            template(ok_local, "tmp = Pos; Dn = (uint8_t)(tmp > 0.0);").replace("ACME_Demo", name);
        let dir = tempfile::tempdir().unwrap();
        std::fs::write(
            dir.path().join("main.il"),
            PROGRAM.replace("ACME_Demo", name),
        )
        .unwrap();
        std::fs::create_dir(dir.path().join("tpl")).unwrap();
        std::fs::write(dir.path().join(format!("tpl/{name}.xml")), text).unwrap();
        let out = ladderc()
            .args([
                "--message-format",
                "short",
                "build",
                "--strategy",
                "il",
                "-o",
                "out",
            ])
            .args(["--templates", "tpl", "main.il"])
            .current_dir(dir.path())
            .output()
            .unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(1), "{name}: {err}");
        assert!(err.contains("error[E4207]"), "{name}: {err}");
    }
}

fn trace(dir: &Path, args: &[&str]) -> String {
    let out = ladderc()
        .args([
            "run",
            "--cycles",
            "2",
            "--watch",
            "main.done",
            "--trace",
            "t.csv",
        ])
        .args(args)
        .args(["--templates", "tpl", "main.il"])
        .current_dir(dir)
        .output()
        .unwrap();
    common::assert_ok(&out);
    std::fs::read_to_string(dir.join("t.csv")).unwrap()
}

#[test]
fn a_legal_vendor_template_builds_warning_free_and_runs_with_both_methods() {
    let text = template(
        r#"<local name="tmp" ctype="double"/>"#,
        "    tmp = Pos * 2.0;\n    Dn = (uint8_t)(Ex && tmp > 4.0);",
    );
    let (dir, out) = ladderc_with(&text, &["build", "--strategy", "template", "-o", "out"]);
    common::assert_ok(&out);
    let program = std::fs::read_to_string(dir.path().join("out/program.c")).unwrap();
    assert!(program.contains("tmp = Pos_1 * 2.0;"), "{program}");
    // The file that holds the synthesised function compiles with -Werror (ladderc_motion.c is left out:
    // with no axes its sampling loop `i < 0u` is a -Wtype-limits warning of the C backend, not a template's).
    let files = [dir.path().join("out/program.c")];
    let cc = std::process::Command::new("cc")
        .args(["-std=c99", "-Wall", "-Wextra", "-Werror", "-fsyntax-only"])
        .arg("-I")
        .arg(dir.path().join("out"))
        .args(&files)
        .output()
        .unwrap();
    assert!(
        cc.status.success(),
        "{}",
        String::from_utf8_lossy(&cc.stderr)
    );
    for strategy in ["template", "il"] {
        let t = trace(dir.path(), &["--strategy", strategy]);
        assert!(t.lines().last().unwrap().ends_with(",1"), "{strategy}: {t}");
    }
}
