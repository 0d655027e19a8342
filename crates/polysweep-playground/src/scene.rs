//! What the user edits: the two operands of the Boolean operation, as polysweep polygon sets, and the lines drawn
//! to clip by the result and split it along, with undo and redo.
//!
//! A vertex is addressed exactly as the core's errors address it — operand, polygon, ring (0 is the exterior,
//! k is hole k − 1), vertex — so an error from the core points straight at the vertex to fix. Rings are kept open
//! (no repeated closing point) so that every vertex is one handle; the core accepts open rings.
//!
//! Every change goes through `Scene::edit` or `Scene::edit_lines`, which record the state before it for undo. A
//! vertex drag is one step: [`Scene::checkpoint`] records it when the drag starts, and the moves change the scene in
//! place.

use polysweep::{LineString, Location, MultiPolygon, Point, Polygon, Ring};
use std::cell::{Ref, RefCell};

/// Which operand: the subject P or the clipping polygon Q.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Operand {
    Subject,
    Clipping,
}

impl Operand {
    pub fn index(self) -> usize {
        self as usize
    }

    pub fn name(self) -> &'static str {
        match self {
            Operand::Subject => "P (subject)",
            Operand::Clipping => "Q (clipping)",
        }
    }
}

/// One vertex of one ring of one polygon of an operand.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct VertexId {
    pub operand: Operand,
    pub polygon: usize,
    pub ring: usize,
    pub vertex: usize,
}

impl VertexId {
    /// The vertex a core error names, if it still exists in `scene`.
    pub fn from_location(scene: &Scene, at: &Location) -> Option<VertexId> {
        let operand = [Operand::Subject, Operand::Clipping]
            .get(at.operand)
            .copied()?;
        let id = VertexId {
            operand,
            polygon: at.polygon,
            ring: at.ring,
            vertex: at.vertex,
        };
        scene
            .ring(id)
            .filter(|ring| at.vertex < ring.len())
            .map(|_| id)
    }
}

/// One vertex of one drawn line.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LineVertex {
    pub line: usize,
    pub vertex: usize,
}

impl LineVertex {
    /// The line vertex an error of [`polysweep::clip`] or [`polysweep::split`] names (a line is operand 1, polygon
    /// `line`), if it still exists in `scene`.
    pub fn from_location(scene: &Scene, at: &Location) -> Option<LineVertex> {
        let id = LineVertex {
            line: at.polygon,
            vertex: at.vertex,
        };
        (at.operand == 1 && scene.line_point(id).is_some()).then_some(id)
    }
}

/// Undo steps kept: at most this many, and only as many as fit in [`HISTORY_VERTICES`], so that a history of edits
/// on large data (the 59,212-vertex land) cannot exhaust the browser's memory.
const UNDO_DEPTH: usize = 200;
const HISTORY_VERTICES: usize = 4_000_000;

/// What one undo step restores.
#[derive(Clone, Debug, Default, PartialEq)]
struct State {
    operands: [MultiPolygon; 2],
    lines: Vec<LineString>,
}

impl State {
    fn vertex_count(&self) -> usize {
        let lines: usize = self.lines.iter().map(Vec::len).sum();
        self.operands[0].vertex_count() + self.operands[1].vertex_count() + lines
    }
}

/// `[min x, min y, max x, max y]`.
type Bounds = [f64; 4];
/// An operand revision and the bounds of each of its polygons.
type RevisionBounds = (u64, Vec<Bounds>);

/// The two operands, the lines and their history.
#[derive(Clone, Debug, Default)]
pub struct Scene {
    state: State,
    undo: Vec<State>,
    redo: Vec<State>,
    /// Counts undo steps recorded, undone and redone: a vertex id taken before a change may no longer be valid.
    generation: u64,
    /// Per operand, bumped whenever it changes: what is derived from an operand (its fill, the result) is
    /// recomputed when its revision moves, without keeping a copy of the operand to compare against.
    revisions: [u64; 2],
    /// Bumped whenever the lines change, as `revisions` are for the operands.
    lines_revision: u64,
    /// Per operand, the bounding box of each polygon and the revision they are of, made when first asked for:
    /// `vertex_near` looks only into polygons near the pointer, so that hovering over millions of vertices stays
    /// cheap.
    polygon_bounds: RefCell<[Option<RevisionBounds>; 2]>,
}

impl Scene {
    pub fn operand(&self, which: Operand) -> &MultiPolygon {
        &self.state.operands[which.index()]
    }

    pub fn lines(&self) -> &[LineString] {
        &self.state.lines
    }

    /// Changes whenever the operand does.
    pub fn revision(&self, which: Operand) -> u64 {
        self.revisions[which.index()]
    }

    /// Changes whenever the lines do.
    pub fn lines_revision(&self) -> u64 {
        self.lines_revision
    }

    /// Changes the `touched` operands as one undoable step.
    fn edit(&mut self, touched: &[Operand], change: impl FnOnce(&mut [MultiPolygon; 2])) {
        self.checkpoint();
        change(&mut self.state.operands);
        for which in touched {
            self.revisions[which.index()] += 1;
        }
    }

    /// Changes the lines as one undoable step.
    fn edit_lines(&mut self, change: impl FnOnce(&mut Vec<LineString>)) {
        self.checkpoint();
        change(&mut self.state.lines);
        self.lines_revision += 1;
    }

    /// Swaps in a state from the history, bumping the revision of each operand it changes, and of the lines.
    fn restore(&mut self, state: State) -> State {
        let operands = state.operands.iter().zip(&self.state.operands);
        for (revision, (new, old)) in self.revisions.iter_mut().zip(operands) {
            if new != old {
                *revision += 1;
            }
        }
        if state.lines != self.state.lines {
            self.lines_revision += 1;
        }
        self.generation += 1;
        std::mem::replace(&mut self.state, state)
    }

    /// Records the current state for undo; a drag calls this once, then [`Scene::move_vertex`] (or
    /// [`Scene::move_line_vertex`]) on every move.
    pub fn checkpoint(&mut self) {
        self.undo.push(self.state.clone());
        while self.undo.len() > 1
            && (self.undo.len() > UNDO_DEPTH
                || self.undo.iter().map(State::vertex_count).sum::<usize>() > HISTORY_VERTICES)
        {
            self.undo.remove(0);
        }
        self.redo.clear();
        self.generation += 1;
    }

    /// Changes whenever the history does; see the field.
    pub fn generation(&self) -> u64 {
        self.generation
    }

    /// Replaces one operand, e.g. with a loaded file.
    pub fn replace(&mut self, which: Operand, polygons: MultiPolygon) {
        self.edit(&[which], |operands| {
            operands[which.index()] = open_rings(polygons)
        });
    }

    /// Replaces both operands (a preset) as one step.
    pub fn replace_both(&mut self, subject: MultiPolygon, clipping: MultiPolygon) {
        self.edit(&[Operand::Subject, Operand::Clipping], |operands| {
            *operands = [open_rings(subject), open_rings(clipping)]
        });
    }

    pub fn can_undo(&self) -> bool {
        !self.undo.is_empty()
    }

    pub fn can_redo(&self) -> bool {
        !self.redo.is_empty()
    }

    pub fn undo(&mut self) {
        if let Some(previous) = self.undo.pop() {
            let current = self.restore(previous);
            self.redo.push(current);
        }
    }

    pub fn redo(&mut self) {
        if let Some(next) = self.redo.pop() {
            let current = self.restore(next);
            self.undo.push(current);
        }
    }

    pub fn ring(&self, id: VertexId) -> Option<&Ring> {
        let polygon = self.operand(id.operand).0.get(id.polygon)?;
        polygon.rings().nth(id.ring)
    }

    pub fn point(&self, id: VertexId) -> Option<Point> {
        self.ring(id)?.get(id.vertex).copied()
    }

    /// Moves a vertex (within the current undo step). Moving it where it is changes nothing, so that a drag held
    /// still asks for no new result.
    pub fn move_vertex(&mut self, id: VertexId, to: Point) {
        if let Some(p) = ring_mut(&mut self.state.operands[id.operand.index()], id)
            .and_then(|r| r.get_mut(id.vertex))
            .filter(|p| **p != to)
        {
            *p = to;
            self.revisions[id.operand.index()] += 1;
        }
    }

    /// Deletes a vertex as one undo step. A ring left with fewer than 3 vertices goes with it; an exterior ring takes
    /// its holes along, since a hole without its shell has nothing to be a hole of.
    pub fn delete_vertex(&mut self, id: VertexId) {
        if self.point(id).is_none() {
            return;
        }
        self.edit(&[id.operand], |operands| {
            let polygons = &mut operands[id.operand.index()].0;
            let polygon = &mut polygons[id.polygon];
            let ring = if id.ring == 0 {
                &mut polygon.exterior
            } else {
                &mut polygon.holes[id.ring - 1]
            };
            ring.remove(id.vertex);
            if ring.len() < 3 {
                if id.ring == 0 {
                    polygons.remove(id.polygon);
                } else {
                    polygon.holes.remove(id.ring - 1);
                }
            }
        });
    }

    /// Adds a closed ring drawn by the user to an operand, as one undo step. A ring that starts inside an exterior
    /// ring of that operand becomes a hole of it (the innermost such polygon), turned to run against its shell so
    /// that it is a hole under the non-zero rule too; any other ring starts a new polygon, as drawn.
    pub fn add_ring(&mut self, which: Operand, mut ring: Ring) {
        if ring.len() < 3 {
            return;
        }
        let area = |r: &Ring| polysweep::ring_area(r);
        let hosts = self.operand(which).0.iter().enumerate();
        let host = hosts
            .filter(|(_, p)| contains(&p.exterior, ring[0]))
            .min_by(|a, b| {
                area(&a.1.exterior)
                    .abs()
                    .total_cmp(&area(&b.1.exterior).abs())
            })
            .map(|(i, p)| (i, area(&p.exterior)));
        if let Some((_, shell_area)) = host {
            if shell_area * area(&ring) > 0.0 {
                ring.reverse();
            }
        }
        self.edit(&[which], |operands| {
            let polygons = &mut operands[which.index()].0;
            match host {
                Some((i, _)) => polygons[i].holes.push(ring),
                None => polygons.push(Polygon::new(ring, Vec::new())),
            }
        });
    }

    /// The vertex nearest to `at` within `radius`, preferring the given operand when two are equally near.
    pub fn vertex_near(&self, at: Point, radius: f64, prefer: Operand) -> Option<VertexId> {
        let mut best: Option<(f64, VertexId)> = None;
        for operand in [prefer, other(prefer)] {
            let bounds = self.polygon_bounds(operand);
            for (p, polygon) in self.operand(operand).0.iter().enumerate() {
                let [x0, y0, x1, y1] = bounds[p];
                if at.x < x0 - radius
                    || at.x > x1 + radius
                    || at.y < y0 - radius
                    || at.y > y1 + radius
                {
                    continue;
                }
                for (r, ring) in polygon.rings().enumerate() {
                    for (v, q) in ring.iter().enumerate() {
                        let d = (q.x - at.x).hypot(q.y - at.y);
                        if d <= radius && best.is_none_or(|(b, _)| d < b) {
                            best = Some((
                                d,
                                VertexId {
                                    operand,
                                    polygon: p,
                                    ring: r,
                                    vertex: v,
                                },
                            ));
                        }
                    }
                }
            }
        }
        best.map(|(_, id)| id)
    }

    /// `[min x, min y, max x, max y]` of each polygon of the operand, made anew when the operand has changed.
    fn polygon_bounds(&self, which: Operand) -> Ref<'_, Vec<Bounds>> {
        let (i, revision) = (which.index(), self.revision(which));
        if self.polygon_bounds.borrow()[i]
            .as_ref()
            .is_none_or(|(r, _)| *r != revision)
        {
            let bounds = (self.operand(which).0.iter())
                .map(|polygon| {
                    polygon.rings().flatten().fold(
                        [
                            f64::INFINITY,
                            f64::INFINITY,
                            f64::NEG_INFINITY,
                            f64::NEG_INFINITY,
                        ],
                        |[x0, y0, x1, y1], q| [x0.min(q.x), y0.min(q.y), x1.max(q.x), y1.max(q.y)],
                    )
                })
                .collect();
            self.polygon_bounds.borrow_mut()[i] = Some((revision, bounds));
        }
        Ref::map(self.polygon_bounds.borrow(), |all| {
            &all[i].as_ref().expect("made above").1
        })
    }

    /// Adds a line drawn by the user, as one undo step. A line without two distinct vertices, which has no length
    /// to clip or cut with, is dropped.
    pub fn add_line(&mut self, line: LineString) {
        if line.iter().all(|p| *p == line[0]) {
            return;
        }
        self.edit_lines(|lines| lines.push(line));
    }

    /// Removes every line, as one undo step (none when there are no lines).
    pub fn clear_lines(&mut self) {
        if !self.state.lines.is_empty() {
            self.edit_lines(Vec::clear);
        }
    }

    pub fn line_point(&self, id: LineVertex) -> Option<Point> {
        self.state.lines.get(id.line)?.get(id.vertex).copied()
    }

    /// Moves a vertex of a line (within the current undo step), if it is not there already.
    pub fn move_line_vertex(&mut self, id: LineVertex, to: Point) {
        if let Some(p) = self
            .state
            .lines
            .get_mut(id.line)
            .and_then(|l| l.get_mut(id.vertex))
            .filter(|p| **p != to)
        {
            *p = to;
            self.lines_revision += 1;
        }
    }

    /// Deletes a vertex of a line as one undo step; a line left with fewer than 2 vertices goes with it.
    pub fn delete_line_vertex(&mut self, id: LineVertex) {
        if self.line_point(id).is_none() {
            return;
        }
        self.edit_lines(|lines| {
            lines[id.line].remove(id.vertex);
            if lines[id.line].len() < 2 {
                lines.remove(id.line);
            }
        });
    }

    /// The line vertex nearest to `at` within `radius`.
    pub fn line_vertex_near(&self, at: Point, radius: f64) -> Option<LineVertex> {
        let mut best: Option<(f64, LineVertex)> = None;
        for (l, line) in self.state.lines.iter().enumerate() {
            for (v, q) in line.iter().enumerate() {
                let d = (q.x - at.x).hypot(q.y - at.y);
                if d <= radius && best.is_none_or(|(b, _)| d < b) {
                    best = Some((d, LineVertex { line: l, vertex: v }));
                }
            }
        }
        best.map(|(_, id)| id)
    }
}

pub fn other(operand: Operand) -> Operand {
    match operand {
        Operand::Subject => Operand::Clipping,
        Operand::Clipping => Operand::Subject,
    }
}

fn ring_mut(m: &mut MultiPolygon, id: VertexId) -> Option<&mut Ring> {
    let polygon = m.0.get_mut(id.polygon)?;
    match id.ring {
        0 => Some(&mut polygon.exterior),
        r => polygon.holes.get_mut(r - 1),
    }
}

/// Drops the repeated closing point of every ring, so each vertex is one handle.
fn open_rings(mut m: MultiPolygon) -> MultiPolygon {
    for polygon in &mut m.0 {
        for ring in std::iter::once(&mut polygon.exterior).chain(&mut polygon.holes) {
            if ring.len() > 1 && ring.first() == ring.last() {
                ring.pop();
            }
        }
    }
    m
}

/// Even-odd point-in-ring test by ray casting; used only to decide where a drawn ring goes.
fn contains(ring: &[Point], p: Point) -> bool {
    let mut inside = false;
    for (i, a) in ring.iter().enumerate() {
        let b = ring[(i + 1) % ring.len()];
        if (a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x) {
            inside = !inside;
        }
    }
    inside
}
