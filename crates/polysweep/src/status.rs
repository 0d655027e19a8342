//! The sweep-line status S (§3, §6): the edges crossing the sweep line, bottom to top.
//!
//! A treap (a binary search tree balanced by random priorities) with parent links, so that insertion is
//! O(log n) expected, and removal needs no search: each edge keeps its node. The nodes are also linked to their
//! neighbours in the order, so the neighbour queries of Fig. 5 (`S.prev`, `S.next`), made for nearly every event,
//! read one node instead of walking the tree. The order itself (§3, §7.1) is decided by the caller's comparison, see
//! [`crate::sweep`], on a copy of what it needs of each edge (`K`) kept in the node: descending the tree then reads
//! nodes only, not the events they stand for. No recursion: the depth is random, never driven by the input (the
//! tests' tree walk aside).
//!
//! Departure from the paper: the paper uses an STL `set` and finds an edge again by comparison (`S.find`). Finding
//! by handle means removal never depends on comparisons made later.

use crate::edges::{EventId, NONE};
use std::hint::select_unpredictable;

#[derive(Clone, Copy)]
struct Node<K> {
    key: K,
    event: EventId,
    parent: u32,
    children: [u32; 2],
    /// The nodes just below and above in the order: the tree's in-order sequence as a list, which rotations do
    /// not change.
    neighbours: [u32; 2],
    priority: u32,
}

pub(crate) struct Status<K> {
    nodes: Vec<Node<K>>,
    free: Vec<u32>,
    root: u32,
    random: u32,
}

impl<K> Default for Status<K> {
    fn default() -> Self {
        Status {
            nodes: Vec::new(),
            free: Vec::new(),
            root: NONE,
            random: 0x9E37_79B9,
        }
    }
}

impl<K: Copy> Status<K> {
    /// Room for `more` nodes without allocating (see [`crate::workspace::room`]).
    pub fn room(&mut self, more: usize) -> bool {
        crate::workspace::room(&mut self.nodes, more)
    }

    pub fn event(&self, node: u32) -> EventId {
        self.nodes[node as usize].event
    }

    /// Inserts `event` with its `key`; `below(key of an edge already in S)` says whether it goes below that edge.
    pub fn insert(&mut self, event: EventId, key: K, below: impl Fn(&K) -> bool) -> u32 {
        let id = self.new_node(event, key);
        if self.root == NONE {
            self.root = id;
            return id;
        }
        let mut current = self.root;
        loop {
            let side = if below(&self.nodes[current as usize].key) {
                0
            } else {
                1
            };
            match self.nodes[current as usize].children[side] {
                NONE => break self.attach(id, current, side),
                child => current = child,
            }
        }
        id
    }

    /// Inserts `event` with its `key` just above `node`, without a search; the caller guarantees that it belongs
    /// there.
    pub fn insert_above(&mut self, node: u32, event: EventId, key: K) -> u32 {
        let id = self.new_node(event, key);
        match self.nodes[node as usize].children[1] {
            NONE => self.attach(id, node, 1),
            // The next node is then the lowest of that subtree, which has no child below it.
            _ => self.attach(id, self.next(node), 0),
        }
        id
    }

    fn new_node(&mut self, event: EventId, key: K) -> u32 {
        // xorshift: deterministic priorities, so runs are reproducible.
        self.random ^= self.random << 13;
        self.random ^= self.random >> 17;
        self.random ^= self.random << 5;
        let node = Node {
            key,
            event,
            parent: NONE,
            children: [NONE; 2],
            neighbours: [NONE; 2],
            priority: self.random,
        };
        match self.free.pop() {
            Some(id) => {
                self.nodes[id as usize] = node;
                id
            }
            None => {
                self.nodes.push(node);
                (self.nodes.len() - 1) as u32
            }
        }
    }

    /// Hangs the new node `id` as the empty child `side` of `parent`, then rotates it up to its place by priority.
    fn attach(&mut self, id: u32, parent: u32, side: usize) {
        self.nodes[parent as usize].children[side] = id;
        self.nodes[id as usize].parent = parent;
        // A new leaf lies between its parent and the parent's neighbour on that side. (The pair made at once, not
        // by a store to one of its halves, which stalls the pair's read that follows.)
        let beyond = self.nodes[parent as usize].neighbours[side];
        let neighbours = select_unpredictable(side == 0, [beyond, parent], [parent, beyond]);
        self.link(id, neighbours);
        while let Some(parent) = self.parent(id) {
            if self.nodes[id as usize].priority >= self.nodes[parent as usize].priority {
                break;
            }
            self.rotate_up(id);
        }
    }

    /// What `insert` was given for `node`.
    pub fn key(&self, node: u32) -> &K {
        &self.nodes[node as usize].key
    }

    /// The same, to change what the order does not read.
    pub fn key_mut(&mut self, node: u32) -> &mut K {
        &mut self.nodes[node as usize].key
    }

    /// Puts another edge at `node`; the caller guarantees that it belongs at this position of the order.
    pub fn replace(&mut self, node: u32, event: EventId, key: K) {
        let n = &mut self.nodes[node as usize];
        (n.event, n.key) = (event, key);
    }

    pub fn remove(&mut self, node: u32) {
        loop {
            let [l, r] = self.nodes[node as usize].children;
            let child = match (l, r) {
                (NONE, NONE) => break,
                (c, NONE) | (NONE, c) => c,
                _ if self.nodes[l as usize].priority < self.nodes[r as usize].priority => l,
                _ => r,
            };
            self.rotate_up(child);
        }
        self.replace_child(self.nodes[node as usize].parent, node, NONE);
        let [below, above] = self.nodes[node as usize].neighbours;
        self.set_neighbour(below, 1, above);
        self.set_neighbour(above, 0, below);
        self.free.push(node);
    }

    /// Puts `node` in the list between `neighbours`.
    fn link(&mut self, node: u32, neighbours: [u32; 2]) {
        self.nodes[node as usize].neighbours = neighbours;
        self.set_neighbour(neighbours[0], 1, node);
        self.set_neighbour(neighbours[1], 0, node);
    }

    fn set_neighbour(&mut self, node: u32, side: usize, neighbour: u32) {
        if node != NONE {
            self.nodes[node as usize].neighbours[side] = neighbour;
        }
    }

    /// The lowest edge's node, or `NONE` when S is empty.
    pub fn lowest(&self) -> u32 {
        let mut node = self.root;
        while node != NONE && self.nodes[node as usize].children[0] != NONE {
            node = self.nodes[node as usize].children[0];
        }
        node
    }

    /// The neighbour below, or `NONE`.
    pub fn prev(&self, node: u32) -> u32 {
        self.nodes[node as usize].neighbours[0]
    }

    /// The neighbour above, or `NONE`.
    pub fn next(&self, node: u32) -> u32 {
        self.nodes[node as usize].neighbours[1]
    }

    fn parent(&self, node: u32) -> Option<u32> {
        Some(self.nodes[node as usize].parent).filter(|&p| p != NONE)
    }

    /// Makes `new` the child of `parent` in place of `old` (or the root when `parent` is `NONE`).
    fn replace_child(&mut self, parent: u32, old: u32, new: u32) {
        if parent == NONE {
            self.root = new;
        } else {
            let children = &mut self.nodes[parent as usize].children;
            let side = if children[0] == old { 0 } else { 1 };
            children[side] = new;
        }
        if new != NONE {
            self.nodes[new as usize].parent = parent;
        }
    }

    /// Rotates `node` above its parent, keeping the in-order sequence.
    fn rotate_up(&mut self, node: u32) {
        let parent = self.nodes[node as usize].parent;
        let grandparent = self.nodes[parent as usize].parent;
        let side = if self.nodes[parent as usize].children[0] == node {
            0
        } else {
            1
        };
        let inner = self.nodes[node as usize].children[1 - side];
        self.nodes[parent as usize].children[side] = inner;
        if inner != NONE {
            self.nodes[inner as usize].parent = parent;
        }
        self.nodes[node as usize].children[1 - side] = parent;
        self.nodes[parent as usize].parent = node;
        self.replace_child(grandparent, parent, node);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The tree's in-order sequence, by walking the tree; it must agree with the neighbour list.
    fn tree_order(status: &Status<u32>) -> Vec<EventId> {
        fn walk(status: &Status<u32>, node: u32, out: &mut Vec<EventId>) {
            if node != NONE {
                let [below, above] = status.nodes[node as usize].children;
                walk(status, below, out);
                out.push(status.event(node));
                walk(status, above, out);
            }
        }
        let mut out = Vec::new();
        walk(status, status.root, &mut out);
        out
    }

    fn in_order(status: &Status<u32>) -> Vec<EventId> {
        let mut out = Vec::new();
        let mut node = status.root;
        if node == NONE {
            return out;
        }
        while status.prev(node) != NONE {
            node = status.prev(node);
        }
        while node != NONE {
            out.push(status.event(node));
            node = status.next(node);
        }
        assert_eq!(out, tree_order(status));
        out
    }

    #[test]
    fn keeps_order_through_inserts_and_removals() {
        let mut status = Status::default();
        let mut nodes = Vec::new();
        // Insert a permutation of 0..200 ordered by value.
        for i in 0..200u32 {
            let v = (i * 73) % 200;
            nodes.push((v, status.insert(v, v, |&other| v < other)));
        }
        assert_eq!(in_order(&status), (0..200).collect::<Vec<_>>());
        for &(v, node) in nodes.iter().filter(|(v, _)| v % 3 == 0) {
            status.remove(node);
            assert!(!in_order(&status).contains(&v));
        }
        let expected: Vec<u32> = (0..200).filter(|v| v % 3 != 0).collect();
        assert_eq!(in_order(&status), expected);
        // Insertion just above a node, without a search: 1000 + v above every remaining v, at both kinds of place
        // (a node with an empty right subtree, and one whose successor is deeper down).
        for &(v, node) in nodes.iter().filter(|(v, _)| v % 3 == 1) {
            status.insert_above(node, 1000 + v, 1000 + v);
        }
        let with_above: Vec<u32> = (expected.iter())
            .flat_map(|&v| [Some(v), (v % 3 == 1).then_some(1000 + v)])
            .flatten()
            .collect();
        assert_eq!(in_order(&status), with_above);
        for &(_, node) in nodes.iter().filter(|(v, _)| v % 3 == 1) {
            status.remove(status.next(node));
        }
        assert_eq!(in_order(&status), expected);
        // Neighbour queries agree with the in-order sequence.
        for &(v, node) in nodes.iter().filter(|(v, _)| v % 3 != 0) {
            let i = expected.iter().position(|&x| x == v).unwrap();
            let prev = status.prev(node);
            assert_eq!(
                if prev == NONE {
                    None
                } else {
                    Some(status.event(prev))
                },
                i.checked_sub(1).map(|j| expected[j])
            );
        }
    }
}
