//! What the app derives from the operands and lines — the operands' fills, the result and its fill, the lines
//! clipped by the result and its pieces with their fills — and when it is recomputed: only when its inputs change,
//! and mid-drag only what fits in a frame.

use super::Playground;
use crate::fill::{Fill, Outline};
use crate::operation::{self, Cut, Op, Outcome};
use crate::scene::Operand;
use polysweep::{Error, FillRule, MultiPolygon};
use web_time::Instant;

/// A computation slower than this (in milliseconds) is not repeated on every move of a drag.
const FRAME_BUDGET_MS: f64 = 12.0;

/// What is derived from the operands, recomputed only when its inputs change.
#[derive(Default)]
pub(super) struct Derived {
    /// The operand revision and fill rule each region fill was computed from.
    pub(super) region_inputs: [Option<(u64, FillRule)>; 2],
    pub(super) region_fills: [Fill; 2],
    /// The operands' rings as drawn, and the revision they are of: kept up to date on every frame (cheap).
    pub(super) operand_outlines: [(Option<u64>, Outline); 2],
    pub(super) result_inputs: Option<ResultInputs>,
    pub(super) outcome: Option<Result<Outcome, Error>>,
    pub(super) result_fill: Fill,
    pub(super) result_outline: Outline,
    /// The result's inputs and the lines revision the cut was computed from.
    pub(super) cut_inputs: Option<(ResultInputs, u64)>,
    /// The lines against the result: none without lines, or without a result to clip them by.
    pub(super) cut: Option<Result<Cut, Error>>,
    /// One fill per piece of the cut.
    pub(super) piece_fills: Vec<Fill>,
    pub(super) piece_outline: Outline,
    /// How long the last computation of each took (sweeps and triangulation), to decide what can run mid-drag.
    pub(super) region_milliseconds: [f64; 2],
    pub(super) result_milliseconds: f64,
    pub(super) cut_milliseconds: f64,
}

/// The operand revisions, operation and fill rule a result is computed from.
type ResultInputs = ([u64; 2], Op, FillRule);

impl Playground {
    /// The result of the current operation, computing it if the operands, operation or fill rule changed.
    pub fn outcome(&mut self) -> &Result<Outcome, Error> {
        self.refresh(true);
        self.derived.outcome.as_ref().expect("refreshed above")
    }

    /// The drawn lines against the current result, computing them if anything they derive from changed; `None`
    /// without lines or when the operation failed.
    pub fn cut(&mut self) -> Option<&Result<Cut, Error>> {
        self.refresh(true);
        self.derived.cut.as_ref()
    }

    /// Brings the fills, the result and the cut up to date with the operands and lines. With `allow_slow` false
    /// (mid-drag), whatever took longer than a frame last time is left as it is, so that dragging stays smooth on
    /// large data; the canvas refreshes it when the pointer rests or is released. Returns whether everything is up
    /// to date.
    pub(super) fn refresh(&mut self, allow_slow: bool) -> bool {
        let timed = |work: &mut dyn FnMut()| {
            let start = Instant::now();
            work();
            start.elapsed().as_secs_f64() * 1e3
        };
        let mut up_to_date = true;
        for which in [Operand::Subject, Operand::Clipping] {
            let i = which.index();
            let revision = Some(self.scene.revision(which));
            if self.derived.operand_outlines[i].0 != revision {
                self.derived.operand_outlines[i] =
                    (revision, Outline::of(&self.scene.operand(which).0));
            }
            let inputs = Some((self.scene.revision(which), self.fill_rule));
            if self.derived.region_inputs[i] == inputs {
                continue;
            }
            if !allow_slow && self.derived.region_milliseconds[i] > FRAME_BUDGET_MS {
                up_to_date = false;
                continue;
            }
            let (scene, fill_rule, derived) = (&self.scene, self.fill_rule, &mut self.derived);
            derived.region_milliseconds[i] = timed(&mut || {
                let region = operation::region(scene, which, fill_rule).unwrap_or_default();
                derived.region_fills[i] = Fill::of(&region);
            });
            derived.region_inputs[i] = inputs;
        }
        let revisions = [Operand::Subject, Operand::Clipping].map(|w| self.scene.revision(w));
        let result_inputs = (revisions, self.operation, self.fill_rule);
        let inputs = Some(result_inputs);
        let fresh = self.derived.result_inputs == inputs;
        if !fresh && !allow_slow && self.derived.result_milliseconds > FRAME_BUDGET_MS {
            return false;
        }
        if !fresh {
            let (scene, operation, fill_rule, derived) = (
                &self.scene,
                self.operation,
                self.fill_rule,
                &mut self.derived,
            );
            derived.result_milliseconds = timed(&mut || {
                let outcome = operation::run(operation, scene, fill_rule);
                derived.result_fill = outcome
                    .as_ref()
                    .map(|o| Fill::of(&o.result))
                    .unwrap_or_default();
                derived.result_outline = outcome
                    .as_ref()
                    .map(|o| Outline::of(&o.result.0))
                    .unwrap_or_default();
                derived.outcome = Some(outcome);
            });
            derived.result_inputs = inputs;
        }
        let inputs = Some((result_inputs, self.scene.lines_revision()));
        if self.derived.cut_inputs == inputs {
            return up_to_date;
        }
        if !allow_slow && self.derived.cut_milliseconds > FRAME_BUDGET_MS {
            return false;
        }
        let (lines, derived) = (self.scene.lines(), &mut self.derived);
        derived.cut_milliseconds = timed(&mut || {
            derived.cut = match &derived.outcome {
                Some(Ok(outcome)) if !lines.is_empty() => {
                    Some(operation::cut(&outcome.result, lines))
                }
                _ => None,
            };
            derived.piece_fills = match &derived.cut {
                Some(Ok(cut)) => cut
                    .pieces
                    .iter()
                    .map(|piece| Fill::of(&MultiPolygon::new(vec![piece.clone()])))
                    .collect(),
                _ => Vec::new(),
            };
            derived.piece_outline = match &derived.cut {
                Some(Ok(cut)) => Outline::of(&cut.pieces),
                _ => Outline::default(),
            };
        });
        derived.cut_inputs = inputs;
        up_to_date
    }
}
