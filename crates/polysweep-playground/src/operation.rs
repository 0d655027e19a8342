//! The five operations the playground offers, run on the core as it is (no wasm, no JS in between), with the
//! figures the side panel shows; and the drawn lines against the result: clipped by it, and cutting it into pieces.

use crate::scene::Operand;
use polysweep::{clip, overlay_with_stats, split, ClipOptions, Error, FillRule, Keep};
use polysweep::{LineString, MultiPolygon, Operation, Options, Polygon};
use web_time::Instant;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Op {
    Intersection,
    Union,
    SubjectMinusClipping,
    ClippingMinusSubject,
    Xor,
}

impl Op {
    pub const ALL: [Op; 5] = [
        Op::Intersection,
        Op::Union,
        Op::SubjectMinusClipping,
        Op::ClippingMinusSubject,
        Op::Xor,
    ];

    pub fn label(self) -> &'static str {
        match self {
            Op::Intersection => "P ∩ Q  intersection",
            Op::Union => "P ∪ Q  union",
            Op::SubjectMinusClipping => "P − Q  difference",
            Op::ClippingMinusSubject => "Q − P  difference",
            Op::Xor => "P ⊕ Q  xor",
        }
    }

    /// The name used in saved file names.
    pub fn slug(self) -> &'static str {
        match self {
            Op::Intersection => "intersection",
            Op::Union => "union",
            Op::SubjectMinusClipping => "p-minus-q",
            Op::ClippingMinusSubject => "q-minus-p",
            Op::Xor => "xor",
        }
    }
}

/// A computed result and what it took.
#[derive(Clone, Debug)]
pub struct Outcome {
    pub result: MultiPolygon,
    pub crossings: usize,
    pub milliseconds: f64,
}

/// Runs `op` on the operands P and Q. Errors name the operand as the user sees it (P is 0, Q is 1), also for Q − P,
/// which the core computes with the operands swapped.
pub fn run(op: Op, [p, q]: [&MultiPolygon; 2], fill_rule: FillRule) -> Result<Outcome, Error> {
    let options = Options::default().with_fill_rule(fill_rule);
    let start = Instant::now();
    let computed = match op {
        Op::Intersection => overlay_with_stats(Operation::Intersection, p, q, &options),
        Op::Union => overlay_with_stats(Operation::Union, p, q, &options),
        Op::SubjectMinusClipping => overlay_with_stats(Operation::Difference, p, q, &options),
        Op::ClippingMinusSubject => {
            overlay_with_stats(Operation::Difference, q, p, &options).map_err(swap_operands)
        }
        Op::Xor => overlay_with_stats(Operation::Xor, p, q, &options),
    };
    let milliseconds = start.elapsed().as_secs_f64() * 1e3;
    computed.map(|(result, stats)| Outcome {
        result,
        crossings: stats.crossings,
        milliseconds,
    })
}

/// The region an operand covers under the fill rule: what its fill shows. `which` says which operand it is, so
/// that errors name it.
pub fn region(
    operand: &MultiPolygon,
    which: Operand,
    fill_rule: FillRule,
) -> Result<MultiPolygon, Error> {
    let empty = MultiPolygon::default();
    let options = Options::default().with_fill_rule(fill_rule);
    match which {
        Operand::Subject => polysweep::overlay(Operation::Union, operand, &empty, &options),
        Operand::Clipping => polysweep::overlay(Operation::Union, &empty, operand, &options),
    }
}

/// The lines against a result: their parts inside it and outside it (of all lines together), and the result split
/// along them.
#[derive(Clone, Debug)]
pub struct Cut {
    pub inside: Vec<LineString>,
    pub outside: Vec<LineString>,
    pub pieces: Vec<Polygon>,
}

/// Clips `lines` by `result` and splits `result` along them. The result is a valid polygon set, which the default
/// even-odd rule reads as it is; the fill rule that made it could read it otherwise (negative: as nothing). Errors
/// name a line as operand 1, polygon `line`.
pub fn cut(result: &MultiPolygon, lines: &[LineString]) -> Result<Cut, Error> {
    let parts = |keep| -> Result<Vec<LineString>, Error> {
        let per_line = clip(lines, result, &ClipOptions::default().keeping(keep))?;
        Ok(per_line.into_iter().flatten().collect())
    };
    Ok(Cut {
        inside: parts(Keep::Inside)?,
        outside: parts(Keep::Outside)?,
        pieces: split(result, lines, &Options::default())?,
    })
}

fn swap_operands(mut error: Error) -> Error {
    if let Error::NonFiniteCoordinate { at, .. } | Error::CoordinateOutOfRange { at, .. } =
        &mut error
    {
        at.operand = 1 - at.operand;
    }
    error
}
