//! The engine on its own thread: the scan hands blocks over through the lock-free channel
//! and MC_Power + MC_MoveAbsolute reach Done.

use motion_lib::axis::AxisConfig;
use motion_lib::blocks::{McMoveAbsolute, McPower};
use motion_lib::engine::{Engine, EngineConfig};
use motion_lib::remote::{spawn, AnyBlock, Target};

#[test]
fn engine_thread_runs_blocks_from_the_scan() {
    let mut e = Engine::new(EngineConfig {
        cycle: 0.0005,
        queue_depth: 4,
    })
    .unwrap();
    let a = e.add_axis(AxisConfig::default()).unwrap();
    let mut link = spawn(e, 2);
    let mut blocks = [
        AnyBlock::Power(McPower {
            enable: true,
            ..Default::default()
        }),
        AnyBlock::MoveAbsolute(McMoveAbsolute {
            execute: true,
            position: 2.0,
            velocity: 100.0,
            acceleration: 2000.0,
            deceleration: 2000.0,
            ..Default::default()
        }),
    ];
    let mut done = false;
    let start = std::time::Instant::now();
    while !done && start.elapsed().as_secs() < 20 {
        link.receive(&mut blocks);
        if let AnyBlock::MoveAbsolute(m) = &blocks[1] {
            assert!(!m.error, "{:?}", m.error_id);
            done = m.done;
        }
        // MoveAbsolute only after the power is on (like a PLC program would).
        let powered = matches!(blocks[0], AnyBlock::Power(p) if p.status);
        link.call(0, &blocks[0], Target::Axis(a));
        if powered {
            link.call(1, &blocks[1], Target::Axis(a));
        }
        std::thread::sleep(std::time::Duration::from_micros(500));
    }
    assert!(done);
    assert!(link.cycles() > 10);
    let e = link.stop().unwrap();
    assert!((e.set_position_of(a).unwrap() - 2.0).abs() < 1e-9);
}
