//! Overlaying two layers of features, each output face knowing the features that cover it; and dissolving features
//! by a key (not in the paper, whose §1 names such overlays as its purpose: sea ice, biomes, watersheds).
//!
//! One sweep of the arrangement of both layers ([`crate::arrangement`]) knows, above every fragment, each feature's
//! winding number there: the numbers above the fragment below, plus the windings of the feature rings the fragment
//! lies on. The features there are those whose number the fill rule reads as inside (each feature on its own: the
//! features of one layer that overlap do not cancel). A face's set of features is the set on the left of its
//! half-edges, and faces of one set that share an edge are one polygon. The cost is one sweep of both layers and
//! the output, not one operation per pair of features. (Under the structural reading a feature that is not a valid
//! polygon set is first made one by sweeps of its own, as the Boolean operations read their operands.)

use crate::arrangement::Arrangement;
use crate::edges::NONE;
use crate::error::{Error, Location};
use crate::geometry::MultiPolygon;
use crate::input::{self, Bounds};
use crate::lines::readable;
use crate::options::Options;
use crate::select::Operation;
use std::collections::HashMap;
use std::hash::Hash;

/// Which faces of two layers' overlay [`overlay_layers`] returns, by the features that cover them.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum LayerMode {
    /// Covered by a feature of each layer.
    #[default]
    Intersection,
    /// Covered by any feature.
    Union,
    /// Covered by a feature of the first layer: the first layer split by the second.
    Identity,
    /// Covered by a feature of the first layer and none of the second.
    Difference,
    /// Covered by features of one layer only.
    Xor,
}

impl LayerMode {
    fn keeps(self, in_a: bool, in_b: bool) -> bool {
        match self {
            LayerMode::Intersection => in_a && in_b,
            LayerMode::Union => in_a || in_b,
            LayerMode::Identity => in_a,
            LayerMode::Difference => in_a && !in_b,
            LayerMode::Xor => in_a != in_b,
        }
    }
}

/// A face of two layers' overlay: the features of each layer that cover it (indices into the layers, in
/// increasing order), and where it is: every point covered by exactly those features, as polygons (faces with
/// these features that share an edge are one polygon; touching at a point, two).
#[derive(Clone, Debug, PartialEq)]
pub struct LayerFace {
    pub a: Vec<u32>,
    pub b: Vec<u32>,
    pub polygons: MultiPolygon,
}

/// The overlay of layers `a` and `b`, each a list of features (polygon sets, each read by `options.fill_rule`):
/// the faces that `mode` keeps, each with the features covering it, sorted by those features (`a`, then `b`). The
/// areas of the faces with a feature add up to the feature's area. Errors name a layer as operand 0 (`a`) or 1
/// (`b`) and a polygon by its index among the layer's polygons, counted through its features in order.
///
/// ```
/// use polysweep::{overlay_layers, LayerMode, MultiPolygon, Options};
/// let square = |x: f64, y: f64, side: f64| {
///     MultiPolygon::from_coordinates(&[vec![vec![[x, y], [x + side, y], [x + side, y + side], [x, y + side]]]])
/// };
/// // Two parcels side by side, and a zone across both.
/// let parcels = [square(0.0, 0.0, 2.0), square(2.0, 0.0, 2.0)];
/// let zones = [square(1.0, 1.0, 2.0)];
/// let faces = overlay_layers(&parcels, &zones, LayerMode::Intersection, &Options::default())?;
/// assert_eq!(faces.len(), 2);
/// assert_eq!((faces[0].a.as_slice(), faces[0].b.as_slice(), faces[0].polygons.area()), (&[0][..], &[0][..], 1.0));
/// assert_eq!((faces[1].a.as_slice(), faces[1].polygons.area()), (&[1][..], 1.0));
/// # Ok::<(), polysweep::Error>(())
/// ```
pub fn overlay_layers(
    a: &[MultiPolygon],
    b: &[MultiPolygon],
    mode: LayerMode,
    options: &Options,
) -> Result<Vec<LayerFace>, Error> {
    let boxes = [check_layer(0, a)?, check_layer(1, b)?];
    let magnitude = boxes[0].around(&boxes[1]).magnitude();
    // Each feature's edges in its layer's slot; the item of each segment is its feature, numbered through both
    // layers, with the segment's winding.
    let mut edges = Vec::new();
    let mut feature_of_segment = Vec::new();
    let features = a.iter().map(|f| (0, f)).chain(b.iter().map(|f| (1, f)));
    let mut fill_rule = options.fill_rule;
    for (index, (layer, feature)) in features.enumerate() {
        // (The rule is the same for every feature: even-odd for one the structural reading has made valid.)
        let (readable, rule) = readable(feature, magnitude, options)?;
        fill_rule = rule;
        input::add_edges(&mut edges, &readable, layer, 0..readable.0.len());
        feature_of_segment.resize(edges.len(), index as u32);
    }
    let arrangement = Arrangement::sweep(edges, magnitude, options)?;
    let (sides, sets) = arrangement.item_sets(
        |s| {
            let winding = arrangement.input[s as usize].winding;
            (feature_of_segment[s as usize], winding)
        },
        |winding| fill_rule.is_inside(winding),
    );
    let in_a = a.len() as u32;
    let kept: Vec<bool> = (sets.iter())
        .map(|set| {
            let covered_by_a = set.first().is_some_and(|&f| f < in_a);
            let covered_by_b = set.last().is_some_and(|&f| f >= in_a);
            mode.keeps(covered_by_a, covered_by_b)
        })
        .collect();
    let polygons = arrangement.polygons(|h| {
        let [left, right] = [h % 2, 1 - h % 2].map(|side| sides[(h / 2) as usize][side as usize]);
        if left != right && kept[left as usize] {
            left
        } else {
            NONE
        }
    });
    let mut faces: HashMap<u32, MultiPolygon> = HashMap::new();
    for (set, polygon) in polygons {
        faces.entry(set).or_default().0.push(polygon);
    }
    let mut faces: Vec<LayerFace> = (faces.into_iter())
        .map(|(set, polygons)| {
            let set = &sets[set as usize];
            let split = set.partition_point(|&f| f < in_a);
            LayerFace {
                a: set[..split].to_vec(),
                b: set[split..].iter().map(|f| f - in_a).collect(),
                polygons,
            }
        })
        .collect();
    faces.sort_by(|x, y| (&x.a, &x.b).cmp(&(&y.a, &y.b)));
    Ok(faces)
}

/// Checks every feature of layer `index`, naming a bad vertex's polygon by its index through the layer; returns
/// the box around the layer.
fn check_layer(index: usize, features: &[MultiPolygon]) -> Result<Bounds, Error> {
    let mut boxes = Vec::new();
    for feature in features {
        let before = boxes.len();
        let feature_boxes = input::check(index, feature).map_err(|e| {
            e.relocated(|at| Location {
                polygon: before + at.polygon,
                ..at
            })
        })?;
        boxes.extend(feature_boxes);
    }
    Ok(Bounds::around_all(&boxes))
}

/// `features`, each with its key, merged by key: for each distinct key, in the order keys first appear, the union of
/// the features with that key (so features of one key that share an edge or overlap become one polygon). Errors name a feature as
/// the operand.
///
/// ```
/// use polysweep::{dissolve, MultiPolygon, Options};
/// let square = |x: f64| MultiPolygon::from_coordinates(&[vec![vec![[x, 0.0], [x + 1.0, 0.0], [x + 1.0, 1.0], [x, 1.0]]]]);
/// let features = [("park", square(0.0)), ("park", square(1.0)), ("lake", square(2.0))];
/// let merged = dissolve(&features, &Options::default())?;
/// assert_eq!(merged.len(), 2);
/// assert_eq!((merged[0].0, merged[0].1.0.len(), merged[0].1.area()), ("park", 1, 2.0));
/// # Ok::<(), polysweep::Error>(())
/// ```
pub fn dissolve<K: Eq + Hash + Clone>(
    features: &[(K, MultiPolygon)],
    options: &Options,
) -> Result<Vec<(K, MultiPolygon)>, Error> {
    let mut groups: Vec<(K, Vec<usize>)> = Vec::new();
    let mut group_of: HashMap<&K, usize> = HashMap::new();
    for (i, (key, _)) in features.iter().enumerate() {
        let g = *group_of.entry(key).or_insert_with(|| {
            groups.push((key.clone(), Vec::new()));
            groups.len() - 1
        });
        groups[g].1.push(i);
    }
    let mut merged = Vec::with_capacity(groups.len());
    for (key, members) in groups {
        let operands: Vec<&MultiPolygon> = members.iter().map(|&i| &features[i].1).collect();
        let union =
            crate::overlay::overlay_many(Operation::Union, &operands, options).map_err(|e| {
                e.relocated(|at| Location {
                    operand: members[at.operand],
                    ..at
                })
            })?;
        merged.push((key, union));
    }
    Ok(merged)
}
