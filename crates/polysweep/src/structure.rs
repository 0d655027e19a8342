//! The structural reading of an operand ([`FillRule::Structure`]: polygon-clipping's and GEOS's `make_valid(…,
//! method='structure')`), and the check that lets valid input skip it. Not in the paper.
//!
//! The reading itself ([`read_by_structure`]) is a sweep per ring, one per polygon with holes and one over all the
//! polygons: about three times the work of the operation. On valid input it gives what the even-odd rule (§7.3)
//! reads, so an operation under the structural reading is first swept under even-odd, watched: the result stands
//! when the sweep saw each operand read alike by both rules, and only otherwise is the operand read by its
//! structure and the operation swept again.
//!
//! Both readings agree on the rings of an operand when they are simple and pairwise disjoint and nest as a valid
//! polygon set: each hole directly inside its own polygon's exterior, each exterior directly inside nothing or a
//! hole. (Then a point lies inside the rings of an odd number of them exactly where the polygon whose ring is
//! innermost around it is an exterior, that is where it lies in one polygon's exterior and none of its holes;
//! orientation does not matter to either rule.) The sweep sees both conditions on the way:
//! - **Contacts**: two rings of an operand, or one ring with itself, meet where the operand has more than two
//!   endpoints at a point (found by the initial sort, see [`crate::events::initial_events`]), or where
//!   possibleInter (Fig. 6, §7.2) finds two of its edges crossing, overlapping or touching inside one of them.
//! - **Nesting**: when the sweep reaches a ring at its lowest-leftmost vertex, the nearest edge of the same operand
//!   below that point in S, of ring `T`, tells the ring directly around the new one: `T` itself if `T`'s inside is
//!   above that edge, else the ring around `T`, found when the sweep reached `T`. (Rings that do not touch keep
//!   their order in S, so this is the innermost ring around the point.)
//!
//! Where the sweep stops early (past the end of the result), what it did not see cannot change the result. Which
//! polygons are swept is decided under even-odd; the pruning stays exact for the structural reading too (see
//! [`crate::prune`]): polygons left out by boxes, or because they lie inside or outside the other operand, change
//! neither reading where the result can be. Only where clipping polygons are judged by the subject's winding number
//! must that number be the structural one, so an intersection then sweeps, and so watches, the whole subject.

use crate::edges::{EventId, InputEdge, Operand, NONE};
use crate::error::Error;
use crate::geometry::MultiPolygon;
use crate::input;
use crate::options::Options;
use crate::overlay::sweep;
use crate::select::{FillRule, Operation, Selection};
use crate::sweep::Sweep;
use crate::trace::Observer;
use crate::workspace::{self, Workspace};

/// What the sweep watches for the structural reading: the rings swept, and whether each operand is read alike by
/// the even-odd rule and by its structure, as far as the sweep has seen.
pub(crate) struct Watch {
    rings: Vec<Ring>,
    /// The ring of each input edge (an index into `rings`).
    ring_of_edge: Vec<u32>,
    /// Per operand: no contact and no misnested ring seen yet.
    pub alike: [bool; 2],
    /// How many more edges of the other operand the rings' first edges may look past, down S, for the nearest edge
    /// of their own: as many as there are edges in all. Each look costs up to the size of S, so many rings far above
    /// the nearest edge of their operand (a row of squares over a stack of bars) could cost the product of the two;
    /// past the budget, the sweep looks no further and the operands are read by their structure instead.
    steps_left: usize,
}

#[derive(Clone, Copy)]
struct Ring {
    polygon: u32,
    hole: bool,
    /// The winding of the ring's first edge in sweep order, the lower of the two at its lowest-leftmost vertex: the
    /// ring's inside is above an edge of the ring whose winding is this. 0 until the sweep reaches the ring.
    inside_above: i32,
    /// The ring directly around this one (an index into the rings), or `NONE`.
    around: u32,
}

impl Watch {
    pub fn new() -> Self {
        Watch {
            rings: Vec::new(),
            ring_of_edge: Vec::new(),
            alike: [true; 2],
            steps_left: 0,
        }
    }

    /// Has the sweep reached the ring of input edge `segment` yet?
    pub fn reached(&self, segment: u32) -> bool {
        self.rings[self.ring_of(segment)].inside_above != 0
    }

    /// The ring of input edge `segment`.
    fn ring_of(&self, segment: u32) -> usize {
        self.ring_of_edge[segment as usize] as usize
    }
}

/// [`input::add_edges`], noting each ring and the ring of each edge in `watch`.
pub(crate) fn add_watched_edges(
    edges: &mut Vec<InputEdge>,
    polygons: &MultiPolygon,
    operand: Operand,
    which: impl IntoIterator<Item = usize>,
    watch: &mut Watch,
) {
    edges.reserve(polygons.vertex_count());
    for p in which {
        let polygon = &polygons.0[p];
        for (r, ring) in polygon.rings().enumerate() {
            let first_edge = edges.len();
            input::add_ring_edges(edges, ring, operand);
            if edges.len() == first_edge {
                continue;
            }
            watch.steps_left += edges.len() - first_edge;
            watch
                .ring_of_edge
                .resize(edges.len(), watch.rings.len() as u32);
            watch.rings.push(Ring {
                polygon: p as u32,
                hole: r > 0,
                inside_above: 0,
                around: NONE,
            });
        }
    }
}

impl<O: Observer> Sweep<'_, O> {
    /// The edges at nodes `a` and `b` of S meet other than at a common endpoint: that is a contact for each
    /// operand both of them carry (an edge carries those its winding counts, overlapping edges merged into it
    /// included).
    pub(crate) fn watch_contact(&mut self, a: u32, b: u32) {
        let Some(watch) = self.watch.as_deref_mut() else {
            return;
        };
        let winding = |n: u32| self.events[self.status.event(n) as usize].winding;
        let (wa, wb) = (winding(a), winding(b));
        for k in 0..2 {
            if wa[k] != 0 && wb[k] != 0 {
                watch.alike[k] = false;
            }
        }
    }

    /// Left event `e`, at `node` in S, is the first of its ring that the sweep reaches: at the ring's lowest-leftmost
    /// vertex (no edge of the ring starts before it), and the lower of the two edges there (§4 orders them so, and
    /// the in-place step takes them in that order). Finds the ring directly around it and checks that it nests as a
    /// valid polygon set's ring does.
    #[inline(never)]
    pub(crate) fn watch_ring_start(&mut self, e: EventId, node: u32) {
        let segment = self.event(e).segment();
        let input = self.edges[segment as usize];
        let k = input.operand as usize;
        let (around, steps) = self.ring_around(node, k);
        let Some(watch) = self.watch.as_deref_mut() else {
            return;
        };
        let ring = watch.ring_of(segment);
        watch.steps_left -= steps;
        watch.rings[ring].inside_above = input.winding;
        let Some(around) = around else {
            watch.alike[k] = false;
            return;
        };
        watch.rings[ring].around = around;
        let this = watch.rings[ring];
        let nests = if this.hole {
            around != NONE && {
                let shell = &watch.rings[around as usize];
                !shell.hole && shell.polygon == this.polygon
            }
        } else {
            around == NONE || watch.rings[around as usize].hole
        };
        watch.alike[k] &= nests;
    }

    /// The ring of operand `k` directly around the point where the edge at `node` starts (`NONE`: none), from the
    /// nearest edge of that operand below it in S, and the edges of the other operand looked past; `None` where
    /// that cannot be told within the budget (see [`Watch::steps_left`]) or the edge is not one of that operand's
    /// rings (merged into another's, §7.2).
    fn ring_around(&self, node: u32, k: usize) -> (Option<u32>, usize) {
        let Some(watch) = self.watch.as_deref() else {
            return (None, 0);
        };
        let mut below = self.status.prev(node);
        let mut steps = 0;
        while below != NONE && self.events[self.status.event(below) as usize].winding[k] == 0 {
            if steps == watch.steps_left {
                return (None, steps);
            }
            steps += 1;
            below = self.status.prev(below);
        }
        if below == NONE {
            return (Some(NONE), steps);
        }
        let edge = self.status.key(below);
        let input = &self.edges[edge.segment as usize];
        if input.operand as usize != k || edge.line.is_vertical() {
            return (None, steps); // (a vertical edge below the point would end at or pass through it: a contact)
        }
        let t = watch.ring_of(edge.segment);
        let ring = &watch.rings[t];
        let around = if input.winding == ring.inside_above {
            t as u32
        } else {
            ring.around
        };
        (Some(around), steps)
    }
}

/// `operand` as a valid polygon set, read by its structure: by one watched sweep where that finds the even-odd rule
/// reads it alike (unless the shortcut is off), else by [`read_by_structure`]; with the number of sweeps made.
/// `magnitude` bounds its coordinates.
pub(crate) fn valid_by_structure(
    operand: &MultiPolygon,
    magnitude: f64,
    options: &Options,
    workspace: &mut Workspace,
) -> Result<(MultiPolygon, usize), Error> {
    let mut sweeps = 0;
    if options.shortcuts.watch_structure {
        sweeps += 1;
        let mut watch = Watch::new();
        let mut edges = workspace::take(&mut workspace.edges);
        add_watched_edges(&mut edges, operand, 0, 0..operand.0.len(), &mut watch);
        let union = Selection::Pair {
            operation: Operation::Union,
            fill_rule: FillRule::EvenOdd,
        };
        let (valid, _) = sweep(
            edges,
            union,
            f64::INFINITY,
            magnitude,
            options,
            workspace,
            Some(&mut watch),
        )?;
        if watch.alike[0] {
            return Ok((valid, sweeps));
        }
    }
    let (valid, more) = read_by_structure(operand, magnitude, options, workspace)?;
    Ok((valid, sweeps + more))
}

/// `operand` read by its structure ([`FillRule::Structure`]), as a valid polygon set: each ring's own region by the
/// non-zero rule of that ring alone, each polygon its exterior's region less the union of its holes' regions, the
/// operand the union of its polygons. A sweep per ring and per polygon with holes, then one over all polygons, each
/// exact up to the rounding of its own output (as `overlay_many`'s normalisation is); with the number of sweeps.
/// `magnitude` bounds its coordinates.
pub(crate) fn read_by_structure(
    operand: &MultiPolygon,
    magnitude: f64,
    options: &Options,
    workspace: &mut Workspace,
) -> Result<(MultiPolygon, usize), Error> {
    let sweeps = std::cell::Cell::new(0);
    let sweep_edges = |add: &dyn Fn(&mut Vec<InputEdge>), selection, workspace: &mut Workspace| {
        sweeps.set(sweeps.get() + 1);
        let mut edges = workspace::take(&mut workspace.edges);
        add(&mut edges);
        let swept = sweep(
            edges,
            selection,
            f64::INFINITY,
            magnitude,
            options,
            workspace,
            None,
        )?;
        Ok::<_, Error>(swept.0)
    };
    let alone = Selection::Pair {
        operation: Operation::Union,
        fill_rule: FillRule::NonZero,
    };
    let less_holes = Selection::Count {
        operation: Operation::Difference,
        operands: 1,
    };
    let mut regions = Vec::with_capacity(operand.0.len());
    for polygon in &operand.0 {
        let exterior = &polygon.exterior;
        let outer = sweep_edges(
            &|edges| input::add_ring_edges(edges, exterior, 0),
            alone,
            workspace,
        )?;
        if polygon.holes.is_empty() || outer.0.is_empty() {
            regions.push(outer);
            continue;
        }
        let mut holes = Vec::with_capacity(polygon.holes.len());
        for hole in &polygon.holes {
            holes.push(sweep_edges(
                &|edges| input::add_ring_edges(edges, hole, 0),
                alone,
                workspace,
            )?);
        }
        let add = |edges: &mut Vec<InputEdge>| {
            input::add_edges(edges, &outer, 0, 0..outer.0.len());
            for hole in &holes {
                input::add_edges(edges, hole, 1, 0..hole.0.len());
            }
        };
        regions.push(sweep_edges(&add, less_holes, workspace)?);
    }
    let union = Selection::Count {
        operation: Operation::Union,
        operands: regions.len() as i32,
    };
    let valid = sweep_edges(
        &|edges| {
            regions
                .iter()
                .for_each(|r| input::add_edges(edges, r, 0, 0..r.0.len()))
        },
        union,
        workspace,
    )?;
    Ok((valid, sweeps.get()))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::overlay::overlay_checked;

    /// A polygon as GeoJSON Polygon coordinates, and a polygon set as MultiPolygon coordinates.
    type Polygon = Vec<Vec<[f64; 2]>>;
    type Coordinates = Vec<Polygon>;

    fn square(x: f64, y: f64, side: f64) -> Vec<[f64; 2]> {
        vec![[x, y], [x + side, y], [x + side, y + side], [x, y + side]]
    }

    fn reversed(mut ring: Vec<[f64; 2]>) -> Vec<[f64; 2]> {
        ring.reverse();
        ring
    }

    /// Whether the watched even-odd sweep of `subject` and `clipping` finds each read alike by both rules.
    fn alike(operation: Operation, subject: &[Polygon], clipping: &[Polygon]) -> [bool; 2] {
        let (a, b) = (
            MultiPolygon::from_coordinates(subject),
            MultiPolygon::from_coordinates(clipping),
        );
        let boxes = [input::check(0, &a).unwrap(), input::check(1, &b).unwrap()];
        let mut watch = Watch::new();
        overlay_checked(
            operation,
            [&a, &b],
            &boxes,
            &swept_whole(),
            Some(&mut watch),
        )
        .unwrap();
        watch.alike
    }

    /// The default options, but polygons apart from all others are swept, not copied: the watched sweep is what
    /// these tests look at, and some of their rings are apart.
    fn swept_whole() -> Options {
        let mut options = Options::default();
        options.shortcuts.copy_apart = false;
        options
    }

    #[test]
    fn valid_polygon_sets_are_read_alike() {
        // A square with a hole (wound either way: the reading does not care), an island in the hole, a square
        // beside it; against a square that crosses all of them, shares the right square's left edge and has a
        // vertex on the big square's edge.
        let subject = [
            vec![square(0.0, 0.0, 10.0), reversed(square(2.0, 2.0, 6.0))],
            vec![square(4.0, 4.0, 2.0)],
            vec![square(12.0, 0.0, 3.0)],
        ];
        let clipping = [vec![vec![
            [5.0, -1.0],
            [12.0, -1.0],
            [12.0, 3.0],
            [5.0, 10.0],
        ]]];
        for operation in [Operation::Intersection, Operation::Union, Operation::Xor] {
            assert_eq!(
                alike(operation, &subject, &clipping),
                [true, true],
                "{operation:?}"
            );
        }
        // A hole in the island, and an island in that hole (three levels of nesting).
        let deeper = [
            vec![square(0.0, 0.0, 10.0), square(2.0, 2.0, 6.0)],
            vec![square(3.0, 3.0, 4.0), square(4.0, 4.0, 2.0)],
            vec![square(4.5, 4.5, 1.0)],
        ];
        assert_eq!(alike(Operation::Union, &deeper, &clipping), [true, true]);
    }

    #[test]
    fn each_way_of_being_invalid_is_seen() {
        let other = [vec![square(-5.0, -5.0, 30.0)]];
        let cases: [(&str, Coordinates); 10] = [
            (
                "overlapping parts",
                vec![vec![square(0.0, 0.0, 4.0)], vec![square(2.0, 2.0, 4.0)]],
            ),
            (
                "a part inside another",
                vec![vec![square(0.0, 0.0, 4.0)], vec![square(1.0, 1.0, 2.0)]],
            ),
            (
                "a hole outside its shell",
                vec![vec![square(0.0, 0.0, 4.0), square(6.0, 0.0, 1.0)]],
            ),
            (
                "a hole in another polygon's shell",
                vec![
                    vec![square(0.0, 0.0, 4.0), square(7.0, 1.0, 1.0)],
                    vec![square(6.0, 0.0, 4.0)],
                ],
            ),
            (
                "a hole in a hole",
                vec![vec![
                    square(0.0, 0.0, 10.0),
                    square(2.0, 2.0, 6.0),
                    square(4.0, 4.0, 2.0),
                ]],
            ),
            (
                "a hole crossing its shell",
                vec![vec![square(0.0, 0.0, 4.0), square(3.0, 1.0, 2.0)]],
            ),
            (
                "a hole touching its shell at a vertex",
                vec![vec![
                    square(0.0, 0.0, 4.0),
                    vec![[0.0, 0.0], [2.0, 1.0], [1.0, 2.0]],
                ]],
            ),
            (
                "a vertex on another ring's edge",
                vec![
                    vec![square(0.0, 0.0, 4.0)],
                    vec![vec![[4.0, 1.0], [6.0, 0.0], [6.0, 3.0]]],
                ],
            ),
            (
                "a ring crossing itself",
                vec![vec![vec![[0.0, 0.0], [4.0, 4.0], [4.0, 0.0], [0.0, 4.0]]]],
            ),
            (
                "a spike",
                vec![vec![vec![
                    [0.0, 0.0],
                    [4.0, 0.0],
                    [4.0, 4.0],
                    [6.0, 4.0],
                    [4.0, 4.0],
                    [0.0, 4.0],
                ]]],
            ),
        ];
        // (Intersection and xor: a union would leave out the polygons inside the convex square, unseen.)
        for (name, subject) in cases {
            assert_eq!(
                alike(Operation::Intersection, &subject, &other),
                [false, true],
                "{name}"
            );
            assert_eq!(
                alike(Operation::Xor, &other, &subject),
                [true, false],
                "{name}, as the clipping operand"
            );
        }
    }

    /// Squares above a stack of 40 bars of the other operand: one is looked for past the bars' 80 edges in S, but
    /// four squares would cost more steps (320) than there are edges (176), and the sweep gives up. The operation is
    /// then swept again with each operand made valid on its own, where the squares and the bars, alone, are seen to
    /// be valid and are read as they are: three sweeps more.
    #[test]
    fn a_ring_far_above_the_nearest_edge_of_its_operand_is_not_looked_for() {
        let bars: Coordinates = (0..40)
            .map(|i| {
                vec![vec![
                    [0.0, 2.0 * f64::from(i)],
                    [10.0, 2.0 * f64::from(i)],
                    [10.0, 2.0 * f64::from(i) + 1.0],
                    [0.0, 2.0 * f64::from(i) + 1.0],
                ]]
            })
            .collect();
        let row: Coordinates = (0..4)
            .map(|i| vec![square(0.5 + 2.0 * f64::from(i), 100.0, 1.0)])
            .collect();
        assert_eq!(alike(Operation::Union, &row[..1], &bars), [true, true]);
        assert_eq!(alike(Operation::Union, &row, &bars), [false, true]);
        let (a, b) = (
            MultiPolygon::from_coordinates(&row),
            MultiPolygon::from_coordinates(&bars),
        );
        let structure = swept_whole().with_fill_rule(FillRule::Structure);
        let (result, stats) =
            crate::overlay_with_stats(Operation::Union, &a, &b, &structure).unwrap();
        assert_eq!(
            (result.area(), stats.structure_sweeps),
            (4.0 + 40.0 * 10.0, 3)
        );
    }

    /// An intersection with clipping polygons judged by the subject's winding number: the subject is a square with a
    /// second, separate square inside it (the structural reading: the big square; even-odd: a frame), and the
    /// clipping operand a grid of small squares inside the inner one, which even-odd finds outside the subject and
    /// leaves out. Were the subject's polygons then left out by boxes (no clipping polygon is left to meet them),
    /// the sweep would not see the inner square inside the outer one, and the result would be empty.
    #[test]
    fn clipping_polygons_judged_by_the_subject_are_judged_by_its_structure() {
        // Each side in 25 edges, so that the winding grid (of about one cell per subject vertex) has cells smaller
        // than the gaps between the small squares and the subject's edges.
        let fine = |x: f64, y: f64, side: f64| -> Vec<[f64; 2]> {
            let corners = square(x, y, side);
            (0..4)
                .flat_map(|c| {
                    let (a, b) = (corners[c], corners[(c + 1) % 4]);
                    (0..25).map(move |i| {
                        let t = f64::from(i) / 25.0;
                        [a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t]
                    })
                })
                .collect()
        };
        let subject = MultiPolygon::from_coordinates(&[
            vec![fine(0.0, 0.0, 100.0)],
            vec![fine(20.0, 20.0, 60.0)],
        ]);
        // Squares of side 3 on a 4 × 4 grid, all inside the inner square, away from its edges.
        let grid: Coordinates = (0..16)
            .map(|i| {
                let (x, y) = (f64::from(i % 4), f64::from(i / 4));
                vec![square(38.0 + 6.0 * x, 38.0 + 6.0 * y, 3.0)]
            })
            .collect();
        let clipping = MultiPolygon::from_coordinates(&grid);
        let structure = Options::default().with_fill_rule(FillRule::Structure);
        let (result, stats) =
            crate::overlay_with_stats(Operation::Intersection, &subject, &clipping, &structure)
                .unwrap();
        // Every one of the 16 squares of area 9 lies inside the big square.
        // The watched sweep; the subject made valid by its own three (two squares, then their union) after a watched
        // one; the squares' own watched one.
        assert_eq!((result.area(), stats.structure_sweeps), (144.0, 1 + 4 + 1));
    }
}
