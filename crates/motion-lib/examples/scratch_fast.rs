use motion_lib::profile::{Limits, Profile, State};
use std::hint::black_box;
fn main() {
    let lim = Limits {
        vmax: 71.19648842444575,
        amax: 9.488249292368122,
        dmax: 9.488249292368122,
        jmax: 3.750756973755056,
    };
    let start = State {
        p: -2862.4958482247066,
        v: 0.0,
        a: 0.0,
    };
    let mut acc = 0.0;
    for _ in 0..5_000_000 {
        acc += Profile::position(
            black_box(start),
            black_box(-344.71613673501633),
            black_box(0.0),
            black_box(&lim),
        )
        .unwrap()
        .duration();
    }
    println!("{acc}");
}
