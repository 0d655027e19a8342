//! Property tests of lines and layers against oracles that do not use the sweep: unit cells counted on integer
//! rectangles, ray casting on the input rings at sample points, and lengths and areas by their formulas.

mod common;

use common::{inside_even_odd, on_boundary};
use polysweep::{
    clip, overlay_layers, split, validate, ClipOptions, Keep, LayerFace, LayerMode, LineString,
    MultiPolygon, Options, Point, Polygon,
};
use proptest::prelude::*;

fn rectangle([x0, y0, x1, y1]: [i32; 4]) -> MultiPolygon {
    let (x0, x1) = (x0.min(x1) as f64, x0.max(x1) as f64 + 1.0);
    let (y0, y1) = (y0.min(y1) as f64, y0.max(y1) as f64 + 1.0);
    MultiPolygon(vec![Polygon::new(
        vec![
            Point::new(x0, y0),
            Point::new(x1, y0),
            Point::new(x1, y1),
            Point::new(x0, y1),
        ],
        vec![],
    )])
}

fn triangle(points: [(i32, i32); 3]) -> MultiPolygon {
    let ring = points
        .iter()
        .map(|&(x, y)| Point::new(x as f64, y as f64))
        .collect();
    MultiPolygon(vec![Polygon::new(ring, vec![])])
}

fn layer_of_rectangles() -> impl Strategy<Value = Vec<[i32; 4]>> {
    prop::collection::vec([0..10, 0..10, 0..10, 0..10], 1..=5)
}

fn layer_of_triangles() -> impl Strategy<Value = Vec<[(i32, i32); 3]>> {
    prop::collection::vec([(0..12, 0..12), (0..12, 0..12), (0..12, 0..12)], 1..=4)
}

/// The faces containing `p` (faces must not overlap: at most one).
fn faces_at(faces: &[LayerFace], p: Point) -> Vec<&LayerFace> {
    faces
        .iter()
        .filter(|f| inside_even_odd(&f.polygons, p))
        .collect()
}

/// The features of `layer` containing `p`.
fn covering(layer: &[MultiPolygon], p: Point) -> Vec<u32> {
    (0..layer.len() as u32)
        .filter(|&i| inside_even_odd(&layer[i as usize], p))
        .collect()
}

fn length(line: &[Point]) -> f64 {
    line.windows(2)
        .map(|w| (w[1].x - w[0].x).hypot(w[1].y - w[0].y))
        .sum()
}

proptest! {
    /// Rectangles on the integer grid: every unit cell lies in exactly one face, the one tagged with the features
    /// covering its centre, or in none where no feature covers it; a face's area is its cells' count, and the faces
    /// tagged with a feature add up to the feature's area.
    #[test]
    fn layer_faces_are_the_covered_cells(a in layer_of_rectangles(), b in layer_of_rectangles()) {
        let (a, b): (Vec<_>, Vec<_>) = (a.into_iter().map(rectangle).collect(), b.into_iter().map(rectangle).collect());
        let faces = overlay_layers(&a, &b, LayerMode::Union, &Options::default()).unwrap();
        let mut cells = vec![0usize; faces.len()];
        for x in 0..11 {
            for y in 0..11 {
                let centre = Point::new(x as f64 + 0.5, y as f64 + 0.5);
                let (in_a, in_b) = (covering(&a, centre), covering(&b, centre));
                let here = faces_at(&faces, centre);
                if in_a.is_empty() && in_b.is_empty() {
                    prop_assert!(here.is_empty());
                    continue;
                }
                prop_assert_eq!(here.len(), 1, "cell {:?}", centre);
                prop_assert_eq!((&here[0].a, &here[0].b), (&in_a, &in_b));
                cells[faces.iter().position(|f| std::ptr::eq(f, here[0])).unwrap()] += 1;
            }
        }
        for (face, count) in faces.iter().zip(cells) {
            prop_assert!(validate(&face.polygons).is_ok(), "{:?}", validate(&face.polygons));
            prop_assert_eq!(face.polygons.area(), count as f64);
        }
        for (layer, features) in [(0, &a), (1, &b)] {
            for (i, feature) in features.iter().enumerate() {
                let tagged: f64 = (faces.iter())
                    .filter(|f| if layer == 0 { &f.a } else { &f.b }.contains(&(i as u32)))
                    .map(|f| f.polygons.area())
                    .sum();
                prop_assert_eq!(tagged, feature.area());
            }
        }
    }

    /// Triangles at any angle: at sample points off every edge, at most one face, tagged as ray casting on the
    /// input finds; the faces tagged with a feature add up to its area.
    #[test]
    fn layer_faces_agree_with_point_in_polygon(a in layer_of_triangles(), b in layer_of_triangles()) {
        let (a, b): (Vec<_>, Vec<_>) = (a.into_iter().map(triangle).collect(), b.into_iter().map(triangle).collect());
        let faces = overlay_layers(&a, &b, LayerMode::Union, &Options::default()).unwrap();
        for face in &faces {
            prop_assert!(validate(&face.polygons).is_ok(), "{:?}", validate(&face.polygons));
        }
        let all: Vec<&MultiPolygon> = a.iter().chain(&b).chain(faces.iter().map(|f| &f.polygons)).collect();
        for i in 0..24 {
            for j in 0..24 {
                let p = Point::new(i as f64 * 0.5 + 0.125, j as f64 * 0.5 + 0.1875);
                if all.iter().any(|m| on_boundary(m, p)) {
                    continue;
                }
                let (in_a, in_b) = (covering(&a, p), covering(&b, p));
                let here = faces_at(&faces, p);
                if in_a.is_empty() && in_b.is_empty() {
                    prop_assert!(here.is_empty());
                } else {
                    prop_assert_eq!(here.len(), 1, "at {:?}", p);
                    prop_assert_eq!((&here[0].a, &here[0].b), (&in_a, &in_b));
                }
            }
        }
        for (i, feature) in a.iter().enumerate() {
            let tagged: f64 = faces.iter().filter(|f| f.a.contains(&(i as u32))).map(|f| f.polygons.area()).sum();
            prop_assert!((tagged - feature.area()).abs() <= 1e-9 * feature.area().max(1.0), "{} vs {}", tagged, feature.area());
        }
    }

    /// A line's parts inside and outside add up to the line, and each lies on its side (ray casting at the middle of
    /// each of its segments, off the boundary).
    #[test]
    fn clipped_parts_make_up_the_line(
        polygon in layer_of_triangles(),
        lines in prop::collection::vec(prop::collection::vec((0..12, 0..12), 2..=6), 1..=3),
    ) {
        let polygon = MultiPolygon(polygon.into_iter().flat_map(|t| triangle(t).0).collect());
        let lines: Vec<LineString> = (lines.into_iter())
            .map(|l| l.into_iter().map(|(x, y)| Point::new(x as f64, y as f64)).collect())
            .collect();
        let options = ClipOptions::default();
        let inside = clip(&lines, &polygon, &options).unwrap();
        let outside = clip(&lines, &polygon, &options.keeping(Keep::Outside)).unwrap();
        for (l, line) in lines.iter().enumerate() {
            let total: f64 = inside[l].iter().chain(&outside[l]).map(|p| length(p)).sum();
            prop_assert!((total - length(line)).abs() <= 1e-9 * length(line).max(1.0), "{} vs {}", total, length(line));
            for (parts, wanted) in [(&inside[l], true), (&outside[l], false)] {
                for w in parts.iter().flat_map(|p| p.windows(2)) {
                    // Points along the segment; off the boundary each is on the part's side, and a segment with all
                    // of them on the boundary runs along it, which counts as inside.
                    let along = [0.25, 0.5, 0.75].map(|t| Point::new(w[0].x + t * (w[1].x - w[0].x), w[0].y + t * (w[1].y - w[0].y)));
                    let off: Vec<Point> = along.into_iter().filter(|&p| !near_boundary(&polygon, p)).collect();
                    if off.is_empty() {
                        // Along the boundary: inside when the polygon set lies on either side.
                        let (dx, dy) = (w[1].x - w[0].x, w[1].y - w[0].y);
                        let norm = 1e-6 / dx.hypot(dy);
                        // (At a point of the segment that is no vertex of the small integer inputs.)
                        let at = Point::new(w[0].x + 0.3141 * dx, w[0].y + 0.3141 * dy);
                        let either = [1.0, -1.0].iter().any(|side| {
                            let p = Point::new(at.x - side * dy * norm, at.y + side * dx * norm);
                            inside_even_odd(&polygon, p)
                        });
                        prop_assert_eq!(either, wanted, "along the boundary at {:?}", at);
                    }
                    for p in off {
                        prop_assert_eq!(inside_even_odd(&polygon, p), wanted, "at {:?}", p);
                    }
                }
            }
        }
    }

    /// Pieces of a rectangle cut by lines: each valid, together the rectangle's area, and at sample points off every
    /// line and edge, exactly one piece holds a point of the rectangle.
    #[test]
    fn split_pieces_tile_the_polygon(
        r in [0..10, 0..10, 0..10, 0..10],
        lines in prop::collection::vec(prop::collection::vec((-1..13, -1..13), 2..=4), 1..=3),
    ) {
        let polygon = rectangle(r);
        let lines: Vec<LineString> = (lines.into_iter())
            .map(|l| l.into_iter().map(|(x, y)| Point::new(x as f64, y as f64)).collect())
            .collect();
        let pieces = split(&polygon, &lines, &Options::default()).unwrap();
        let area: f64 = pieces.iter().map(Polygon::area).sum();
        prop_assert!((area - polygon.area()).abs() <= 1e-9 * polygon.area());
        let pieces: Vec<MultiPolygon> = pieces.into_iter().map(|p| MultiPolygon(vec![p])).collect();
        for piece in &pieces {
            prop_assert!(validate(piece).is_ok(), "{:?}", validate(piece));
        }
        for i in 0..24 {
            for j in 0..24 {
                let p = Point::new(i as f64 * 0.5 + 0.125, j as f64 * 0.5 + 0.1875);
                if on_boundary(&polygon, p) || lines.iter().any(|l| on_line(l, p)) {
                    continue;
                }
                let holding = pieces.iter().filter(|m| inside_even_odd(m, p)).count();
                prop_assert_eq!(holding, usize::from(inside_even_odd(&polygon, p)), "at {:?}", p);
            }
        }
    }
}

proptest! {
    /// A line through a rectangle whose inner vertices all lie inside it cuts it along every segment between two of
    /// them (each such segment lies on a closed walk, the line and the boundary, so it separates two faces): just
    /// either side of such a segment, two different pieces.
    #[test]
    fn a_line_bending_inside_separates_its_sides(
        r in [0..6, 0..6, 0..6, 0..6],
        inner in prop::collection::vec((0..96, 0..96), 2..=4),
        ends in [(0..4, 0..96), (0..4, 0..96)],
    ) {
        let polygon = rectangle(r);
        let ring = &polygon.0[0].exterior;
        let (x0, y0, x1, y1) = (ring[0].x, ring[0].y, ring[2].x, ring[2].y);
        // Inner vertices strictly inside, on a grid of 1/16; ends outside, beyond one of the four sides.
        let inside = |(u, v): (i32, i32)| {
            Point::new(x0 + (x1 - x0) * (1.0 + u as f64) / 98.0, y0 + (y1 - y0) * (1.0 + v as f64) / 98.0)
        };
        let outside = |(side, t): (i32, i32)| {
            let t = x0 + (x1 - x0) * t as f64 / 96.0;
            let s = y0 + (y1 - y0) * (t - x0) / (x1 - x0);
            match side {
                0 => Point::new(x0 - 1.0, s),
                1 => Point::new(x1 + 1.0, s),
                2 => Point::new(t, y0 - 1.0),
                _ => Point::new(t, y1 + 1.0),
            }
        };
        let mut line = vec![outside(ends[0])];
        line.extend(inner.iter().map(|&q| inside(q)));
        line.push(outside(ends[1]));
        let pieces: Vec<MultiPolygon> = (split(&polygon, std::slice::from_ref(&line), &Options::default()).unwrap())
            .into_iter()
            .map(|p| MultiPolygon(vec![p]))
            .collect();
        let segments: Vec<[Point; 2]> = line.windows(2).map(|w| [w[0], w[1]]).collect();
        for (k, w) in segments.iter().enumerate().skip(1).take(inner.len() - 1) {
            let (dx, dy) = (w[1].x - w[0].x, w[1].y - w[0].y);
            let length = dx.hypot(dy);
            if length == 0.0 {
                continue;
            }
            let at = Point::new(w[0].x + 0.37 * dx, w[0].y + 0.37 * dy);
            let far_from_the_rest = segments.iter().enumerate().all(|(j, s)| j == k || distance(at, s) > 1e-3)
                && !near_boundary(&polygon, at);
            if !far_from_the_rest {
                continue;
            }
            let side = |sign: f64| Point::new(at.x - sign * dy / length * 1e-5, at.y + sign * dx / length * 1e-5);
            let holding = |p: Point| -> Vec<usize> {
                (0..pieces.len()).filter(|&i| inside_even_odd(&pieces[i], p)).collect()
            };
            let (left, right) = (holding(side(1.0)), holding(side(-1.0)));
            prop_assert_eq!(left.len(), 1);
            prop_assert_eq!(right.len(), 1);
            prop_assert_ne!(left, right, "segment {} does not cut", k);
        }
    }
}

/// The distance from `p` to the segment `s`.
fn distance(p: Point, [a, b]: &[Point; 2]) -> f64 {
    let (dx, dy) = (b.x - a.x, b.y - a.y);
    let t = (((p.x - a.x) * dx + (p.y - a.y) * dy) / (dx * dx + dy * dy)).clamp(0.0, 1.0);
    let t = if t.is_nan() { 0.0 } else { t };
    (a.x + t * dx - p.x).hypot(a.y + t * dy - p.y)
}

/// Is `p` within 1e-9 of an edge of `m`? (Points along a part that ends at a rounded crossing are computed in
/// floats, so they can be a rounding off an edge the part runs along.)
fn near_boundary(m: &MultiPolygon, p: Point) -> bool {
    m.0.iter().flat_map(|polygon| polygon.rings()).any(|ring| {
        (0..ring.len()).any(|i| distance(p, &[ring[i], ring[(i + 1) % ring.len()]]) <= 1e-9)
    })
}

/// Is `p` on the open polyline `line`?
fn on_line(line: &[Point], p: Point) -> bool {
    line.windows(2).any(|w| {
        let segment = MultiPolygon(vec![Polygon::new(vec![w[0], w[1]], vec![])]);
        on_boundary(&segment, p)
    })
}
