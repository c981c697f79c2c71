//! The profile kernel: ruckig's closed-form profile families, kept free of any interface.
//!
//! Input: one-axis boundary states and limits. Output: the time-optimal kernel
//! [`kprofile::Profile`] (seven phases of constant jerk) after an optional brake
//! pre-phase, plus the blocked duration intervals of ruckig's step 1.
//! Invariants: every profile it returns passed the validity check of [`kprofile`]; nothing
//! allocates.
//!
//! Provenance: `roots`, `brake`, `kprofile`, `pos3` (step 1 of the third-order position
//! problem) and `pos2` (second order) are adapted from rsruckig 3.0.1
//! (<https://github.com/petrikosk/rsruckig>), the Rust port of ruckig
//! (<https://github.com/pantor/ruckig>), both MIT licensed:
//! Copyright (c) 2021 Lars Berscheid; Copyright (c) 2023 Petri Koskinen.
//! Permission is hereby granted, free of charge, to any person obtaining a copy of this
//! software and associated documentation files, to deal in the Software without
//! restriction, subject to the following condition: the above copyright notice and this
//! permission notice shall be included in all copies or substantial portions of the
//! Software. THE SOFTWARE IS PROVIDED "AS IS", WITHOUT WARRANTY OF ANY KIND.
//! Changes: no allocation, no interface types, NaN-safe root sorting, brake phases kept
//! outside the kernel profile, unused interfaces removed.

#![allow(clippy::too_many_arguments, clippy::upper_case_acronyms)]

pub mod brake;
pub mod kprofile;
pub mod pos2;
pub mod pos2_duration;
pub mod pos3;
pub mod pos3_duration;
pub mod roots;

use core::cmp::Ordering;
use kprofile::Profile;

/// State after `t` of constant jerk `j` from (p0, v0, a0).
#[inline]
pub fn integrate(t: f64, p0: f64, v0: f64, a0: f64, j: f64) -> (f64, f64, f64) {
    (
        p0 + t * (v0 + t * (a0 / 2.0 + t * j / 6.0)),
        v0 + t * (a0 + t * j / 2.0),
        a0 + t * j,
    )
}

/// A blocked interval of durations (left, right): no profile of such a duration exists.
#[derive(Debug, Clone, Copy, Default)]
pub struct Interval {
    pub left: f64,
    pub right: f64,
    /// The extremal profile of duration `right`.
    pub profile: Profile,
}

impl Interval {
    #[inline]
    pub fn from_profiles(profile_left: &Profile, profile_right: &Profile) -> Self {
        let l = profile_left.t_sum[6];
        let r = profile_right.t_sum[6];
        Self {
            left: l.min(r),
            right: l.max(r),
            profile: if l < r { *profile_right } else { *profile_left },
        }
    }
}

/// Result of step 1: the fastest profile and the blocked intervals.
#[derive(Clone, Default, Debug)]
pub struct Block {
    pub p_min: Profile,
    pub t_min: f64,
    pub a: Option<Interval>,
    pub b: Option<Interval>,
}

#[inline]
pub fn remove_profile(
    valid_profiles: &mut [Profile; 6],
    valid_profile_counter: &mut usize,
    index: usize,
) {
    for i in index..(*valid_profile_counter - 1) {
        valid_profiles[i] = valid_profiles[i + 1];
    }
    *valid_profile_counter -= 1;
}

impl Block {
    #[inline]
    pub fn set_min_profile(&mut self, profile: &Profile) {
        self.p_min = *profile;
        self.t_min = self.p_min.t_sum[6];
        self.a = None;
        self.b = None;
    }

    #[inline]
    #[allow(clippy::if_same_then_else)]
    pub fn calculate_block(
        block: &mut Block,
        valid_profiles: &mut [Profile; 6],
        valid_profile_counter: &mut usize,
        numerical_robust: Option<bool>,
    ) -> bool {
        if *valid_profile_counter == 1 {
            block.set_min_profile(&valid_profiles[0]);
            return true;
        } else if *valid_profile_counter == 2 {
            if f64::abs(valid_profiles[0].t_sum[6] - valid_profiles[1].t_sum[6])
                < 8.0 * f64::EPSILON
            {
                block.set_min_profile(&valid_profiles[0]);
                return true;
            }

            if numerical_robust.unwrap_or(true) {
                let idx_min = if valid_profiles[0].t_sum[6] < valid_profiles[1].t_sum[6] {
                    0
                } else {
                    1
                };

                let idx_else_1 = (idx_min + 1) % 2;

                block.set_min_profile(&valid_profiles[idx_min]);
                block.a = Some(Interval::from_profiles(
                    &valid_profiles[idx_min],
                    &valid_profiles[idx_else_1],
                ));

                return true;
            }
            // Only happens due to numerical issues
        } else if *valid_profile_counter == 4 {
            // Find "identical" profiles. Note that the last pair does not
            // compare directions: a degenerate profile (e.g. with a zero-width
            // velocity plateau) can duplicate a profile of the same direction
            // from another family (matches upstream C++ behavior).
            if f64::abs(valid_profiles[0].t_sum[6] - valid_profiles[1].t_sum[6])
                < 32.0 * f64::EPSILON
                && valid_profiles[0].direction != valid_profiles[1].direction
            {
                remove_profile(valid_profiles, valid_profile_counter, 1);
            } else if f64::abs(valid_profiles[2].t_sum[6] - valid_profiles[3].t_sum[6])
                < 256.0 * f64::EPSILON
                && valid_profiles[2].direction != valid_profiles[3].direction
            {
                remove_profile(valid_profiles, valid_profile_counter, 3);
            } else if f64::abs(valid_profiles[0].t_sum[6] - valid_profiles[3].t_sum[6])
                < 256.0 * f64::EPSILON
            {
                remove_profile(valid_profiles, valid_profile_counter, 3);
            } else {
                // Fallback for numerically degenerate inputs (e.g. boundary
                // states exactly on the velocity-at-zero-acceleration curve):
                // two profiles from different families with essentially
                // identical durations describe the same solution, and the
                // interval between them would be degenerate anyway.
                let mut removed = false;
                'outer: for i in 0..4 {
                    for j in (i + 1)..4 {
                        let ti = valid_profiles[i].t_sum[6];
                        let tj = valid_profiles[j].t_sum[6];
                        if f64::abs(ti - tj) < 1e-12 * (1.0 + f64::abs(ti)) {
                            remove_profile(valid_profiles, valid_profile_counter, j);
                            removed = true;
                            break 'outer;
                        }
                    }
                }
                if !removed {
                    return false;
                }
            }
        } else if (*valid_profile_counter).is_multiple_of(2) {
            return false;
        }

        // Find index of fastest profile
        let idx_min = valid_profiles
            .iter()
            .take(*valid_profile_counter)
            .enumerate()
            .min_by(|(_, a), (_, b)| {
                a.t_sum[6]
                    .partial_cmp(&b.t_sum[6])
                    .unwrap_or(Ordering::Equal)
            })
            .map(|(idx, _)| idx)
            .unwrap_or(0);

        block.set_min_profile(&valid_profiles[idx_min]);

        if *valid_profile_counter == 3 {
            let idx_else_1 = (idx_min + 1) % 3;
            let idx_else_2 = (idx_min + 2) % 3;

            block.a = Some(Interval::from_profiles(
                &valid_profiles[idx_else_1],
                &valid_profiles[idx_else_2],
            ));
            return true;
        } else if *valid_profile_counter == 5 {
            let idx_else_1 = (idx_min + 1) % 5;
            let idx_else_2 = (idx_min + 2) % 5;
            let idx_else_3 = (idx_min + 3) % 5;
            let idx_else_4 = (idx_min + 4) % 5;

            if valid_profiles[idx_else_1].direction == valid_profiles[idx_else_2].direction {
                block.a = Some(Interval::from_profiles(
                    &valid_profiles[idx_else_1],
                    &valid_profiles[idx_else_2],
                ));
                block.b = Some(Interval::from_profiles(
                    &valid_profiles[idx_else_3],
                    &valid_profiles[idx_else_4],
                ));
            } else {
                block.a = Some(Interval::from_profiles(
                    &valid_profiles[idx_else_1],
                    &valid_profiles[idx_else_4],
                ));
                block.b = Some(Interval::from_profiles(
                    &valid_profiles[idx_else_2],
                    &valid_profiles[idx_else_3],
                ));
            }
            return true;
        }

        false
    }

    /// True when no profile of duration `t` exists.
    pub fn is_blocked(&self, t: f64) -> bool {
        t < self.t_min
            || self.a.is_some_and(|a| t > a.left && t < a.right)
            || self.b.is_some_and(|b| t > b.left && t < b.right)
    }
}
