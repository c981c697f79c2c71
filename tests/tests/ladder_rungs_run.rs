//! Issue #13: the rungs of an LD body drawn on one shared power rail (Beremiz, the OpenPLC Editor:
//! one left rail and one right rail for the whole body, each rung on its own connection point) are
//! networks of their own, run top to bottom, as IEC 61131-3 orders LD networks and as Beremiz and
//! every LD runtime run them: a rung reads the coils of the rungs above it in the same scan.
//! Before (Session 33's start, 0d674c7): the rails joined every rung into one network, evaluated
//! before any coil was written, so two interlocked contactors pressed in the same scan both switched
//! on (a reversing starter's short circuit) and then dropped together, and a rung reading a coil
//! above it saw it one scan late. Inside one rung a contact still reads the value from before the
//! rung (`crates/ladder-compiler/README.md`, `tests/tests/ladder_run.rs`).

mod common;
use common::{column, run_stimulated};

fn fixture(name: &str) -> std::path::PathBuf {
    common::repo_root()
        .join("tests/tests/fixtures/ladder_rungs")
        .join(name)
}

/// UP and DOWN pressed in the same scan (1): the top rung's K_UP wins, K_DOWN reads it (its NC
/// contact) and stays off; RUNNING_UP, a rung below, follows K_UP in the same scan. STOP (4) drops
/// K_UP; DOWN (6) then seals K_DOWN in; UP (8) cannot start K_UP while K_DOWN holds. The two
/// contactors are never on together.
#[test]
fn interlocked_rungs_on_one_rail_run_top_to_bottom() {
    let p = "i0";
    let rows = [
        (1, "UP", 1),
        (1, "DOWN", 1),
        (2, "UP", 0),
        (2, "DOWN", 0),
        (4, "STOP", 1),
        (5, "STOP", 0),
        (6, "DOWN", 1),
        (7, "DOWN", 0),
        (8, "UP", 1),
        (9, "UP", 0),
    ];
    let stimulus: String = rows
        .iter()
        .map(|(c, v, x)| format!("{c},{p}.{v},{x}\n"))
        .collect();
    let (trace, _) = run_stimulated(
        &fixture("interlock.xml"),
        11,
        &stimulus,
        "i0.K_UP,i0.K_DOWN,i0.RUNNING_UP",
    );
    let up = column(&trace, "i0.K_UP");
    let down = column(&trace, "i0.K_DOWN");
    let running = column(&trace, "i0.RUNNING_UP");
    assert_eq!(up, [0., 1., 1., 1., 0., 0., 0., 0., 0., 0., 0.], "{trace}");
    assert_eq!(
        down,
        [0., 0., 0., 0., 0., 0., 1., 1., 1., 1., 1.],
        "{trace}"
    );
    assert_eq!(
        running, up,
        "RUNNING_UP reads K_UP in the same scan: {trace}"
    );
    assert!(
        up.iter().zip(&down).all(|(u, d)| u + d < 2.0),
        "both contactors on: {trace}"
    );
}
