//! What the app derives from the operands and lines — the operands' fills, and the result with its fill and the
//! lines against it — and when: each frame asks the background (background.rs) for whatever is out of date and
//! shows the newest it has received meanwhile, so that the canvas keeps drawing while a result is computed.

use super::Playground;
use crate::background::{Background, Delivery, Request};
use crate::fill::{Fill, Outline};
use crate::job::{Computed, Derivation, Job, SLOTS};
use crate::operation::{Cut, Op, Outcome};
use crate::scene::Operand;
use eframe::egui;
use polysweep::{Error, FillRule, MultiPolygon};
use std::sync::Arc;

/// The inputs a slot's job is computed from: an operand's revision and the fill rule; or both revisions, the lines'
/// revision, the operation and the fill rule.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Inputs {
    Region(u64, FillRule),
    Result([u64; 2], u64, Op, FillRule),
}

/// What is derived from the operands, and what has been asked for.
#[derive(Default)]
pub(super) struct Derived {
    /// The operands' rings as drawn, and the revision they are of: kept up to date on every frame (cheap).
    pub(super) operand_outlines: [(Option<u64>, Outline); 2],
    pub(super) region_fills: [Fill; 2],
    /// The result shown, once one has been computed.
    pub(super) computed: Option<Computed>,
    /// Per slot, the inputs and request number of what is shown.
    shown: [Option<(Inputs, u64)>; SLOTS],
    /// Requests made and not yet delivered (or superseded), with their inputs.
    asked: Vec<(u64, usize, Inputs)>,
    last_request: u64,
    /// Started on the first frame (it needs the egui context to wake the UI).
    background: Option<Background>,
    /// The operands as jobs last saw them, with their revisions: a job of an unchanged operand shares it.
    snapshots: [Option<(u64, Arc<MultiPolygon>)>; 2],
    /// Results (of the operation, not the operands' fills) received from the background.
    results_received: u64,
    /// Frames drawn, and of them those drawn while a result was being computed.
    pub(super) frames: u64,
    pub(super) frames_while_pending: u64,
}

impl Playground {
    /// The result of the current operation, computing it here and now if it is out of date.
    pub fn outcome(&mut self) -> &Result<Outcome, Error> {
        self.settle();
        &self.derived.computed.as_ref().expect("settled").outcome
    }

    /// The drawn lines against the current result, computing them here and now if they are out of date; `None`
    /// without lines or when the operation failed.
    pub fn cut(&mut self) -> Option<&Result<Cut, Error>> {
        self.settle();
        self.derived
            .computed
            .as_ref()
            .expect("settled")
            .cut
            .as_ref()
    }

    /// Whether something shown is out of date and being computed.
    pub fn pending(&self) -> bool {
        (0..SLOTS).any(|slot| self.derived.shown[slot].map(|(i, _)| i) != Some(self.inputs(slot)))
    }

    /// Frames drawn so far, and those of them drawn while a result was pending.
    pub fn frames(&self) -> (u64, u64) {
        (self.derived.frames, self.derived.frames_while_pending)
    }

    /// How many results of the operation were received from the background (the thread, or the browser's
    /// worker) and shown.
    pub fn results_received(&self) -> u64 {
        self.derived.results_received
    }

    /// Whether results are computed away from the UI thread (not before the first frame, nor in a browser without
    /// a working worker).
    pub fn computes_off_thread(&self) -> bool {
        (self.derived.background.as_ref()).is_some_and(Background::off_thread)
    }

    /// The result shown now, which may be out of date while [`Playground::pending`].
    pub fn shown(&self) -> Option<&Computed> {
        self.derived.computed.as_ref()
    }

    /// Brings everything derived up to date on this thread, waiting for nothing.
    pub fn settle(&mut self) {
        self.refresh_outlines();
        self.receive();
        for slot in 0..SLOTS {
            let inputs = self.inputs(slot);
            if self.derived.shown[slot].map(|(i, _)| i) != Some(inputs) {
                let sequence = self.next_request();
                let derivation = self.job(slot).run();
                self.show_derivation(slot, (inputs, sequence), derivation);
            }
        }
    }

    /// One frame's part: asks the background for what is out of date (newest request wins) and takes what it has
    /// delivered. Returns whether something is still pending.
    pub(super) fn derive_in_background(&mut self, ctx: &egui::Context) -> bool {
        self.refresh_outlines();
        if self.derived.background.is_none() {
            let ctx = ctx.clone();
            let wake = move || ctx.request_repaint();
            #[cfg(target_arch = "wasm32")]
            let background = Background::new(self.worker_url.as_deref(), wake);
            #[cfg(not(target_arch = "wasm32"))]
            let background = Background::new(wake);
            self.derived.background = Some(background);
        }
        self.receive();
        for slot in 0..SLOTS {
            let inputs = self.inputs(slot);
            let shown = self.derived.shown[slot].map(|(i, _)| i) == Some(inputs);
            let asked = (self.derived.asked.iter()).any(|&(_, s, i)| s == slot && i == inputs);
            if !shown && !asked {
                let sequence = self.next_request();
                self.derived.asked.push((sequence, slot, inputs));
                let job = self.job(slot);
                let background = self.derived.background.as_mut().expect("started above");
                background.submit(Request { sequence, job });
            }
        }
        let pending = self.pending();
        self.derived.frames += 1;
        self.derived.frames_while_pending += u64::from(pending);
        pending
    }

    fn refresh_outlines(&mut self) {
        for which in [Operand::Subject, Operand::Clipping] {
            let revision = Some(self.scene.revision(which));
            let (shown, outline) = &mut self.derived.operand_outlines[which.index()];
            if *shown != revision {
                *shown = revision;
                *outline = Outline::of(&self.scene.operand(which).0);
            }
        }
    }

    /// Shows what the background delivered, unless something newer of its slot is shown already.
    fn receive(&mut self) {
        let Some(background) = &mut self.derived.background else {
            return;
        };
        for Delivery {
            slot,
            sequence,
            derivation,
        } in background.take_deliveries()
        {
            let asked = &mut self.derived.asked;
            let inputs = (asked.iter())
                .find(|&&(s, _, _)| s == sequence)
                .map(|&(_, _, i)| i);
            // This request and older ones of its slot (superseded before they started) are done with.
            asked.retain(|&(s, sl, _)| sl != slot || s > sequence);
            let newer_shown = self.derived.shown[slot].is_some_and(|(_, s)| s > sequence);
            if let (Some(inputs), false) = (inputs, newer_shown) {
                self.derived.results_received += u64::from(slot == 2);
                self.show_derivation(slot, (inputs, sequence), derivation);
            }
        }
    }

    fn show_derivation(&mut self, slot: usize, shown: (Inputs, u64), derivation: Derivation) {
        match derivation {
            Derivation::Region(fill) => self.derived.region_fills[slot] = fill,
            Derivation::Result(computed) => self.derived.computed = Some(*computed),
        }
        self.derived.shown[slot] = Some(shown);
    }

    fn next_request(&mut self) -> u64 {
        self.derived.last_request += 1;
        self.derived.last_request
    }

    fn inputs(&self, slot: usize) -> Inputs {
        let revision = |which| self.scene.revision(which);
        match slot {
            0 => Inputs::Region(revision(Operand::Subject), self.fill_rule),
            1 => Inputs::Region(revision(Operand::Clipping), self.fill_rule),
            _ => Inputs::Result(
                [Operand::Subject, Operand::Clipping].map(revision),
                self.scene.lines_revision(),
                self.operation,
                self.fill_rule,
            ),
        }
    }

    /// The job of a slot, on its inputs as they are now.
    fn job(&mut self, slot: usize) -> Job {
        let mut operand = |which: Operand| {
            let revision = self.scene.revision(which);
            let snapshot = &mut self.derived.snapshots[which.index()];
            match snapshot {
                Some((r, operand)) if *r == revision => operand.clone(),
                _ => {
                    let operand = Arc::new(self.scene.operand(which).clone());
                    *snapshot = Some((revision, operand.clone()));
                    operand
                }
            }
        };
        match slot {
            0 | 1 => {
                let which = [Operand::Subject, Operand::Clipping][slot];
                Job::Region {
                    which,
                    operand: operand(which),
                    fill_rule: self.fill_rule,
                }
            }
            _ => Job::Result {
                op: self.operation,
                fill_rule: self.fill_rule,
                operands: [Operand::Subject, Operand::Clipping].map(operand),
                lines: self.scene.lines().to_vec(),
            },
        }
    }
}
