//! The sweep explorer's model: the trace of the sweep ([`polysweep::trace`]) on the playground's operands and a
//! position in it, moved by event, by x, to the next crossing, or played at a speed. The timeline is the events
//! of the sweep (§3, Fig. 5), then the rings the connection step closes (§5), one position each.
//!
//! S is kept only for a window of events around the position (the land has 120,000 events, and S after each of
//! them would not fit in memory): moving out of the window traces again with the window about the new position.
//! What the canvas shows up to the position — the subdivision points made so far, the edges selected so far — are
//! prefixes of lists in event order, found by binary search.

use polysweep::{
    trace_with_status_for, Error, Meeting, MultiPolygon, Operation, Options, Reason, Step,
    TraceEdge,
};
use std::ops::Range;
use std::sync::Arc;

/// Events S is kept for at a time.
const WINDOW: usize = 4096;

/// An edge the selection put in the result, the event whose processing selected it, and why.
#[derive(Clone, Copy, Debug)]
pub struct Selected {
    pub event: usize,
    pub edge: TraceEdge,
    pub reason: Reason,
}

/// A ring the connection step closed: its polygon, its index there (0 the exterior) and its points.
#[derive(Clone, Debug)]
pub struct ClosedRing {
    pub polygon: usize,
    pub ring: usize,
    pub points: Vec<[f64; 2]>,
}

pub struct Explorer {
    operation: Operation,
    options: Options,
    operands: [Arc<MultiPolygon>; 2],
    steps: Vec<Step>,
    /// Where each event is in `steps`, and where the events' steps end (the rings follow).
    events: Vec<usize>,
    events_end: usize,
    /// The events whose S is in `steps`.
    window: Range<usize>,
    selected: Vec<Selected>,
    /// Points where edges were split, and the event during which each was.
    subdivisions: Vec<(usize, [f64; 2])>,
    crossings: Vec<usize>,
    rings: Vec<ClosedRing>,
    /// 0 to `events.len() - 1`: after that event; beyond: after that many rings more were closed.
    position: usize,
    pub playing: bool,
    /// Positions a second while playing.
    pub speed: f64,
    /// Time played that has not made a whole step yet.
    played: f64,
}

impl Explorer {
    /// The trace of `operation` on `operands`, at its first event.
    pub fn new(
        operation: Operation,
        options: Options,
        operands: [Arc<MultiPolygon>; 2],
    ) -> Result<Explorer, Error> {
        let mut explorer = Explorer {
            operation,
            options,
            operands,
            steps: Vec::new(),
            events: Vec::new(),
            events_end: 0,
            window: 0..0,
            selected: Vec::new(),
            subdivisions: Vec::new(),
            crossings: Vec::new(),
            rings: Vec::new(),
            position: 0,
            playing: false,
            speed: 4.0,
            played: 0.0,
        };
        explorer.trace(0..WINDOW)?;
        Ok(explorer)
    }

    fn trace(&mut self, window: Range<usize>) -> Result<(), Error> {
        let [p, q] = &self.operands;
        self.steps = trace_with_status_for(self.operation, p, q, &self.options, window.clone())?;
        self.window = window;
        (self.events, self.selected, self.subdivisions) = (Vec::new(), Vec::new(), Vec::new());
        (self.crossings, self.rings) = (Vec::new(), Vec::new());
        for (i, step) in self.steps.iter().enumerate() {
            let event = self.events.len().saturating_sub(1);
            match step {
                Step::Event { .. } => self.events.push(i),
                Step::Subdivision { at, .. } => self.subdivisions.push((event, *at)),
                Step::Meeting {
                    meeting: Meeting::Crossing,
                    ..
                } => self.crossings.push(event),
                Step::Selection {
                    edge,
                    in_result: true,
                    reason,
                } => self.selected.push(Selected {
                    event,
                    edge: *edge,
                    reason: *reason,
                }),
                Step::Ring {
                    polygon,
                    ring,
                    points,
                } => self.rings.push(ClosedRing {
                    polygon: *polygon,
                    ring: *ring,
                    points: points.clone(),
                }),
                _ => {}
            }
        }
        self.events_end = (self.steps.iter())
            .position(|s| matches!(s, Step::Ring { .. }))
            .unwrap_or(self.steps.len());
        Ok(())
    }

    pub fn event_count(&self) -> usize {
        self.events.len()
    }

    /// Positions in all: the events, then the rings.
    pub fn len(&self) -> usize {
        self.events.len() + self.rings.len()
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    pub fn position(&self) -> usize {
        self.position
    }

    /// Moves to `position` (clamped), tracing again if S is not kept there.
    pub fn go_to(&mut self, position: usize) -> Result<(), Error> {
        self.position = position.min(self.len().saturating_sub(1));
        if self.position < self.events.len() && !self.window.contains(&self.position) {
            let start = self.position.saturating_sub(WINDOW / 2);
            self.trace(start..start + WINDOW)?;
        }
        Ok(())
    }

    pub fn step(&mut self, by: isize) -> Result<(), Error> {
        self.go_to(self.position.saturating_add_signed(by))
    }

    /// The first event after (or, backwards, the last before) the position at another x.
    pub fn step_x(&mut self, forward: bool) -> Result<(), Error> {
        let Some(x) = self.event().map(|(point, ..)| point[0]) else {
            return self.step(if forward { 1 } else { -1 });
        };
        let other_x = |k: &usize| self.event_at(*k).is_some_and(|(p, ..)| p[0] != x);
        let target = if forward {
            (self.position + 1..self.events.len()).find(other_x)
        } else {
            (0..self.position).rev().find(other_x)
        };
        self.go_to(target.unwrap_or(if forward { self.events.len() } else { 0 }))
    }

    /// The next event during which possibleInter found a crossing (the end if there is none).
    pub fn next_crossing(&mut self) -> Result<(), Error> {
        let after = self.crossings.partition_point(|&e| e <= self.position);
        let target = self.crossings.get(after).copied().unwrap_or(self.len());
        self.go_to(target)
    }

    /// Plays `seconds` more at the speed; stops at the end.
    pub fn play(&mut self, seconds: f64) -> Result<(), Error> {
        self.played += seconds * self.speed;
        let steps = self.played.floor();
        self.played -= steps;
        if steps >= 1.0 {
            self.step(steps as isize)?;
        }
        if self.position + 1 >= self.len() {
            self.playing = false;
        }
        Ok(())
    }

    fn event_at(&self, k: usize) -> Option<([f64; 2], bool, TraceEdge)> {
        match self.steps.get(*self.events.get(k)?)? {
            Step::Event { point, left, edge } => Some((*point, *left, *edge)),
            _ => None,
        }
    }

    /// The event at the position: its point, whether it is a left endpoint, and its edge. None once the rings
    /// are being closed.
    pub fn event(&self) -> Option<([f64; 2], bool, TraceEdge)> {
        self.event_at(self.position)
    }

    /// What happened while the event at the position was processed, S aside.
    pub fn substeps(&self) -> &[Step] {
        let Some(&start) = self.events.get(self.position) else {
            return &[];
        };
        let end = (self.events.get(self.position + 1).copied()).unwrap_or(self.events_end);
        let steps = &self.steps[start + 1..end];
        match steps.last() {
            Some(Step::Status(_)) => &steps[..steps.len() - 1],
            _ => steps,
        }
    }

    /// S after the event at the position, bottom to top (empty once the rings are being closed).
    pub fn status(&self) -> &[TraceEdge] {
        let Some(&start) = self.events.get(self.position) else {
            return &[];
        };
        let end = (self.events.get(self.position + 1).copied()).unwrap_or(self.events_end);
        match self.steps[start + 1..end].last() {
            Some(Step::Status(edges)) => edges,
            _ => &[],
        }
    }

    /// The edges selected into the result up to the position, in the order they were.
    pub fn selected(&self) -> &[Selected] {
        let done = self.selected.partition_point(|s| s.event <= self.position);
        &self.selected[..done]
    }

    /// The points edges were split at up to the position.
    pub fn subdivisions(&self) -> impl Iterator<Item = [f64; 2]> + '_ {
        let done = (self.subdivisions).partition_point(|&(e, _)| e <= self.position);
        self.subdivisions[..done].iter().map(|&(_, p)| p)
    }

    /// The rings closed up to the position.
    pub fn rings(&self) -> &[ClosedRing] {
        let closed = (self.position + 1).saturating_sub(self.events.len());
        &self.rings[..closed.min(self.rings.len())]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The paper's Fig. 7 case (tests/fixtures/fig7-sweep-line.json), through the preset.
    fn fig7() -> Explorer {
        let (p, q) = crate::presets::Preset::Fig7.operands();
        let operands = [p, q].map(Arc::new);
        Explorer::new(Operation::Intersection, Options::default(), operands).unwrap()
    }

    #[test]
    fn steps_by_event_by_x_and_to_crossings_and_closes_the_ring_at_the_end() {
        let mut explorer = fig7();
        // 14 edges after 4 crossings: 28 events; then the one ring of P ∩ Q.
        assert_eq!((explorer.event_count(), explorer.len()), (28, 29));
        assert_eq!(explorer.event().unwrap().0, [0.0, -1.0]);
        // Events 0 and 1 are at (0, −1), 2 and 3 at (0, 4): all at x = 0; the next x is the crossing's, 2.5.
        explorer.step_x(true).unwrap();
        assert_eq!(explorer.position(), 4);
        assert_eq!(explorer.event().unwrap().0, [2.5, 1.5]);
        explorer.step_x(false).unwrap();
        assert_eq!(explorer.position(), 3);
        assert_eq!(explorer.status().len(), 4, "d, e to i, a to i, c");
        assert_eq!(
            explorer.subdivisions().count(),
            2,
            "e and a, split at i by event 2"
        );
        // The crossing with c of e's second part is found when that part enters S, at i: the fourth event there.
        explorer.next_crossing().unwrap();
        assert_eq!(explorer.position(), 7);
        assert!(explorer.substeps().iter().any(|s| matches!(
            s,
            Step::Meeting {
                meeting: Meeting::Crossing,
                at: [5.0, 4.0],
                ..
            }
        )));
        assert!(
            explorer.selected().is_empty(),
            "nothing has left S inside Q yet"
        );
        // Event 8 is the right end of a's part from i, (4, 0): the first edge of P ∩ Q.
        explorer.step(1).unwrap();
        let selected = explorer.selected();
        assert_eq!(selected.len(), 1);
        assert_eq!(
            (selected[0].edge.left, selected[0].edge.right),
            ([2.5, 1.5], [4.0, 0.0])
        );
        assert_eq!(selected[0].reason, Reason::InsideOther);
        assert!(explorer.rings().is_empty());
        explorer.go_to(usize::MAX).unwrap();
        assert_eq!(explorer.position(), 28);
        assert!(explorer.event().is_none() && explorer.status().is_empty());
        assert_eq!(explorer.rings().len(), 1);
        assert_eq!(explorer.selected().len(), 5, "the five edges of P ∩ Q");
    }

    #[test]
    fn a_long_trace_keeps_s_only_near_the_position() {
        let (p, q) = crate::presets::Preset::Table1 { squares: 8 }.operands();
        let operands = [p, q].map(Arc::new);
        let mut explorer =
            Explorer::new(Operation::Intersection, Options::default(), operands).unwrap();
        assert!(explorer.event_count() > 100_000);
        let statuses = |e: &Explorer| {
            e.steps
                .iter()
                .filter(|s| matches!(s, Step::Status(_)))
                .count()
        };
        assert_eq!(statuses(&explorer), WINDOW);
        explorer.go_to(90_000).unwrap();
        assert!(
            !explorer.status().is_empty(),
            "S at the far position, traced again about it"
        );
        assert_eq!(statuses(&explorer), WINDOW);
        // Between events of one x, S changes by one edge at most (an insertion or a removal), or by two where an
        // edge is split and its part put back in Q.
        let before = explorer.status().len();
        explorer.step(1).unwrap();
        assert!(explorer.status().len().abs_diff(before) <= 2);
    }
}
