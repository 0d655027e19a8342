//! The arrangement of all the edges (not in the paper): the sweep of Fig. 5 keeping every edge, with the input
//! segments that lie on each. Lines and layers (see [`crate::lines`], [`crate::layers`]) read their results from
//! it, where the Boolean operations select edges by the operands' winding numbers alone.
//!
//! The sweep is the paper's, with one more thing noted: where §7.2 merges overlapping edges into one carrying both
//! windings, the merged edge also carries the other's input segments (`Sources`), and a split's fragments inherit
//! them. Every edge that leaves S is recorded as a [`Fragment`]: its exact vertices, its winding numbers and
//! coverage, its input segments and the fragment just below it when it entered S (Fig. 9's edge below, the one
//! §5 nests holes by). From those, what lies on either side of every fragment is known without a second look at
//! the geometry: the region above a fragment is the region above the one below it, changed by what lies on it.
//!
//! Its output is rounded as the Boolean operations' is, through [`crate::connect`]; the snap rounding of
//! [`crate::overlay`], which sweeps a result again as one polygon set, is not applied (see docs/robustness.md).

use crate::connect::connect_classes;
use crate::edges::{EventId, InputEdge, ResultEdge, NONE};
use crate::error::Error;
use crate::events::MAX_EVENTS;
use crate::exact::{Exact, SweepPoint};
use crate::geometry::Polygon;
use crate::options::Options;
use crate::select::{Flags, Selection};
use crate::sweep::Sweep;
use crate::trace::Silent;
use crate::workspace::{self, room};
use std::collections::HashMap;

/// What an arrangement sweep notes beside the events: the input segments on each edge, and the fragments.
pub(crate) struct Sources {
    /// Per event (read for left events): its list in `lists` of the segments merged into its edge, or `NONE`.
    of_event: Vec<u32>,
    lists: Vec<Vec<u32>>,
    fragments: Vec<Fragment>,
}

/// An edge of the arrangement: a piece of one or more input segments that meets no other edge but at its ends.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Fragment {
    /// Its exact vertices (indices into the sweep's vertices), left then right in sweep order.
    pub ends: [u32; 2],
    /// The input segment whose line it lies on.
    pub segment: u32,
    /// The other input segments on it (merged into it, §7.2), as a list of [`Arrangement::segments`], or `NONE`.
    merged: u32,
    /// The sum of its segments' windings per operand.
    pub winding: [i32; 2],
    /// The operands' winding numbers above it (right of it when vertical), as Fig. 9 counts them.
    coverage_above: [i32; 2],
    /// The closest non-vertical fragment below its left end when it entered S, or `NONE`.
    pub below: u32,
}

impl Sources {
    fn new(events: usize) -> Self {
        Sources {
            of_event: vec![NONE; events],
            lists: Vec::new(),
            fragments: Vec::new(),
        }
    }

    /// Room for the events of a split (see `Sweep::room_for_events`).
    pub fn room(&mut self, events: usize) -> bool {
        room(&mut self.of_event, events) && room(&mut self.fragments, events)
    }

    /// Left event `edge` was split (Fig. 6): its two new events, just pushed, carry what it carries.
    pub fn split(&mut self, edge: EventId) {
        let list = self.of_event[edge as usize];
        self.of_event.extend([list, list]);
    }

    /// Left event `merged` was merged into `keep` (§7.2); `segments` are their input segments.
    pub fn merge(&mut self, keep: EventId, merged: EventId, segments: [u32; 2]) {
        let mut list = self.list(keep).to_vec();
        list.push(segments[1]);
        list.extend_from_slice(self.list(merged));
        self.of_event[keep as usize] = self.lists.len() as u32;
        self.lists.push(list);
    }

    fn list(&self, e: EventId) -> &[u32] {
        match self.of_event[e as usize] {
            NONE => &[],
            l => &self.lists[l as usize],
        }
    }

    /// Left event `l` leaves S, between exact vertices `ends`: it becomes a fragment, whose index is returned.
    pub fn record(
        &mut self,
        l: EventId,
        ends: [u32; 2],
        segment: u32,
        winding: [i32; 2],
        flags: &Flags,
    ) -> u32 {
        self.fragments.push(Fragment {
            ends,
            segment,
            merged: self.of_event[l as usize],
            winding,
            coverage_above: flags.coverage_above,
            below: flags.result_below,
        });
        (self.fragments.len() - 1) as u32
    }
}

/// The swept arrangement of some input edges.
pub(crate) struct Arrangement {
    pub input: Vec<InputEdge>,
    pub exact: Exact,
    /// The exact vertices, in sweep order.
    pub vertices: Vec<SweepPoint>,
    pub fragments: Vec<Fragment>,
    lists: Vec<Vec<u32>>,
}

/// A side of a fragment as a half-edge: `2f` runs along fragment `f` in sweep order (left to right, or up), with the
/// region above it (left of it, when vertical) on its left; `2f + 1` runs back, with the other side on its left.
pub(crate) type HalfEdge = u32;

impl Arrangement {
    /// Sweeps `input`, whose coordinates have magnitude `magnitude` at most.
    pub fn sweep(input: Vec<InputEdge>, magnitude: f64, options: &Options) -> Result<Self, Error> {
        if 2 * input.len() > MAX_EVENTS {
            return Err(Error::TooLarge { limit: MAX_EVENTS });
        }
        let mut shortcuts = options.shortcuts;
        // (Merged when the events are made, identical edges would not carry each other's segments.)
        shortcuts.merge_identical_edges = false;
        workspace::with(shortcuts.keep_working_memory, |workspace| {
            let mut sweep = Sweep::new(
                &input,
                Selection::Arrangement,
                f64::INFINITY,
                magnitude,
                shortcuts,
                workspace,
                Silent,
            );
            sweep.sources = Some(Sources::new(sweep.events.len()));
            sweep.run()?;
            let sources = sweep.sources.take().expect("set above");
            let vertices = std::mem::take(&mut sweep.vertices);
            // The fragment below each, by its left event until now.
            let events = &sweep.events;
            let mut fragments = sources.fragments;
            for f in &mut fragments {
                if f.below != NONE {
                    f.below = events[f.below as usize].result_edge();
                }
            }
            let exact = std::mem::take(&mut sweep.exact);
            sweep.give_back(workspace);
            Ok(Arrangement {
                input,
                exact,
                vertices,
                fragments,
                lists: sources.lists,
            })
        })
    }

    /// The input segments on fragment `f`.
    pub fn segments(&self, f: u32) -> impl Iterator<Item = u32> + '_ {
        let fragment = &self.fragments[f as usize];
        let merged: &[u32] = match fragment.merged {
            NONE => &[],
            l => &self.lists[l as usize],
        };
        std::iter::once(fragment.segment).chain(merged.iter().copied())
    }

    pub fn is_vertical(&self, f: u32) -> bool {
        self.input[self.fragments[f as usize].segment as usize]
            .line
            .is_vertical()
    }

    /// The operands' winding numbers on the left of each half-edge of fragment `f`: `[2f, 2f + 1]`.
    pub fn coverage(&self, f: u32) -> [[i32; 2]; 2] {
        let fragment = &self.fragments[f as usize];
        let (w, c) = (fragment.winding, fragment.coverage_above);
        // Fig. 9: above a fragment is below it plus its winding; a vertical one (§7.1) has the coverage below on
        // its right and that plus its winding on its left.
        let (under, over) = if self.is_vertical(f) {
            (c, [c[0] + w[0], c[1] + w[1]])
        } else {
            ([c[0] - w[0], c[1] - w[1]], c)
        };
        [over, under]
    }

    /// For each fragment, the sets of items inside on the left of its two half-edges (as ids into the returned
    /// sets). Each input segment is part of one item's boundary: `item_of(segment)` gives the item and its winding
    /// (+1 when crossing the segment upwards, or leftwards when vertical, enters the item's ring). The region above
    /// a fragment has the winding numbers of the region above the fragment below it plus those of the fragment's
    /// segments, and the region below everything none; an item is inside where `inside` says its winding number is.
    pub fn item_sets(
        &self,
        item_of: impl Fn(u32) -> (u32, i32),
        inside: impl Fn(i32) -> bool,
    ) -> (Vec<[u32; 2]>, Vec<Vec<u32>>) {
        // The winding numbers of a region, as (item, number) for the numbers that are not 0, sorted; interned.
        let mut windings: Vec<Vec<(u32, i32)>> = vec![Vec::new()];
        let mut winding_ids: HashMap<Vec<(u32, i32)>, u32> = HashMap::from([(Vec::new(), 0)]);
        let mut sides = vec![[NONE; 2]; self.fragments.len()];
        let mut chain = Vec::new();
        for start in 0..self.fragments.len() as u32 {
            // The fragments below `start` not yet known, down to one that is (or to the bottom), then back up.
            let mut f = start;
            while f != NONE && sides[f as usize][0] == NONE {
                chain.push(f);
                f = self.fragments[f as usize].below;
            }
            while let Some(f) = chain.pop() {
                // The region just above the fragment below (never vertical, see `Fragment::below`).
                let under = match self.fragments[f as usize].below {
                    NONE => 0,
                    b => sides[b as usize][0],
                };
                let mut numbers = windings[under as usize].clone();
                for s in self.segments(f) {
                    let (item, winding) = item_of(s);
                    match numbers.binary_search_by_key(&item, |&(i, _)| i) {
                        Ok(i) if numbers[i].1 + winding == 0 => {
                            numbers.remove(i);
                        }
                        Ok(i) => numbers[i].1 += winding,
                        Err(i) => numbers.insert(i, (item, winding)),
                    }
                }
                let over = *winding_ids.entry(numbers).or_insert_with_key(|numbers| {
                    windings.push(numbers.clone());
                    (windings.len() - 1) as u32
                });
                sides[f as usize] = [over, under];
            }
        }
        // The items inside, for each set of winding numbers, interned again: regions whose numbers differ can hold the
        // same items.
        let mut sets: Vec<Vec<u32>> = Vec::new();
        let mut set_ids: HashMap<Vec<u32>, u32> = HashMap::new();
        let set_of: Vec<u32> = (windings.iter())
            .map(|numbers| {
                let set: Vec<u32> = (numbers.iter())
                    .filter(|&&(_, w)| inside(w))
                    .map(|&(item, _)| item)
                    .collect();
                *set_ids.entry(set).or_insert_with_key(|set| {
                    sets.push(set.clone());
                    (sets.len() - 1) as u32
                })
            })
            .collect();
        let sides = (sides.iter())
            .map(|side| side.map(|w| set_of[w as usize]))
            .collect();
        (sides, sets)
    }

    /// The polygons bounded by the half-edges given a class by `class_of` (`NONE`: none), each polygon with its
    /// class: a half-edge has its class on its left, and the half-edges of one class are connected into the
    /// polygons of that class by §5's walk (so both half-edges of a fragment, with the same class on both sides,
    /// are cut off as a ring of no area, and left out). A hole belongs to the closest polygon of its class below it.
    pub fn polygons(&self, class_of: impl Fn(HalfEdge) -> u32) -> Vec<(u32, Polygon)> {
        let half_edges = 2 * self.fragments.len() as u32;
        let classes: Vec<u32> = (0..half_edges).map(&class_of).collect();
        let mut output = vec![NONE; half_edges as usize];
        let mut edges = Vec::new();
        let mut class = Vec::new();
        for h in 0..half_edges {
            if classes[h as usize] == NONE {
                continue;
            }
            let fragment = &self.fragments[h as usize / 2];
            let forward = h % 2 == 0;
            let [from, to] = if forward {
                fragment.ends
            } else {
                [fragment.ends[1], fragment.ends[0]]
            };
            output[h as usize] = edges.len() as u32;
            edges.push(ResultEdge {
                from,
                to,
                segment: fragment.segment,
                forward,
                below: h,
            });
            class.push(classes[h as usize]);
        }
        // The closest half-edge below of the same class, as the result edge it is.
        let below = |h: u32| {
            let wanted = classes[h as usize];
            let mut g = self.fragments[h as usize / 2].below;
            while g != NONE {
                for side in [2 * g, 2 * g + 1] {
                    if classes[side as usize] == wanted {
                        return output[side as usize];
                    }
                }
                g = self.fragments[g as usize].below;
            }
            NONE
        };
        let (polygons, polygon_class, _) = connect_classes(
            &self.exact,
            &self.input,
            &self.vertices,
            &mut edges,
            below,
            &class,
            &mut Default::default(),
        );
        polygon_class.into_iter().zip(polygons.0).collect()
    }

    /// The output vertex of exact vertex `v`: rounded to the nearest floats.
    pub fn point(&self, v: u32) -> crate::Point {
        let [x, y] = self.vertices[v as usize].approx;
        crate::Point::new(x, y)
    }
}
