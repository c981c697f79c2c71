//! The generated C for a small program, reviewed as a snapshot (and compiled strictly).

mod support;
use support::*;

const SRC: &str = "FUNCTION clamp100 : INT
VAR_INPUT
  x : INT;
END_VAR
  LD x
  LIMIT 0, 100
  ST clamp100
END_FUNCTION
FUNCTION_BLOCK blink
VAR_INPUT
  enable : BOOL;
END_VAR
VAR_OUTPUT
  out : BOOL;
END_VAR
VAR
  t : TON;
END_VAR
  LD enable
  ANDN t.Q
  IN t
  LD t.Q
  JMPCN done
  LD out
  NOT
  ST out
done:
  RET
END_FUNCTION_BLOCK
PROGRAM main
VAR
  run AT %IX0.0 : BOOL;
  lamp AT %QX0.0 : BOOL;
  b : blink := (enable := TRUE);
  level : INT := 7;
END_VAR
  LD run
  AND( level
  GT 5
  )
  ST b.enable
  CAL b
  LD b.out
  ST lamp
  LD level
  clamp100
  ST level
END_PROGRAM
";

#[test]
fn generated_c_for_a_small_program() {
    let (units, model, map) = frontend(SRC);
    let p = generate_with(
        &units,
        &model,
        &map,
        &Default::default(),
        &Default::default(),
    );
    let text = format!(
        "==== ladderc_config.h\n{}==== program.h\n{}==== program.c\n{}==== Makefile\n{}",
        p.file("ladderc_config.h").unwrap(),
        p.file("program.h").unwrap(),
        p.file("program.c").unwrap(),
        p.file("Makefile").unwrap()
    );
    insta::assert_snapshot!(text);
    let paths: Vec<&str> = p.files.iter().map(|(p, _)| p.as_str()).collect();
    assert_eq!(
        paths,
        [
            "ladderc_config.h",
            "program.h",
            "program.c",
            "ladderc_rt.h",
            "ladderc_rt.c",
            "ladderc_strings.c",
            "ladderc_main.c",
            "Makefile"
        ]
    );
    let b = build_program(p);
    let rows = run(
        &b,
        7,
        10.0,
        "0,main.b.t.PT,T#20ms\n0,%IX0.0,1\n",
        &["%QX0.0"],
    );
    // the TON restarts the cycle after it fires, so the lamp toggles every 4 cycles from cycle 2
    assert_eq!(column(&rows, "%QX0.0"), ["0", "0", "1", "1", "1", "1", "0"]);
}
