//! A large return value built in the caller's return slot.
//!
//! `Result<Profile, PlanError>` is 552 bytes. Returned by value from a function that
//! builds it in a local, it is copied into the caller's slot right after being written
//! with small stores; the copy's wide loads cannot be forwarded from those stores and
//! wait until they reach the cache (about a third of a fast-path plan's time).
//! [`in_place`] has the value built in the slot itself: the builder is a call that writes
//! through a pointer to an uninitialised local, which the compiler then replaces by the
//! caller's return slot (no copy).
//!
//! Safety argument of the one `unsafe` block: [`run`] returns normally only when the
//! builder returned a reference to the slot itself, and safe code can only obtain a
//! `&mut T` to an uninitialised slot by writing it ([`MaybeUninit::write`]). If the
//! builder panics, the unwinding leaves [`in_place`] before the slot is read (a value
//! already written is then leaked, never read or dropped twice).

use std::mem::MaybeUninit;

/// The value that `build` writes into an uninitialised slot, built in the caller's slot.
/// `build` must initialise the slot it is given (with [`MaybeUninit::write`]) and return
/// the reference that gives; anything else panics.
#[inline(always)]
pub(crate) fn in_place<T>(build: impl FnOnce(&mut MaybeUninit<T>) -> &mut T) -> T {
    let mut slot = MaybeUninit::uninit();
    run(&mut slot, build);
    // SAFETY: `run` returned normally, so `slot` is initialised (module documentation).
    unsafe { slot.assume_init() }
}

/// Calls `build` on `slot` and checks that it returned the slot, initialised. A call of
/// its own (never inlined): the compiler can then pass the caller's return slot as
/// `slot`.
#[inline(never)]
fn run<T>(slot: &mut MaybeUninit<T>, build: impl FnOnce(&mut MaybeUninit<T>) -> &mut T) {
    let at = slot.as_ptr();
    let built: *const T = build(slot);
    assert!(
        std::ptr::eq(built, at),
        "in_place: the builder did not initialise its slot"
    );
}

#[cfg(test)]
mod tests {
    use super::in_place;
    use std::mem::MaybeUninit;

    /// The value is what the builder wrote and then modified, for a value with a
    /// destructor too.
    #[test]
    fn in_place_gives_the_built_value() {
        let v: Result<[f64; 4], String> = in_place(|slot| {
            let r = slot.write(Ok([1.0; 4]));
            if let Ok(a) = r {
                a[2] = 5.0;
            }
            r
        });
        assert_eq!(v, Ok([1.0, 1.0, 5.0, 1.0]));
        let e: Result<[f64; 4], String> = in_place(|slot| slot.write(Err("no".into())));
        assert_eq!(e, Err("no".to_string()));
    }

    /// A builder that returns another value than its slot's panics instead of leaving the
    /// slot uninitialised.
    #[test]
    #[should_panic(expected = "did not initialise its slot")]
    fn a_builder_that_does_not_write_its_slot_panics() {
        let _: [f64; 4] =
            in_place(|_slot: &mut MaybeUninit<[f64; 4]>| Box::leak(Box::new([0.0; 4])));
    }
}
