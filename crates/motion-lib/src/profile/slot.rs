//! A large return value built in a slot the planner writes once.
//!
//! `Result<Profile, PlanError>` is 552 bytes. Returned by value from a function that
//! builds it in a local, it is copied into the caller's slot right after being written
//! with small stores. The planners therefore also exist as `*_into` functions that write
//! their result once into a slot the caller keeps (an `Option`, reused from plan to plan,
//! as rsruckig reuses its `Trajectory`); [`in_place`] gives the by-value form on top. All of it is safe code (the
//! crate keeps `unsafe` to its C ABI): a builder that returns without writing its slot
//! panics instead of leaving anything uninitialised.

/// The value that `build` writes into its slot. `build` must write the slot it is given
/// (with [`Option::insert`]); otherwise this panics.
#[inline(always)]
pub(crate) fn in_place<T>(build: impl FnOnce(&mut Option<T>) -> &mut T) -> T {
    let mut slot = None;
    build(&mut slot);
    slot.expect("in_place: the builder did not initialise its slot")
}

#[cfg(test)]
mod tests {
    use super::in_place;

    /// The value is what the builder wrote and then modified, for a value with a
    /// destructor too.
    #[test]
    fn in_place_gives_the_built_value() {
        let v: Result<[f64; 4], String> = in_place(|slot| {
            let r = slot.insert(Ok([1.0; 4]));
            if let Ok(a) = r {
                a[2] = 5.0;
            }
            r
        });
        assert_eq!(v, Ok([1.0, 1.0, 5.0, 1.0]));
        let e: Result<[f64; 4], String> = in_place(|slot| slot.insert(Err("no".into())));
        assert_eq!(e, Err("no".to_string()));
    }

    /// A builder that returns another value than its slot's panics instead of leaving the
    /// slot uninitialised.
    #[test]
    #[should_panic(expected = "did not initialise its slot")]
    fn a_builder_that_does_not_write_its_slot_panics() {
        let _: [f64; 4] = in_place(|_slot: &mut Option<[f64; 4]>| Box::leak(Box::new([0.0; 4])));
    }

    /// A slot reused from plan to plan holds each plan's result, equal to the by-value
    /// planners' (durations and end states), for profiles, errors and lines.
    #[test]
    fn a_reused_slot_gives_what_the_by_value_planners_give() {
        use crate::profile::{line::Line, Limits, Profile, State};
        let lim = Limits {
            vmax: 2.0,
            amax: 5.0,
            dmax: 4.0,
            jmax: 50.0,
        };
        let mut slot = None;
        for (p0, v0, p1) in [(0.0, 0.0, 10.0), (3.0, 1.5, -2.0), (0.0, 0.0, 0.25)] {
            let start = State {
                p: p0,
                v: v0,
                a: 0.0,
            };
            let by_value = Profile::position(start, p1, 0.0, &lim).expect("plans");
            let into = Profile::position_into(&mut slot, start, p1, 0.0, &lim)
                .as_ref()
                .expect("plans");
            assert_eq!(into.duration(), by_value.duration());
            assert_eq!(into.at(into.duration()), by_value.at(by_value.duration()));
        }
        let bad = Limits {
            vmax: f64::NAN,
            ..lim
        };
        let err = Profile::position_into(&mut slot, State::default(), 1.0, 0.0, &bad).clone();
        assert_eq!(err, Profile::position(State::default(), 1.0, 0.0, &bad));
        assert!(err.is_err());
        let axes = [lim, lim, Limits { vmax: 1.0, ..lim }];
        let mut line_slot = None;
        for end in [[1.0, 2.0, 3.0], [-4.0, 0.5, 0.0]] {
            let by_value = Line::plan(&[0.0; 3], &end, &axes).expect("plans");
            let into = Line::plan_into(&mut line_slot, &[0.0; 3], &end, &axes)
                .as_ref()
                .expect("plans");
            assert_eq!(into.duration(), by_value.duration());
        }
    }
}
