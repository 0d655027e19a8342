//! Lines against polygons (not in the paper): clipping polylines by a polygon set, and splitting polygons along
//! polylines. Both sweep the arrangement ([`crate::arrangement`]) of the polygon set's edges (operand 0, under its
//! fill rule) and the lines' (operand 1, each segment winding +1, so that a fragment carries a line exactly where
//! its operand-1 winding is positive, however many lines lie on it). The lines fill nothing: the coverage of
//! operand 0 on either side of a fragment says whether it lies inside the polygon set, outside, or along its
//! boundary. Lines are cut only by the polygon set's boundary: where they cross themselves or each other they go
//! on as given.

use crate::arrangement::{Arrangement, HalfEdge};
use crate::edges::NONE;
use crate::error::{Error, Location};
use crate::geometry::{MultiPolygon, Point, Polygon};
use crate::input::{self, push_edge, Bounds};
use crate::options::Options;
use crate::select::FillRule;
use crate::structure::valid_by_structure;
use crate::workspace;
use std::borrow::Cow;

/// A polyline: its vertices in order (at least two distinct ones to have any length).
pub type LineString = Vec<Point>;

/// Which parts of the lines [`clip`] keeps.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Keep {
    /// The parts inside the polygon set.
    #[default]
    Inside,
    /// The parts outside it.
    Outside,
}

/// Where [`clip`] puts the parts of a line that run along the polygon set's boundary.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Boundary {
    /// With the inside: the polygon set is closed, as GEOS's intersection and difference of a line and a polygon
    /// read it.
    #[default]
    Inside,
    /// With the outside: the polygon set is open.
    Outside,
}

/// `lines` clipped by `polygon` (read by `options.fill_rule`): for each line, in order, its parts on the `keep` side,
/// each running the line's way. A line is cut where it passes from inside the polygon set to outside (or onto its
/// boundary, which counts as `boundary` says); elsewhere a part goes on through the line's vertices and across
/// other lines, as the line does; a closed line (its last point its first) is not cut where it closes. Input
/// vertices come out bit for bit, cut points are the exact crossings rounded
/// to the nearest floats. Errors name the polygon set as operand 0, and a line as operand 1, polygon `line`,
/// ring 0.
///
/// ```
/// use polysweep::{clip, ClipOptions, Keep, MultiPolygon, Point};
/// let square = MultiPolygon::from_coordinates(&[vec![vec![[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]]]]);
/// let road = vec![Point::new(-1.0, 1.0), Point::new(3.0, 1.0)];
/// let inside = clip(&[road.clone()], &square, &ClipOptions::default())?;
/// assert_eq!(inside, vec![vec![vec![Point::new(0.0, 1.0), Point::new(2.0, 1.0)]]]);
/// let outside = clip(&[road], &square, &ClipOptions::default().keeping(Keep::Outside))?;
/// assert_eq!(outside[0].len(), 2);
/// # Ok::<(), polysweep::Error>(())
/// ```
pub fn clip(
    lines: &[LineString],
    polygon: &MultiPolygon,
    options: &ClipOptions,
) -> Result<Vec<Vec<LineString>>, Error> {
    let swept = LinesAndPolygon::sweep(polygon, lines, &options.options)?;
    let arrangement = &swept.arrangement;
    // Each line segment's pieces: (segment, exact vertices in the line's direction, kept).
    let mut pieces: Vec<(u32, [u32; 2], bool)> = Vec::new();
    for f in 0..arrangement.fragments.len() as u32 {
        let fragment = &arrangement.fragments[f as usize];
        if fragment.winding[1] <= 0 {
            continue;
        }
        let [left, right] = arrangement
            .coverage(f)
            .map(|c| swept.fill_rule.is_inside(c[0]));
        let inside = if left == right {
            left
        } else {
            options.boundary == Boundary::Inside
        };
        let kept = inside == (options.keep == Keep::Inside);
        for s in arrangement.segments(f) {
            if let Some(&(_, forward)) = swept.line_of(s) {
                let [a, b] = fragment.ends;
                pieces.push((s, if forward { [a, b] } else { [b, a] }, kept));
            }
        }
    }
    // Along each segment, the line's way: exact vertex ids follow the sweep order.
    pieces.sort_unstable_by_key(|&(s, [a, b], _)| (s, a.min(b)));
    let mut parts: Vec<Vec<LineString>> = vec![Vec::new(); lines.len()];
    let mut part = Part::default();
    let mut at = 0;
    let mut line = NONE;
    for s in swept.first_line_segment..arrangement.input.len() as u32 {
        let (this_line, forward) = swept.lines[(s - swept.first_line_segment) as usize];
        if this_line != line {
            part.close(&mut parts, line);
            line = this_line;
        }
        let end = at + pieces[at..].partition_point(|p| p.0 == s);
        let mut along: Vec<&(u32, [u32; 2], bool)> = pieces[at..end].iter().collect();
        if !forward {
            along.reverse();
        }
        let last = along.len().saturating_sub(1);
        for (i, &&(_, [a, b], kept)) in along.iter().enumerate() {
            if !kept {
                part.close(&mut parts, line);
                continue;
            }
            // A part keeps the line's own vertices and its two ends, not the points where other edges met it.
            if part.points.is_empty() {
                part.push(arrangement.point(a));
            }
            part.end = Some(arrangement.point(b));
            if i == last {
                part.push(arrangement.point(b));
            }
        }
        at = end;
    }
    part.close(&mut parts, line);
    for (line, parts) in lines.iter().zip(&mut parts) {
        join_around_a_closed_line(line, parts);
    }
    Ok(parts)
}

/// A closed line (its last point its first) has no end: its last and first parts, where they meet there, are one.
fn join_around_a_closed_line(line: &[Point], parts: &mut Vec<LineString>) {
    let start = line.first();
    let meet = |last: &LineString, first: &LineString| {
        last.last() == start && first.first() == start && line.len() > 2 && line.last() == start
    };
    if parts.len() >= 2 && meet(&parts[parts.len() - 1], &parts[0]) {
        let first = parts.remove(0);
        parts
            .last_mut()
            .expect("two parts")
            .extend_from_slice(&first[1..]);
    }
}

/// A part of a line being built by [`clip`]: its points so far, and where it ends if it ends here.
#[derive(Default)]
struct Part {
    points: LineString,
    end: Option<Point>,
}

impl Part {
    fn push(&mut self, p: Point) {
        if self.points.last() != Some(&p) {
            self.points.push(p);
        }
        self.end = None;
    }

    /// Ends the part (if any) as a part of `line`.
    fn close(&mut self, parts: &mut [Vec<LineString>], line: u32) {
        if let Some(end) = self.end.take() {
            self.push(end);
        }
        if self.points.len() >= 2 {
            parts[line as usize].push(std::mem::take(&mut self.points));
        }
        self.points.clear();
    }
}

/// Options of [`clip`]: which side to keep, where the boundary goes, and the polygon set's fill rule.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[non_exhaustive]
pub struct ClipOptions {
    pub keep: Keep,
    pub boundary: Boundary,
    /// The fill rule and the rest of the Boolean operations' options.
    pub options: Options,
}

impl ClipOptions {
    pub fn keeping(self, keep: Keep) -> Self {
        ClipOptions { keep, ..self }
    }

    pub fn with_boundary(self, boundary: Boundary) -> Self {
        ClipOptions { boundary, ..self }
    }

    pub fn with_fill_rule(self, fill_rule: FillRule) -> Self {
        let options = self.options.with_fill_rule(fill_rule);
        ClipOptions { options, ..self }
    }
}

/// The pieces of `polygon` (read by `options.fill_rule`) cut along `lines`: each a valid polygon, two of them
/// meeting only along cuts (and at points), together the polygon set. Only a line's parts inside the polygon set
/// cut it, and only where they separate it: a line that ends inside a piece (a dangling end) or runs along the
/// boundary cuts nothing there, and a polygon no line crosses from boundary to boundary comes out whole. Errors
/// name the polygon set as operand 0, and a line as operand 1, polygon `line`, ring 0.
///
/// ```
/// use polysweep::{split, MultiPolygon, Options, Point};
/// let square = MultiPolygon::from_coordinates(&[vec![vec![[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]]]]);
/// let cut = vec![Point::new(1.0, -1.0), Point::new(1.0, 3.0)];
/// let pieces = split(&square, &[cut], &Options::default())?;
/// assert_eq!(pieces.len(), 2);
/// assert!(pieces.iter().all(|p| p.area() == 2.0));
/// # Ok::<(), polysweep::Error>(())
/// ```
pub fn split(
    polygon: &MultiPolygon,
    lines: &[LineString],
    options: &Options,
) -> Result<Vec<Polygon>, Error> {
    let swept = LinesAndPolygon::sweep(polygon, lines, options)?;
    let arrangement = &swept.arrangement;
    let class_of = |h: HalfEdge| {
        let f = h / 2;
        let coverage = arrangement.coverage(f);
        let inside = |side: u32| swept.fill_rule.is_inside(coverage[side as usize][0]);
        let (left, right) = (inside(h % 2), inside(1 - h % 2));
        let cut = arrangement.fragments[f as usize].winding[1] > 0;
        if left && (!right || cut) {
            0
        } else {
            NONE
        }
    };
    Ok(arrangement
        .polygons(class_of)
        .into_iter()
        .map(|(_, p)| p)
        .collect())
}

/// The arrangement of a polygon set and some lines, and which line each of the lines' segments belongs to.
struct LinesAndPolygon {
    arrangement: Arrangement,
    /// The fill rule the polygon set's edges are read by (even-odd once the structural reading has made it valid).
    fill_rule: FillRule,
    /// The input segments from here on are the lines'.
    first_line_segment: u32,
    /// Per line segment: its line, and whether it runs the line's way in sweep order.
    lines: Vec<(u32, bool)>,
}

impl LinesAndPolygon {
    fn sweep(
        polygon: &MultiPolygon,
        lines: &[LineString],
        options: &Options,
    ) -> Result<LinesAndPolygon, Error> {
        let polygon_box = Bounds::around_all(&input::check(0, polygon)?);
        let as_rings = MultiPolygon(
            (lines.iter())
                .map(|l| Polygon::new(l.clone(), Vec::new()))
                .collect(),
        );
        let lines_box = Bounds::around_all(
            &input::check(1, &as_rings)
                .map_err(|e| e.relocated(|at| Location { ring: 0, ..at }))?,
        );
        let magnitude = polygon_box.around(&lines_box).magnitude();
        let (polygon, fill_rule) = readable(polygon, magnitude, options)?;
        let mut edges = Vec::new();
        input::add_edges(&mut edges, &polygon, 0, 0..polygon.0.len());
        let first_line_segment = edges.len() as u32;
        let mut of_segment = Vec::new();
        for (i, line) in lines.iter().enumerate() {
            for pair in line.windows(2) {
                let (from, to) = ([pair[0].x, pair[0].y], [pair[1].x, pair[1].y]);
                let before = edges.len();
                push_edge(&mut edges, from, to, 1);
                if let Some(edge) = edges.get_mut(before) {
                    of_segment.push((i as u32, edge.winding > 0));
                    // Every line counts one, whichever way it runs.
                    edge.winding = 1;
                }
            }
        }
        Ok(LinesAndPolygon {
            arrangement: Arrangement::sweep(edges, magnitude, options)?,
            fill_rule,
            first_line_segment,
            lines: of_segment,
        })
    }

    /// The line of input segment `s`, and whether it runs the line's way, if it is a line's.
    fn line_of(&self, s: u32) -> Option<&(u32, bool)> {
        s.checked_sub(self.first_line_segment)
            .and_then(|i| self.lines.get(i as usize))
    }
}

/// The polygon set as its edges are read: under the structural reading, first made a valid polygon set (which
/// even-odd then reads as it is); otherwise as it is, under its fill rule.
pub(crate) fn readable<'p>(
    polygon: &'p MultiPolygon,
    magnitude: f64,
    options: &Options,
) -> Result<(Cow<'p, MultiPolygon>, FillRule), Error> {
    if options.fill_rule != FillRule::Structure {
        return Ok((Cow::Borrowed(polygon), options.fill_rule));
    }
    let valid = workspace::with(options.shortcuts.keep_working_memory, |workspace| {
        valid_by_structure(polygon, magnitude, options, workspace)
    })?;
    Ok((Cow::Owned(valid.0), FillRule::EvenOdd))
}
