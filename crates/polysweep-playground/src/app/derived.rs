//! What the app derives from the operands — their fills, the result and its fill — and when it is recomputed: only
//! when its inputs change, and mid-drag only what fits in a frame.

use super::Playground;
use crate::fill::Fill;
use crate::operation::{self, Op, Outcome};
use crate::scene::Operand;
use polysweep::{Error, FillRule};
use web_time::Instant;

/// A computation slower than this (in milliseconds) is not repeated on every move of a drag.
const FRAME_BUDGET_MS: f64 = 12.0;

/// What is derived from the operands, recomputed only when its inputs change.
#[derive(Default)]
pub(super) struct Derived {
    /// The operand revision and fill rule each region fill was computed from.
    pub(super) region_inputs: [Option<(u64, FillRule)>; 2],
    pub(super) region_fills: [Fill; 2],
    /// The operand revisions, operation and fill rule the result was computed from.
    pub(super) result_inputs: Option<([u64; 2], Op, FillRule)>,
    pub(super) outcome: Option<Result<Outcome, Error>>,
    pub(super) result_fill: Fill,
    /// How long the last computation of each took (sweep and triangulation), to decide what can run mid-drag.
    pub(super) region_milliseconds: [f64; 2],
    pub(super) result_milliseconds: f64,
}

impl Playground {
    /// The result of the current operation, computing it if the operands, operation or fill rule changed.
    pub fn outcome(&mut self) -> &Result<Outcome, Error> {
        self.refresh(true);
        self.derived.outcome.as_ref().expect("refreshed above")
    }

    /// Brings the fills and the result up to date with the operands. With `allow_slow` false (mid-drag), whatever
    /// took longer than a frame last time is left as it is, so that dragging stays smooth on large data; the canvas
    /// refreshes it when the pointer rests or is released. Returns whether everything is up to date.
    pub(super) fn refresh(&mut self, allow_slow: bool) -> bool {
        let timed = |work: &mut dyn FnMut()| {
            let start = Instant::now();
            work();
            start.elapsed().as_secs_f64() * 1e3
        };
        let mut up_to_date = true;
        for which in [Operand::Subject, Operand::Clipping] {
            let i = which.index();
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
        let inputs = Some((revisions, self.operation, self.fill_rule));
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
                derived.outcome = Some(outcome);
            });
            derived.result_inputs = inputs;
        }
        up_to_date
    }
}
