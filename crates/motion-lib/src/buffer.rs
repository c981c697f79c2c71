//! Buffer modes, transition modes and the bounded command queue.
//!
//! Input: the BufferMode / TransitionMode inputs of the blocks and commands to queue.
//! Output: the junction velocity between two moves and a fixed-capacity FIFO.
//! Invariants: the queue never allocates after creation and never drops an element: a
//! push onto a full queue is refused (the caller reports `ErrorId::QueueFull`).

use std::collections::VecDeque;

use crate::error::ErrorId;

/// MC_BUFFER_MODE.
#[repr(u8)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum BufferMode {
    #[default]
    /// Starts at once from the current position, velocity and acceleration; the running and every
    /// buffered command get CommandAborted.
    Aborting = 0,
    /// Starts when the predecessor releases the axis (positioning: Done; MoveVelocity: InVelocity;
    /// GearIn/CamIn: InGear/InSync), from rest for positioning moves.
    Buffered = 1,
    /// Joins the predecessor at the lower of the two commanded velocities, min(v1, v2).
    BlendingLow = 2,
    /// Joins the predecessor at its own velocity v1.
    BlendingPrevious = 3,
    /// Joins the predecessor at the successor's velocity v2.
    BlendingNext = 4,
    /// Joins the predecessor at the higher of the two commanded velocities, max(v1, v2).
    BlendingHigh = 5,
}

impl BufferMode {
    /// From the PLCopen integer value.
    pub fn from_u8(v: u8) -> Result<BufferMode, ErrorId> {
        Ok(match v {
            0 => BufferMode::Aborting,
            1 => BufferMode::Buffered,
            2 => BufferMode::BlendingLow,
            3 => BufferMode::BlendingPrevious,
            4 => BufferMode::BlendingNext,
            5 => BufferMode::BlendingHigh,
            _ => return Err(ErrorId::InvalidBufferMode),
        })
    }

    /// True for the four blending modes.
    pub fn is_blending(self) -> bool {
        !matches!(self, BufferMode::Aborting | BufferMode::Buffered)
    }

    /// Junction speed (magnitude) between a predecessor with velocity `v1` and a successor
    /// with velocity `v2` (both magnitudes): 0 for Buffered, min/v1/v2/max for blending.
    pub fn junction_speed(self, v1: f64, v2: f64) -> f64 {
        let (v1, v2) = (v1.abs(), v2.abs());
        match self {
            BufferMode::Aborting | BufferMode::Buffered => 0.0,
            BufferMode::BlendingLow => v1.min(v2),
            BufferMode::BlendingPrevious => v1,
            BufferMode::BlendingNext => v2,
            BufferMode::BlendingHigh => v1.max(v2),
        }
    }
}

/// MC_TRANSITION_MODE (Part 4). TMNone, TMCornerDistance and TMMaxCornerDeviation are
/// implemented; TMStartVelocity (1) and TMConstantVelocity (2), whose geometry Part 4
/// leaves to the vendor, are refused with ErrorID 59 (InvalidTransitionMode).
#[repr(u8)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum TransitionMode {
    /// The path speed at the corner is the junction speed, the direction changes at once.
    #[default]
    None = 0,
    /// TransitionParameter = corner distance: the blend leaves the path that far before
    /// the corner and joins it that far after.
    CornerDistance = 3,
    /// TransitionParameter = the largest distance the blend may pass from the corner.
    MaxCornerDeviation = 4,
}

impl TransitionMode {
    /// From the PLCopen integer value (1, 2 and values above 4 are refused).
    pub fn from_u8(v: u8) -> Result<TransitionMode, ErrorId> {
        match v {
            0 => Ok(TransitionMode::None),
            3 => Ok(TransitionMode::CornerDistance),
            4 => Ok(TransitionMode::MaxCornerDeviation),
            _ => Err(ErrorId::InvalidTransitionMode),
        }
    }
}

/// MC_DIRECTION.
#[repr(u8)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Direction {
    #[default]
    /// mcPositiveDirection: modulo targets are reached moving forward; MoveVelocity runs forward.
    Positive = 0,
    /// mcShortestWay: the shorter way round a modulo axis (refused by MoveVelocity, ErrorID 25).
    Shortest = 1,
    /// mcNegativeDirection: modulo targets are reached moving backward; MoveVelocity runs backward.
    Negative = 2,
    /// mcCurrentDirection: keeps the direction the axis moves in now (forward from rest).
    Current = 3,
}

impl Direction {
    /// From the integer value (0 positive, 1 shortest, 2 negative, 3 current: the order
    /// of MC_DIRECTION in the PLCopen specification).
    pub fn from_u8(v: u8) -> Result<Direction, ErrorId> {
        Ok(match v {
            0 => Direction::Positive,
            1 => Direction::Shortest,
            2 => Direction::Negative,
            3 => Direction::Current,
            _ => return Err(ErrorId::InvalidDirection),
        })
    }
}

/// A bounded FIFO that refuses pushes when full.
#[derive(Clone, Debug)]
pub(crate) struct Queue<T> {
    items: VecDeque<T>,
    depth: usize,
}

impl<T> Queue<T> {
    /// A queue holding at most `depth` elements (memory reserved now).
    pub fn new(depth: usize) -> Queue<T> {
        Queue {
            items: VecDeque::with_capacity(depth),
            depth,
        }
    }

    /// Appends `item`, or gives it back with `ErrorId::QueueFull`.
    pub fn push(&mut self, item: T) -> Result<(), (ErrorId, T)> {
        if self.items.len() >= self.depth {
            Err((ErrorId::QueueFull, item))
        } else {
            self.items.push_back(item);
            Ok(())
        }
    }

    pub fn pop(&mut self) -> Option<T> {
        self.items.pop_front()
    }

    pub fn front(&self) -> Option<&T> {
        self.items.front()
    }

    pub fn back(&self) -> Option<&T> {
        self.items.back()
    }

    pub fn back_mut(&mut self) -> Option<&mut T> {
        self.items.back_mut()
    }

    pub fn iter(&self) -> impl Iterator<Item = &T> {
        self.items.iter()
    }

    pub fn iter_mut(&mut self) -> impl Iterator<Item = &mut T> {
        self.items.iter_mut()
    }

    pub fn len(&self) -> usize {
        self.items.len()
    }

    pub fn is_empty(&self) -> bool {
        self.items.is_empty()
    }

    pub fn depth(&self) -> usize {
        self.depth
    }

    /// Removes every element, oldest first, handing each to `f`.
    pub fn drain_with(&mut self, mut f: impl FnMut(T)) {
        while let Some(x) = self.items.pop_front() {
            f(x);
        }
    }
}
