//! E2xxx diagnostics: addresses outside the profile, unsupported address forms, misalignment, unknown
//! or invalid embedded functions, invalid profiles.

mod support;
use c_backend::{AddressUnit, EmbeddedFunction, Options, TargetProfile};
use diagnostics::{render_human, Diagnostics};
use support::*;

/// Generation diagnostics rendered with their source excerpt.
fn rendered(src: &str, profile: &TargetProfile, opts: &Options) -> String {
    let (units, model, map) = frontend(src);
    let mut diags = Diagnostics::new();
    let r = c_backend::generate(&units, &model, profile, opts, &mut diags);
    assert!(r.is_none(), "generation unexpectedly succeeded");
    render_human(&map, &diags.into_sorted())
}

#[test]
fn address_outside_the_profile_area_is_e2001_with_its_span() {
    let src = "PROGRAM main
VAR
  far AT %QW200 : WORD;
END_VAR
  LD %IX300.0
  ST %QX0.0
  LD 1
  ST far
END_PROGRAM
";
    let out = rendered(src, &TargetProfile::default(), &Options::default());
    insta::assert_snapshot!(out);
    // the same program fits a profile with larger areas
    let big = TargetProfile {
        input_bytes: 512,
        output_bytes: 512,
        ..TargetProfile::default()
    };
    let (units, model, map) = frontend(src);
    generate_with(&units, &model, &map, &big, &Options::default());
}

#[test]
fn unsupported_address_forms_are_e2002() {
    let errors = generate_errors(
        "PROGRAM main
  LD %IW0.1
  ST %QW1
  LD %IX1.2.3
  ST %QX0.0
  LD %IX0.9
  ST %QX0.0
END_PROGRAM
",
        &TargetProfile::default(),
        &Options::default(),
    );
    // hierarchical addresses (`%IW0.1`, `%IX1.2.3`) have slots of their own (see `emit::hier`):
    // the bit number above 7 is the form left
    assert_eq!(errors.len(), 1, "{errors:#?}");
    assert!(
        errors.iter().all(|e| e.contains("error[E2002]")),
        "{errors:#?}"
    );
    assert!(errors[0].starts_with("test.il:6:6:"), "{errors:#?}");
}

#[test]
fn a_bit_address_with_one_number_is_an_absolute_bit_number() {
    let (units, model, map) = frontend("PROGRAM main\n  LD %IX13\n  ST %QX2\nEND_PROGRAM\n");
    let p = generate_with(
        &units,
        &model,
        &map,
        &TargetProfile::default(),
        &Options::default(),
    );
    let b = build_program(p);
    // %IX13 is byte 1 bit 5, %QX2 byte 0 bit 2
    let rows = run(&b, 2, 10.0, "1,%IX1.5,1\n", &["%QX0.2", "%QX2", "%QB0"]);
    assert_eq!(rows[1][2..].join(","), "0,0,0");
    assert_eq!(rows[2][2..].join(","), "1,1,4");
}

#[test]
fn misaligned_word_in_byte_addressing_is_e2006() {
    let profile = TargetProfile {
        address_unit: AddressUnit::Byte,
        alignment: 2,
        ..TargetProfile::default()
    };
    let errors = generate_errors(
        "PROGRAM main
  LD %IW3
  ST %QW4
END_PROGRAM
",
        &profile,
        &Options::default(),
    );
    assert_eq!(errors.len(), 1, "{errors:#?}");
    assert!(
        errors[0].contains("error[E2006]") && errors[0].contains("byte 3"),
        "{errors:#?}"
    );
}

#[test]
fn unknown_embedded_function_is_e2004() {
    let out = rendered(
        "PROGRAM main
  LD TRUE
  FUNC MC_MoveAbsolute()
  ST %QX0.0
END_PROGRAM
",
        &TargetProfile::default(),
        &Options::default(),
    );
    insta::assert_snapshot!(out);
}

#[test]
fn invalid_embedded_function_names_are_e2007() {
    let opts = Options {
        embedded: ["int", "ladderc_now", "move-abs", "ok_name", "OK_NAME"]
            .iter()
            .map(|n| EmbeddedFunction {
                name: n.to_string(),
                c_source: "void ok_name(void) {}\n".into(),
            })
            .collect(),
        ..Default::default()
    };
    let errors = generate_errors(
        "PROGRAM main\n  LD TRUE\n  ST %QX0.0\nEND_PROGRAM\n",
        &TargetProfile::default(),
        &opts,
    );
    assert_eq!(errors.len(), 4, "{errors:#?}");
    assert!(
        errors.iter().all(|e| e.contains("error[E2007]")),
        "{errors:#?}"
    );
}

#[test]
fn embedded_function_is_called_and_shares_the_tm_area() {
    // A stand-in for a parameter-passing block: inputs copied into TM bytes by IL, the C function
    // reads and writes only TM, outputs copied back.
    let src = "PROGRAM main
VAR
  a : WORD := 20;
  b : WORD := 22;
  sum : INT;
END_VAR
  LD a
  ST %MW1920
  LD b
  ST %MW1921
  FUNC TM_Add()
  LD %MW1922
  WORD_TO_INT
  ST sum
END_PROGRAM
";
    // default profile: TM = bytes 3840..4096 of %M, i.e. %MW1920 is TM byte 0
    let opts = Options {
        embedded: vec![EmbeddedFunction {
            name: "tm_add".into(),
            c_source: "void tm_add(void) {\n    uint16_t x = (uint16_t)ladderc_load(LADDERC_TM, 0, 2);\n    uint16_t y = (uint16_t)ladderc_load(LADDERC_TM, 2, 2);\n    ladderc_store(LADDERC_TM, 4, 2, (uint16_t)(x + y));\n}\n".into(),
        }],
        ..Default::default()
    };
    let (units, model, map) = frontend(src);
    let p = generate_with(&units, &model, &map, &TargetProfile::default(), &opts);
    assert!(p.file("embedded.c").is_some());
    assert!(p.file("program.h").unwrap().contains("void tm_add(void);"));
    let b = build_program(p);
    let rows = run(&b, 1, 10.0, "", &["main.sum"]);
    assert_eq!(column(&rows, "main.sum"), ["42"]);
}

#[test]
fn target_profiles_load_validate_and_round_trip() {
    let d = TargetProfile::default();
    assert_eq!(
        TargetProfile::from_json(c_backend::profile::DEFAULT_PROFILE_JSON).unwrap(),
        d
    );
    assert_eq!(TargetProfile::from_json(&d.to_json()).unwrap(), d);
    let e = TargetProfile::from_json("{\"name\": \"x\"}")
        .unwrap_err()
        .to_string();
    assert!(e.contains("missing field"), "{e}");
    let mut bad = d.clone();
    bad.tm_offset = bad.memory_bytes - 10;
    let e = TargetProfile::from_json(&bad.to_json())
        .unwrap_err()
        .to_string();
    assert!(e.contains("TM area"), "{e}");
    bad = d.clone();
    bad.alignment = 3;
    assert!(TargetProfile::from_json(&bad.to_json()).is_err());
    bad = d.clone();
    bad.input_bytes = 0;
    assert!(TargetProfile::from_json(&bad.to_json()).is_err());
    let unknown = d.to_json().replace("\"name\"", "\"nmae\"");
    assert!(TargetProfile::from_json(&unknown).is_err());
    // loading a missing file is an I/O error: E9001
    let mut diags = Diagnostics::new();
    assert!(
        TargetProfile::load_or_report(std::path::Path::new("/nonexistent/p.json"), &mut diags)
            .is_none()
    );
    assert_eq!(diags.iter().next().unwrap().code.0, "E9001");
}

#[test]
fn unsupported_constructs_are_e2005_not_bad_c() {
    let errors = generate_errors(
        "PROGRAM main
VAR
  s AT %QB0 : STRING;
END_VAR
  LD 'abc'
  ST s
END_PROGRAM
",
        &TargetProfile::default(),
        &Options::default(),
    );
    assert_eq!(errors.len(), 1, "{errors:#?}");
    assert!(
        errors[0].contains("error[E2005]") && errors[0].contains("located variable"),
        "{errors:#?}"
    );
}
