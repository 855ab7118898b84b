//! Where a traced formula holds, as the traced code recorded it: the trace's side of
//! [`crate::branch`]. The core tells the running trace when it picks a piece by a value
//! ([`crate::branch::choose`]) or reads one quietly; every other read of a value (`re()` in
//! the code, or in num-dual's own functions, such as `sph_j0` near 0) is recorded as a read
//! without a condition: the formula is then claimed at the trace point only.

use super::expr::ARENA;
use crate::branch::Observer;

/// The hooks a running trace installs ([`crate::branch::observe`]).
pub(crate) static OBSERVER: Observer = Observer {
    begin_choice: || enter(ReadMode::Piece(None)),
    end_choice: |condition| {
        ARENA.with(|a| {
            let mut a = a.borrow_mut();
            if let ReadMode::Piece(Some(id)) = a.read_mode {
                a.claims.push((id, condition));
            }
            a.read_mode = a.read_modes.pop().unwrap_or_default();
        })
    },
    begin_quiet: || enter(ReadMode::Quiet),
    end_quiet: || {
        ARENA.with(|a| {
            let mut a = a.borrow_mut();
            a.read_mode = a.read_modes.pop().unwrap_or_default();
        })
    },
};

/// Enters `mode`, keeping the one it replaces for the matching end.
fn enter(mode: ReadMode) {
    ARENA.with(|a| {
        let mut a = a.borrow_mut();
        let before = std::mem::replace(&mut a.read_mode, mode);
        a.read_modes.push(before);
    })
}

/// How an expression's value read through `re()` is recorded.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub(crate) enum ReadMode {
    /// A read without a condition (the formula is claimed at the trace point only).
    #[default]
    Unrecorded,
    /// Inside [`choose`]: the node read is kept for its condition.
    Piece(Option<u32>),
    /// Inside [`read_quietly`]: not recorded.
    Quiet,
}

/// Records that the value of node `id` (of trace `generation`) was read through `re()`.
pub(crate) fn note_read(id: u32, generation: u64, value: f64) {
    ARENA.with(|a| {
        let mut a = a.borrow_mut();
        if a.generation != generation || !a.live {
            return;
        }
        if matches!(a.nodes.get(id as usize), Some(super::Node::Num(_)) | None) {
            // a constant's value chooses nothing
            return;
        }
        match a.read_mode {
            ReadMode::Piece(_) => a.read_mode = ReadMode::Piece(Some(id)),
            ReadMode::Quiet => {}
            ReadMode::Unrecorded => {
                if !a.reads.iter().any(|&(i, _)| i == id) {
                    a.reads.push((id, value));
                }
            }
        }
    })
}
