//! The sort of the initial events' keys (see [`super::initial_events`]): coordinates as integers that order like
//! them, sorted by distributing them into buckets by value and then sorting each bucket.
//!
//! Not in the paper, which sorts the events by comparison (a priority queue). Most of a comparison sort's work is
//! in the levels where the keys are still far apart; one pass of arithmetic on the value does them all at once.
//! With a bucket per four keys, on Table 1's workloads, the sort takes about half the instructions of the standard
//! library's sort, with far fewer unpredictable branches; more buckets cost more than they save. Keys that bunch in few buckets (a grid's columns, a cluster far from an
//! outlier) are sorted there by comparison, as before.

use crate::workspace::refill;

/// The bits of a finite float as an integer that orders like the float, with -0 equal to 0.
pub(crate) fn ordered_bits(v: f64) -> u64 {
    let bits = (v + 0.0).to_bits(); // -0 + 0 is +0
    if bits >> 63 == 1 {
        !bits
    } else {
        bits | 1 << 63
    }
}

/// The float whose [`ordered_bits`] `key` is.
fn value(key: u64) -> f64 {
    f64::from_bits(if key >> 63 == 1 {
        key & !(1 << 63)
    } else {
        !key
    })
}

/// The working memory of [`sort_by_key`], kept from one sort to the next: what it holds is overwritten.
#[derive(Default)]
pub(crate) struct Buckets<T> {
    /// The items in sorted order, before they are copied back.
    sorted: Vec<(u64, T)>,
    /// Each item's bucket.
    of_item: Vec<u32>,
    /// Where each bucket begins in the sorted order, and where its next item goes.
    starts: Vec<u32>,
    next: Vec<u32>,
}

impl<T> Buckets<T> {
    /// The bytes it holds (see [`crate::workspace`]).
    pub fn bytes(&self) -> usize {
        use crate::workspace::bytes_of;
        bytes_of(&self.sorted)
            + bytes_of(&self.of_item)
            + bytes_of(&self.starts)
            + bytes_of(&self.next)
    }
}

/// Sorts `items` by key (not stably: ties are ordered again by the caller).
///
/// A key's bucket is its value's place between the smallest and the largest, scaled to the number of buckets and
/// rounded down. Every step of that (a subtraction, a product with a positive factor, rounding down) is monotone
/// in floating point too, so a smaller key never lands in a later bucket, and sorting each bucket sorts them all.
/// Each item is an integer that orders like a coordinate, and what it stands for.
pub(crate) fn sort_by_key<T: Copy + Default>(items: &mut [(u64, T)], memory: &mut Buckets<T>) {
    let (Some(low), Some(high)) = (
        items.iter().map(|&(key, _)| key).min(),
        items.iter().map(|&(key, _)| key).max(),
    ) else {
        return;
    };
    if low == high {
        return;
    }
    let buckets = items.len() / 4 + 1;
    let (low, high) = (value(low), value(high));
    // (Over a range wider than the largest float, the scale is 0 and every key shares one bucket: still correct.)
    let scale = (buckets - 1) as f64 / (high - low);
    let bucket = |key: u64| (((value(key) - low) * scale) as usize).min(buckets - 1);
    // `starts[b]`: where bucket `b` begins in the sorted order, once summed up.
    let Buckets {
        sorted,
        of_item,
        starts,
        next,
    } = memory;
    refill(starts, buckets + 1, 0);
    of_item.clear();
    of_item.extend(items.iter().map(|&(key, _)| {
        let b = bucket(key);
        starts[b + 1] += 1;
        b as u32
    }));
    for b in 1..=buckets {
        starts[b] += starts[b - 1];
    }
    refill(sorted, items.len(), (0, T::default()));
    next.clear();
    next.extend_from_slice(starts);
    for (&item, &b) in items.iter().zip(of_item.iter()) {
        let slot = &mut next[b as usize];
        sorted[*slot as usize] = item;
        *slot += 1;
    }
    for range in starts.windows(2) {
        if range[1] - range[0] > 1 {
            sorted[range[0] as usize..range[1] as usize].sort_unstable_by_key(|&(key, _)| key);
        }
    }
    items.copy_from_slice(sorted);
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_random::{bits, unit};

    #[test]
    fn keys_order_like_their_coordinates_and_come_back_to_them() {
        let values = [
            -f64::MAX,
            -180.0,
            -1e-300,
            -0.0,
            0.0,
            5e-324,
            1.5,
            180.0,
            f64::MAX,
        ];
        for pair in values.windows(2) {
            assert!(ordered_bits(pair[0]) <= ordered_bits(pair[1]), "{pair:?}");
            assert_eq!(value(ordered_bits(pair[1])), pair[1] + 0.0);
        }
        assert_eq!(ordered_bits(-0.0), ordered_bits(0.0));
    }

    #[test]
    fn sorts_like_the_standard_sort() {
        let (mut random, mut uniform) = (bits(17), unit(18));
        let mut cases: Vec<Vec<f64>> = vec![
            vec![],
            vec![3.0],
            vec![2.0, 2.0, 2.0],
            vec![-f64::MAX, f64::MAX, 0.0, 1.0, -1.0], // a range wider than the largest float
            vec![1e-300, 0.0, 1e300, -5e-324, 7.0, 7.0],
            vec![1e-323, 0.0, 5e-324, 0.0], // a range so narrow that the scale overflows
        ];
        // Spread out, bunched in a few columns (a grid), and a cluster with an outlier far away.
        cases.push((0..20_000).map(|_| 360.0 * uniform() - 180.0).collect());
        cases.push((0..20_000).map(|_| (random() % 7) as f64 * 0.1).collect());
        cases.push(
            (0..20_000)
                .map(|i| if i == 0 { 1e200 } else { uniform() })
                .collect(),
        );
        // Any finite floats, of every magnitude.
        cases.push(
            (0..20_000)
                .map(|_| f64::from_bits(random()))
                .filter(|v| v.is_finite())
                .collect(),
        );
        for values in cases {
            let mut items: Vec<(u64, u32)> = (values.iter().enumerate())
                .map(|(i, &v)| (ordered_bits(v), i as u32))
                .collect();
            let mut expected = items.clone();
            sort_by_key(&mut items, &mut Buckets::default());
            expected.sort_unstable_by_key(|&(key, _)| key);
            let keys = |items: &[(u64, u32)]| items.iter().map(|&(key, _)| key).collect::<Vec<_>>();
            assert_eq!(keys(&items), keys(&expected), "{} values", values.len());
            let mut ids: Vec<u32> = items.iter().map(|&(_, id)| id).collect();
            ids.sort_unstable();
            assert!(ids.iter().enumerate().all(|(i, &id)| id == i as u32));
        }
    }
}
