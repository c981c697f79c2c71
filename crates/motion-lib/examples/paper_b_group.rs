//! Paper B's experiment as CSV (time, then position and velocity of each axis, then the
//! path speed), for plotting: `cargo run -p motion-lib --example paper_b_group > b.csv`.
#![forbid(unsafe_code)]

use motion_lib::axis::AxisConfig;
use motion_lib::buffer::{BufferMode, TransitionMode};
use motion_lib::engine::{Engine, EngineConfig};
use motion_lib::group::{GroupMotion, PathInputs};
use motion_lib::profile::Limits;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut e = Engine::new(EngineConfig {
        cycle: 0.01,
        queue_depth: 4,
    })?;
    let cfg = AxisConfig {
        limits: Limits {
            vmax: 500.0,
            amax: 100.0,
            dmax: 100.0,
            jmax: 100.0,
        },
        ..AxisConfig::default()
    };
    let g = e.add_group();
    for ident in 0..3 {
        let a = e.add_axis(cfg)?;
        e.add_axis_to_group(g, a, ident)
            .map_err(|x| format!("{x:?}"))?;
        e.power(a, true).map_err(|x| format!("{x:?}"))?;
    }
    e.group_enable(g).map_err(|x| format!("{x:?}"))?;
    let moves = [
        ([1600.0, 1200.0, 800.0], 40.0, BufferMode::Aborting),
        ([2200.0, 3800.0, 5000.0], 55.0, BufferMode::BlendingLow),
        ([4500.0, 4200.0, 4800.0], 70.0, BufferMode::BlendingHigh),
    ];
    let mut ids = Vec::new();
    for (target, v, bm) in moves {
        let mut position = [0.0; 16];
        position[..3].copy_from_slice(&target);
        let inputs = PathInputs {
            velocity: v,
            acceleration: 5.0,
            deceleration: 5.0,
            jerk: 2.0,
            buffer: bm,
            transition: TransitionMode::None,
            transition_parameter: 0.0,
        };
        ids.push(
            e.submit_group(g, GroupMotion::LinearAbsolute { position }, inputs)
                .map_err(|x| format!("{x:?}"))?,
        );
    }
    println!("t,x,y,z,vx,vy,vz,path_speed");
    while e.status(ids[2]) != motion_lib::cmd::CmdStatus::Done {
        e.step();
        let p = e.group_position(g).map_err(|x| format!("{x:?}"))?;
        let (v, s) = e.group_velocity(g).map_err(|x| format!("{x:?}"))?;
        println!(
            "{:.2},{:.4},{:.4},{:.4},{:.4},{:.4},{:.4},{:.4}",
            e.time(),
            p[0],
            p[1],
            p[2],
            v[0],
            v[1],
            v[2],
            s
        );
    }
    Ok(())
}
