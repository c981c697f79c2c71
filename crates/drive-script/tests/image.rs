//! Image round trip and rejection of bad images (magic, version, CRC, length, content).

use drive_script::image::{crc32, HEADER_LEN};
use drive_script::*;

fn program(text: &str) -> Program {
    compile_str("t.ds", text).1.expect("compiles").program
}

fn every_kind() -> Program {
    program(
        "S:: PARAM; S:: P0 = -1; S:: P15 = 0x7FFFFFFF;\n\
         S:: INIT; S:: MD0 = 3; S:: MD49 = -2147483648; S:: Velocity = 1; S:: Acceleration = 2;\n\
         S:: Deceleration = 3; S:: JogVelocity = 4; S:: EventsPerCycle = 1024;\n\
         S:: MOTION 0;\n\
         S:: EVENT 0; S:: IF DI_15 AND DO_15 = 1 AND TimerDone_7 <> 0 AND MotionState >= 2;\n\
         S:: THEN MD1 = ActualPosition + ActualVelocity AND DO_3 = ActualCurrent - 1 AND Velocity = P1 * 2\n\
         AND Acceleration = P2 / 3 AND Deceleration = P3 % 4 AND JogVelocity = P4 & 5 AND SetPosition = P5 | 6 AND VelocityMove = P6 ^ 7;\n\
         S:: EVENT 1; S:: IF Homed < 1 AND MotionDone <= 1 AND MathError > -1;\n\
         S:: THEN RelativeTargetPosition = 1 AND AbsoluteTargetPosition = 2 AND Jog = -1 AND Homing = 3 AND Stop AND TimerSet_7 = 100 AND MathError = 0 AND Loop(MD2) = 0;\n\
         S:: EVENT 2; S:: IF TRUE; S:: THEN Jump = 1 AND NextMotionID = 1;\n\
         S:: MOTION 1; S:: EVENT 0; S:: IF FALSE; S:: THEN NextMotionID = 0;",
    )
}

#[test]
fn image_decodes_back_to_an_equal_program() {
    for p in [
        every_kind(),
        program(
            &std::fs::read_to_string(concat!(
                env!("CARGO_MANIFEST_DIR"),
                "/tests/scripts/three_motions.ds"
            ))
            .unwrap(),
        ),
    ] {
        let bytes = encode(&p);
        assert_eq!(&bytes[..4], b"LDSI");
        assert_eq!(decode(&bytes), Ok(p));
    }
}

#[test]
fn image_size_follows_the_documented_layout() {
    let p = program("S:: MOTION 0; S:: EVENT 0; S:: IF DI_0; S:: THEN DO_0=HIGH AND RelativeTargetPosition=10000;");
    // header 16 + fixed 288 + one Motion 4 + one Event (2 + 1 condition * 23 + 2 actions * 13)
    assert_eq!(encode(&p).len(), 16 + 288 + 4 + 2 + 23 + 26);
}

fn with_crc(mut bytes: Vec<u8>) -> Vec<u8> {
    let crc = crc32(&bytes[HEADER_LEN..]);
    bytes[12..16].copy_from_slice(&crc.to_le_bytes());
    bytes
}

#[test]
fn decoder_rejects_bad_magic_version_and_crc_with_their_codes() {
    let good = encode(&every_kind());
    let mut bad = good.clone();
    bad[0] = b'X';
    assert_eq!(decode(&bad), Err(ImageError::BadMagic));
    assert_eq!(decode(&good[..10]), Err(ImageError::BadMagic));
    assert_eq!(ImageError::BadMagic.code().0, "E6020");

    let mut v2 = good.clone();
    v2[4] = 2;
    assert_eq!(decode(&v2), Err(ImageError::UnsupportedVersion(2)));
    assert_eq!(ImageError::UnsupportedVersion(2).code().0, "E6021");

    let mut flipped = good.clone();
    let last = flipped.len() - 1;
    flipped[last] ^= 0x01;
    let e = decode(&flipped).unwrap_err();
    assert!(
        matches!(&e, ImageError::Corrupt(m) if m.contains("CRC-32 mismatch")),
        "{e}"
    );
    assert_eq!(e.code().0, "E6022");

    let e = decode(&good[..good.len() - 3]).unwrap_err();
    assert!(
        matches!(&e, ImageError::Corrupt(m) if m.contains("announces")),
        "{e}"
    );
}

#[test]
fn decoder_rejects_content_that_breaks_the_pool_invariants() {
    let p = program("S:: MOTION 0; S:: EVENT 0; S:: IF TRUE; S:: THEN NextMotionID = 0;");
    let good = encode(&p);
    let event_at = HEADER_LEN + 288 + 4;
    // Action kind byte (after counts and one 23-byte condition).
    let mut bad = good.clone();
    bad[event_at + 2 + 23] = 99;
    let e = decode(&with_crc(bad)).unwrap_err();
    assert_eq!(e, ImageError::Malformed("unknown action 99".into()));
    assert_eq!(e.code().0, "E6023");
    // NextMotionID to Motion 5 of a one-Motion program.
    let mut bad = good.clone();
    bad[event_at + 2 + 23 + 1] = 5;
    let e = decode(&with_crc(bad)).unwrap_err();
    assert!(e.to_string().contains("out of range"), "{e}");
    // Trailing byte (length field updated too).
    let mut bad = good.clone();
    bad.push(0);
    let len = (bad.len() - HEADER_LEN) as u32;
    bad[8..12].copy_from_slice(&len.to_le_bytes());
    assert!(decode(&with_crc(bad))
        .unwrap_err()
        .to_string()
        .contains("trailing"));
}

#[test]
fn decoder_never_panics_on_truncated_or_altered_payloads() {
    let good = encode(&every_kind());
    for cut in HEADER_LEN..good.len() {
        let mut b = good[..cut].to_vec();
        let len = (cut - HEADER_LEN) as u32;
        b[8..12].copy_from_slice(&len.to_le_bytes());
        assert!(decode(&with_crc(b)).is_err(), "cut at {cut}");
    }
    let mut accepted = 0;
    for pos in HEADER_LEN..good.len() {
        for v in [0u8, 1, 0x7F, 0xFF] {
            let mut b = good.clone();
            b[pos] = v;
            if let Ok(p) = decode(&with_crc(b)) {
                // Whatever decodes is a valid program the interpreter accepts and runs.
                let mut i = Interpreter::new(p).expect("decoded programs are valid");
                let mut d = SimDrive::new(1);
                for _ in 0..3 {
                    i.cycle(&mut d);
                    d.tick();
                }
                accepted += 1;
            }
        }
    }
    assert!(
        accepted > 0,
        "value bytes can change without breaking the layout"
    );
}
