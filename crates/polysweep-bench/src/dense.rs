//! The dense workloads (issue 25): arrangements where edges are collinear, vertices coincide and edges cross densely,
//! built after the workloads of i_overlay's published comparison with Clipper2 and Boost (iShape-Rust's
//! iOverlayPerformance: the same shapes, sizes and operations, in floats with integer values), plus the edge-sharing
//! board of parcel maps. Each workload comes in three sizes, the number of edges (or, for the lines net, of
//! crossings) growing about 4× from one to the next. docs/benchmarks.md describes each.

/// MultiPolygon coordinates: polygons of closed rings, exterior first.
pub type Coordinates = Vec<Vec<Vec<[f64; 2]>>>;

/// One dense workload at one size: two operands, the operation and the fill rule every engine reads them by.
pub struct Dense {
    pub name: &'static str,
    pub n: usize,
    pub operation: &'static str,
    /// `"nonzero"`: the lines net's and the spiral's operands overlap themselves; the others do not, where non-zero
    /// and even-odd agree.
    pub fill_rule: &'static str,
    pub subject: Coordinates,
    pub clip: Coordinates,
}

/// The workloads: name, operation, the three sizes and the generator of its two operands at a size.
type Generator = fn(usize) -> (Coordinates, Coordinates);
pub const WORKLOADS: [(&str, &str, [usize; 3], Generator); 7] = [
    ("checkerboard", "xor", [50, 100, 200], checkerboard),
    ("not-overlap", "union", [50, 100, 200], not_overlap),
    ("shared-edges", "union", [50, 100, 200], shared_edges),
    ("lines-net", "intersection", [125, 250, 500], lines_net),
    ("spiral", "union", [2048, 8192, 32768], spiral),
    ("windows", "difference", [50, 100, 200], windows),
    ("nested-squares", "xor", [250, 1000, 4000], nested_squares),
];

/// Every workload at every size, or those named (by workload name; sizes as numbers) when the lists are not empty.
pub fn workloads(names: &[String], sizes: &[usize]) -> Vec<Dense> {
    let mut all = Vec::new();
    for (name, operation, series, generate) in WORKLOADS {
        if !names.is_empty() && !names.iter().any(|n| n == name) {
            continue;
        }
        for n in series {
            if !sizes.is_empty() && !sizes.contains(&n) {
                continue;
            }
            let (subject, clip) = generate(n);
            let fill_rule = if matches!(name, "lines-net" | "spiral") {
                "nonzero"
            } else {
                "evenodd"
            };
            all.push(Dense {
                name,
                n,
                operation,
                fill_rule,
                subject,
                clip,
            });
        }
    }
    all
}

fn rectangle(x0: f64, y0: f64, x1: f64, y1: f64) -> Vec<Vec<[f64; 2]>> {
    vec![vec![[x0, y0], [x1, y0], [x1, y1], [x0, y1], [x0, y0]]]
}

/// n × n squares of side `size`, `pitch` apart, the first with its lower left corner at (x0, y0).
fn many_squares(x0: f64, y0: f64, size: f64, pitch: f64, n: usize) -> Coordinates {
    let mut squares = Vec::with_capacity(n * n);
    for row in 0..n {
        for col in 0..n {
            let (x, y) = (x0 + col as f64 * pitch, y0 + row as f64 * pitch);
            squares.push(rectangle(x, y, x + size, y + size));
        }
    }
    squares
}

/// n × n squares of side 20, 30 apart, xor the (n − 1) × (n − 1) of the same shifted by half the pitch: each square
/// overlaps four others at its corners, and every edge is collinear with the edges of its row or column.
fn checkerboard(n: usize) -> (Coordinates, Coordinates) {
    (
        many_squares(0.0, 0.0, 20.0, 30.0, n),
        many_squares(15.0, 15.0, 20.0, 30.0, n - 1),
    )
}

/// As the checkerboard with squares of side 10: no two squares meet; the union is every square.
fn not_overlap(n: usize) -> (Coordinates, Coordinates) {
    (
        many_squares(0.0, 0.0, 10.0, 30.0, n),
        many_squares(15.0, 15.0, 10.0, 30.0, n - 1),
    )
}

/// The black cells of an n × n board (cells of side 10) united with its white cells: every inner edge is shared by
/// a black and a white cell, four cells meet at every inner corner, and the union is one square — a parcel map's
/// shape, where every edge has a neighbour's on it.
fn shared_edges(n: usize) -> (Coordinates, Coordinates) {
    let (mut black, mut white) = (Vec::new(), Vec::new());
    for row in 0..n {
        for col in 0..n {
            let (x, y) = (col as f64 * 10.0, row as f64 * 10.0);
            let cell = rectangle(x, y, x + 10.0, y + 10.0);
            if (row + col) % 2 == 0 {
                black.push(cell);
            } else {
                white.push(cell);
            }
        }
    }
    (black, white)
}

/// n vertical bars (width 10, 20 apart) ∩ n horizontal bars: n² crossings of bars, 4n² crossing points.
fn lines_net(n: usize) -> (Coordinates, Coordinates) {
    let s = 10.0 * n as f64;
    let start = -s + 5.0;
    let vertical = (0..n)
        .map(|i| {
            let x = start + 20.0 * i as f64;
            rectangle(x, -s, x + 10.0, s)
        })
        .collect();
    let horizontal = (0..n)
        .map(|i| {
            let y = start + 20.0 * i as f64;
            rectangle(-s, y, s, y + 10.0)
        })
        .collect();
    (vertical, horizontal)
}

/// One ring of n vertices: a band along an Archimedean spiral (64 vertices a turn on each side), out along its outer
/// side and back along its inner side, whose width swings above and below the spacing of the turns, so that each
/// turn's outer side crosses the next turn's inner side 14 times. Its union with nothing, under non-zero, is the
/// region the band covers.
fn spiral(n: usize) -> (Coordinates, Coordinates) {
    let steps = n / 2;
    let turn = std::f64::consts::TAU;
    let pitch = 10.0; // distance between turns
    let radius = |a: f64| 20.0 + pitch * a / turn;
    // (The phase keeps the crossings away from the vertices.)
    let half_width = |a: f64| pitch / 2.0 * (1.0 + 0.5 * (7.0 * a + 0.5).sin());
    let point = |a: f64, r: f64| [r * a.cos(), r * a.sin()];
    // The inner side's vertices lie half a step of angle after the outer side's: otherwise the closing edge, on a
    // ray from the centre, would pass through the next turn's vertex on that ray.
    let outer = |i: usize| {
        let a = i as f64 * turn / 64.0;
        point(a, radius(a) + half_width(a))
    };
    let inner = |i: usize| {
        let a = (i as f64 + 0.5) * turn / 64.0;
        point(a, radius(a) - half_width(a))
    };
    let mut ring: Vec<[f64; 2]> = (0..steps).map(outer).collect();
    ring.extend((0..steps).rev().map(inner));
    ring.push(ring[0]);
    (vec![vec![ring]], Vec::new())
}

/// n × n squares of side 20, 30 apart, minus a square of side 10 at the centre of each: n² frames.
fn windows(n: usize) -> (Coordinates, Coordinates) {
    let origin = -15.0 * n as f64;
    let (mut outer, mut inner) = (Vec::new(), Vec::new());
    for row in 0..n {
        for col in 0..n {
            let (x, y) = (origin + 30.0 * col as f64, origin + 30.0 * row as f64);
            outer.push(rectangle(x, y, x + 20.0, y + 20.0));
            inner.push(rectangle(x + 5.0, y + 5.0, x + 15.0, y + 15.0));
        }
    }
    (outer, inner)
}

/// n concentric square frames (bars of width 4, 8 apart), the subject their top and bottom bars, the clipping
/// operand their left and right bars; the xor is the frames without their corners.
fn nested_squares(n: usize) -> (Coordinates, Coordinates) {
    let a = 4.0;
    let (mut horizontal, mut vertical) = (Vec::new(), Vec::new());
    for i in 0..n {
        let r = 2.0 * a * (i + 1) as f64;
        horizontal.push(rectangle(-r, r - a, r, r));
        horizontal.push(rectangle(-r, -r, r, -r + a));
        vertical.push(rectangle(-r, -r, -r + a, r));
        vertical.push(rectangle(r - a, -r, r, r));
    }
    (horizontal, vertical)
}

/// The number of edges of an operand.
pub fn edge_count(c: &Coordinates) -> usize {
    c.iter().flatten().map(|r| r.len() - 1).sum()
}
