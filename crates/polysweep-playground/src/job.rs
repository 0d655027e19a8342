//! What the canvas shows that takes time to compute, as jobs on a snapshot of their inputs, so that they can run
//! away from the UI thread (background.rs): the region each operand covers, filled; and the operation's result,
//! filled, with the drawn lines clipped by it and cutting it into pieces.

use crate::fill::{Fill, Outline};
use crate::operation::{self, Cut, Op, Outcome};
use crate::scene::Operand;
use polysweep::{Error, FillRule, LineString, MultiPolygon};
use std::sync::Arc;

/// The jobs there are, one slot each: a newer job of a slot supersedes an older one that has not started.
pub const SLOTS: usize = 3;

#[derive(Clone, Debug)]
pub enum Job {
    /// The region one operand covers under the fill rule, triangulated.
    Region {
        which: Operand,
        operand: Arc<MultiPolygon>,
        fill_rule: FillRule,
    },
    /// The operation on P and Q, and the lines against its result.
    Result {
        op: Op,
        fill_rule: FillRule,
        operands: [Arc<MultiPolygon>; 2],
        lines: Vec<LineString>,
    },
}

/// What a job computed.
pub enum Derivation {
    Region(Fill),
    Result(Box<Computed>),
}

/// The result of the operation and everything drawn of it.
pub struct Computed {
    pub outcome: Result<Outcome, Error>,
    pub fill: Fill,
    pub outline: Outline,
    /// The lines against the result: none without lines, or without a result to clip them by.
    pub cut: Option<Result<Cut, Error>>,
    /// One fill per piece of the cut.
    pub piece_fills: Vec<Fill>,
    pub piece_outline: Outline,
}

impl Job {
    /// The slot of this job: P's region, Q's region, the result.
    pub fn slot(&self) -> usize {
        match self {
            Job::Region { which, .. } => which.index(),
            Job::Result { .. } => 2,
        }
    }

    pub fn run(&self) -> Derivation {
        match self {
            Job::Region {
                which,
                operand,
                fill_rule,
            } => {
                let region = operation::region(operand, *which, *fill_rule).unwrap_or_default();
                Derivation::Region(Fill::of(&region))
            }
            Job::Result {
                op,
                fill_rule,
                operands: [p, q],
                lines,
            } => {
                let outcome = operation::run(*op, [p, q], *fill_rule);
                let cut = match &outcome {
                    Ok(outcome) if !lines.is_empty() => {
                        Some(operation::cut(&outcome.result, lines))
                    }
                    _ => None,
                };
                let (fill, piece_fills) = match &cut {
                    Some(Ok(cut)) => (Fill::default(), fills_of_pieces(cut)),
                    _ => (
                        outcome
                            .as_ref()
                            .map(|o| Fill::of(&o.result))
                            .unwrap_or_default(),
                        Vec::new(),
                    ),
                };
                Derivation::Result(Box::new(Computed::new(outcome, fill, cut, piece_fills)))
            }
        }
    }
}

impl Computed {
    /// The computed result with its outlines, which are quick to make (the fills are not).
    pub fn new(
        outcome: Result<Outcome, Error>,
        fill: Fill,
        cut: Option<Result<Cut, Error>>,
        piece_fills: Vec<Fill>,
    ) -> Computed {
        let outline = match &outcome {
            Ok(o) => Outline::of(&o.result.0),
            Err(_) => Outline::default(),
        };
        let piece_outline = match &cut {
            Some(Ok(cut)) => Outline::of(&cut.pieces),
            _ => Outline::default(),
        };
        Computed {
            outcome,
            fill,
            outline,
            cut,
            piece_fills,
            piece_outline,
        }
    }
}

fn fills_of_pieces(cut: &Cut) -> Vec<Fill> {
    (cut.pieces.iter())
        .map(|piece| Fill::of(&MultiPolygon::new(vec![piece.clone()])))
        .collect()
}
