//! Jobs and what they computed as flat arrays of numbers, the form in which they cross to the browser's worker and
//! back (background.rs) as transferable `Float64Array`s. Counts, codes and indices are stored as f64, exact up to
//! 2⁵³. Fills and outlines get new ids when read: ids are per thread.

use crate::fill::Fill;
use crate::job::{Computed, Derivation, Job};
use crate::operation::{Cut, Op, Outcome};
use crate::scene::Operand;
use polysweep::{Error, FillRule, Location, MultiPolygon, Point, Polygon};
use std::sync::Arc;

/// A malformed message: only a mismatch between the page's and the worker's builds could cause one.
#[derive(Debug)]
pub struct Malformed;

pub fn write_job(job: &Job) -> Vec<f64> {
    let mut w = Writer::default();
    match job {
        Job::Region {
            which,
            operand,
            fill_rule,
        } => {
            w.count(0);
            w.count(which.index());
            w.count(fill_rule_code(*fill_rule));
            w.polygons(&operand.0);
        }
        Job::Result {
            op,
            fill_rule,
            operands,
            lines,
        } => {
            w.count(1);
            w.count(
                Op::ALL
                    .iter()
                    .position(|o| o == op)
                    .expect("every op is in ALL"),
            );
            w.count(fill_rule_code(*fill_rule));
            operands.iter().for_each(|o| w.polygons(&o.0));
            w.chains(lines);
        }
    }
    w.0
}

pub fn read_job(numbers: &[f64]) -> Result<Job, Malformed> {
    let mut r = Reader::new(numbers);
    let job = match r.count()? {
        0 => Job::Region {
            which: [Operand::Subject, Operand::Clipping][r.index(2)?],
            fill_rule: FILL_RULES[r.index(FILL_RULES.len())?],
            operand: Arc::new(MultiPolygon::new(r.polygons()?)),
        },
        1 => Job::Result {
            op: Op::ALL[r.index(Op::ALL.len())?],
            fill_rule: FILL_RULES[r.index(FILL_RULES.len())?],
            operands: [r.polygons()?, r.polygons()?].map(|p| Arc::new(MultiPolygon::new(p))),
            lines: r.chains()?,
        },
        _ => return Err(Malformed),
    };
    r.end(job)
}

/// Writes what a job computed, or `None` if it holds an error this format does not know (a variant added to the
/// core's `Error` after this was written): the page then runs the job itself.
pub fn write_derivation(derivation: &Derivation) -> Option<Vec<f64>> {
    let mut w = Writer::default();
    match derivation {
        Derivation::Region(fill) => {
            w.count(0);
            w.fill(fill);
        }
        Derivation::Result(computed) => {
            w.count(1);
            match &computed.outcome {
                Ok(o) => {
                    w.count(0);
                    w.polygons(&o.result.0);
                    w.count(o.crossings);
                    w.0.push(o.milliseconds);
                }
                Err(e) => {
                    w.count(1);
                    w.error(e)?;
                }
            }
            w.fill(&computed.fill);
            match &computed.cut {
                None => w.count(0),
                Some(Ok(cut)) => {
                    w.count(1);
                    w.chains(&cut.inside);
                    w.chains(&cut.outside);
                    w.polygons(&cut.pieces);
                }
                Some(Err(e)) => {
                    w.count(2);
                    w.error(e)?;
                }
            }
            w.count(computed.piece_fills.len());
            computed.piece_fills.iter().for_each(|f| w.fill(f));
        }
    }
    Some(w.0)
}

pub fn read_derivation(numbers: &[f64]) -> Result<Derivation, Malformed> {
    let mut r = Reader::new(numbers);
    let derivation = match r.count()? {
        0 => Derivation::Region(r.fill()?),
        1 => {
            let outcome = match r.count()? {
                0 => Ok(Outcome {
                    result: MultiPolygon::new(r.polygons()?),
                    crossings: r.whole()?,
                    milliseconds: r.number()?,
                }),
                _ => Err(r.error()?),
            };
            let fill = r.fill()?;
            let cut = match r.count()? {
                0 => None,
                1 => Some(Ok(Cut {
                    inside: r.chains()?,
                    outside: r.chains()?,
                    pieces: r.polygons()?,
                })),
                _ => Some(Err(r.error()?)),
            };
            let piece_fills = (0..r.count()?)
                .map(|_| r.fill())
                .collect::<Result<_, _>>()?;
            Derivation::Result(Box::new(Computed::new(outcome, fill, cut, piece_fills)))
        }
        _ => return Err(Malformed),
    };
    r.end(derivation)
}

const FILL_RULES: [FillRule; 4] = [
    FillRule::EvenOdd,
    FillRule::NonZero,
    FillRule::Positive,
    FillRule::Negative,
];

fn fill_rule_code(rule: FillRule) -> usize {
    FILL_RULES
        .iter()
        .position(|r| *r == rule)
        .expect("every fill rule is listed")
}

#[derive(Default)]
struct Writer(Vec<f64>);

impl Writer {
    fn count(&mut self, n: usize) {
        self.0.push(n as f64);
    }

    fn points(&mut self, points: &[Point]) {
        self.count(points.len());
        self.0.extend(points.iter().flat_map(|p| [p.x, p.y]));
    }

    fn chains(&mut self, chains: &[Vec<Point>]) {
        self.count(chains.len());
        chains.iter().for_each(|c| self.points(c));
    }

    fn polygons(&mut self, polygons: &[Polygon]) {
        self.count(polygons.len());
        for polygon in polygons {
            self.points(&polygon.exterior);
            self.chains(&polygon.holes);
        }
    }

    fn fill(&mut self, fill: &Fill) {
        self.points(fill.points());
        self.count(fill.triangles().len());
        self.0.extend(fill.triangles().iter().map(|&i| i as f64));
    }

    fn location(&mut self, at: &Location) {
        for n in [at.operand, at.polygon, at.ring, at.vertex] {
            self.count(n);
        }
    }

    fn error(&mut self, error: &Error) -> Option<()> {
        match error {
            Error::NonFiniteCoordinate { at, value } => {
                self.count(0);
                self.location(at);
                self.0.push(*value);
            }
            Error::CoordinateOutOfRange { at, value } => {
                self.count(1);
                self.location(at);
                self.0.push(*value);
            }
            Error::TooLarge { limit } => {
                self.count(2);
                self.count(*limit);
            }
            Error::OutOfMemory { edges, crossings } => {
                self.count(3);
                self.count(*edges);
                self.count(*crossings);
            }
            _ => return None,
        }
        Some(())
    }
}

struct Reader<'a> {
    numbers: &'a [f64],
    at: usize,
}

impl<'a> Reader<'a> {
    fn new(numbers: &'a [f64]) -> Self {
        Reader { numbers, at: 0 }
    }

    fn number(&mut self) -> Result<f64, Malformed> {
        let n = *self.numbers.get(self.at).ok_or(Malformed)?;
        self.at += 1;
        Ok(n)
    }

    /// A whole number, not negative.
    fn whole(&mut self) -> Result<usize, Malformed> {
        let n = self.number()?;
        // (NaN fails the first test.)
        if !(n >= 0.0 && n.fract() == 0.0 && n <= usize::MAX as f64) {
            return Err(Malformed);
        }
        Ok(n as usize)
    }

    /// A count, which never exceeds the length of the message: that also bounds what a bad message can make us
    /// allocate.
    fn count(&mut self) -> Result<usize, Malformed> {
        let n = self.whole()?;
        (n <= self.numbers.len()).then_some(n).ok_or(Malformed)
    }

    /// A code below `limit`.
    fn index(&mut self, limit: usize) -> Result<usize, Malformed> {
        let n = self.count()?;
        (n < limit).then_some(n).ok_or(Malformed)
    }

    fn points(&mut self) -> Result<Vec<Point>, Malformed> {
        let n = self.count()?;
        let coordinates = self
            .numbers
            .get(self.at..self.at + 2 * n)
            .ok_or(Malformed)?;
        self.at += 2 * n;
        Ok(coordinates
            .chunks_exact(2)
            .map(|c| Point::new(c[0], c[1]))
            .collect())
    }

    fn chains(&mut self) -> Result<Vec<Vec<Point>>, Malformed> {
        (0..self.count()?).map(|_| self.points()).collect()
    }

    fn polygons(&mut self) -> Result<Vec<Polygon>, Malformed> {
        (0..self.count()?)
            .map(|_| Ok(Polygon::new(self.points()?, self.chains()?)))
            .collect()
    }

    fn fill(&mut self) -> Result<Fill, Malformed> {
        let points = self.points()?;
        let triangles = (0..self.count()?)
            .map(|_| {
                let i = self.count()?;
                (i < points.len()).then_some(i as u32).ok_or(Malformed)
            })
            .collect::<Result<_, _>>()?;
        Ok(Fill::from_triangles(points, triangles))
    }

    fn location(&mut self) -> Result<Location, Malformed> {
        Ok(Location {
            operand: self.whole()?,
            polygon: self.whole()?,
            ring: self.whole()?,
            vertex: self.whole()?,
        })
    }

    fn error(&mut self) -> Result<Error, Malformed> {
        Ok(match self.count()? {
            0 => Error::NonFiniteCoordinate {
                at: self.location()?,
                value: self.number()?,
            },
            1 => Error::CoordinateOutOfRange {
                at: self.location()?,
                value: self.number()?,
            },
            2 => Error::TooLarge {
                limit: self.whole()?,
            },
            3 => Error::OutOfMemory {
                edges: self.whole()?,
                crossings: self.whole()?,
            },
            _ => return Err(Malformed),
        })
    }

    /// `value` if the whole message was read.
    fn end<T>(self, value: T) -> Result<T, Malformed> {
        (self.at == self.numbers.len())
            .then_some(value)
            .ok_or(Malformed)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square(x: f64, y: f64, side: f64) -> Vec<[f64; 2]> {
        vec![
            [x, y],
            [x + side, y],
            [x + side, y + side],
            [x, y + side],
            [x, y],
        ]
    }

    fn holed_and_plain() -> MultiPolygon {
        MultiPolygon::from_coordinates(&[
            vec![square(0.0, 0.0, 4.0), square(1.0, 1.0, 1.0)],
            vec![square(10.0, 0.0, 1.0)],
        ])
    }

    #[test]
    fn a_job_reads_back_as_it_was_written() {
        let line = vec![Point::new(-1.0, 0.5), Point::new(12.0, 0.5)];
        let job = Job::Result {
            op: Op::ClippingMinusSubject,
            fill_rule: FillRule::Negative,
            operands: [holed_and_plain(), MultiPolygon::default()].map(Arc::new),
            lines: vec![line.clone(), vec![]],
        };
        let Ok(Job::Result {
            op,
            fill_rule,
            operands,
            lines,
        }) = read_job(&write_job(&job))
        else {
            panic!("a result job reads back as one");
        };
        assert_eq!(
            (op, fill_rule),
            (Op::ClippingMinusSubject, FillRule::Negative)
        );
        assert_eq!(
            operands.map(|o| (*o).clone()),
            [holed_and_plain(), MultiPolygon::default()]
        );
        assert_eq!(lines, vec![line, vec![]]);
    }

    #[test]
    fn a_result_with_its_fill_and_cut_reads_back_with_the_same_figures() {
        // The xor of P (a holed square and a unit square) and Q (a square over P's corner), cut by a line down P.
        let q = MultiPolygon::from_coordinates(&[vec![square(3.0, 3.0, 2.0)]]);
        let job = Job::Result {
            op: Op::Xor,
            fill_rule: FillRule::EvenOdd,
            operands: [holed_and_plain(), q].map(Arc::new),
            lines: vec![vec![Point::new(2.5, -1.0), Point::new(2.5, 6.0)]],
        };
        let written = write_derivation(&job.run()).expect("no unknown error");
        let Ok(Derivation::Result(computed)) = read_derivation(&written) else {
            panic!("a result reads back as one");
        };
        // P is 16 − 1 + 1 = 16, Q is 4, they share the unit square (3, 3)–(4, 4): the xor is 16 + 4 − 2 = 18.
        let outcome = computed.outcome.as_ref().expect("no error");
        assert_eq!(outcome.result.area(), 18.0);
        let cut = computed
            .cut
            .as_ref()
            .expect("a line")
            .as_ref()
            .expect("no error");
        let piece_area: f64 = computed.piece_fills.iter().map(Fill::area).sum();
        assert_eq!(piece_area, 18.0, "the pieces' fills cover the result");
        assert_eq!(cut.pieces.len(), computed.piece_fills.len());
        // The line x = 2.5 from y = −1 to 6 is inside the result from y = 0 to 4 (clear of the hole and of Q).
        assert_eq!(
            cut.inside,
            vec![vec![Point::new(2.5, 0.0), Point::new(2.5, 4.0)]]
        );
        assert_eq!(cut.outside.len(), 2);
        assert!(!computed.piece_outline.segments().is_empty());
    }

    #[test]
    fn an_error_reads_back_naming_the_same_vertex() {
        let bad =
            MultiPolygon::from_coordinates(&[vec![vec![[0.0, 0.0], [f64::NAN, 1.0], [1.0, 1.0]]]]);
        let job = Job::Result {
            op: Op::ClippingMinusSubject,
            fill_rule: FillRule::EvenOdd,
            operands: [holed_and_plain(), bad].map(Arc::new),
            lines: vec![],
        };
        let written = write_derivation(&job.run()).expect("a known error");
        let Ok(Derivation::Result(computed)) = read_derivation(&written) else {
            panic!("a result reads back as one");
        };
        let error = computed.outcome.as_ref().expect_err("NaN is refused");
        assert!(
            error
                .to_string()
                .contains("operand 1, polygon 0, ring 0, vertex 1"),
            "{error}"
        );
    }

    #[test]
    fn figures_larger_than_the_message_read_back() {
        // An empty result after many crossings, and errors with large figures: not counts of what follows.
        let empty_after_crossings = Derivation::Result(Box::new(Computed::new(
            Ok(Outcome {
                result: MultiPolygon::default(),
                crossings: 1_000_000,
                milliseconds: 2.5,
            }),
            Fill::default(),
            Some(Err(Error::OutOfMemory {
                edges: 3_000_000,
                crossings: 7_000_000,
            })),
            Vec::new(),
        )));
        let written = write_derivation(&empty_after_crossings).unwrap();
        let Ok(Derivation::Result(computed)) = read_derivation(&written) else {
            panic!("a result reads back as one");
        };
        assert_eq!(computed.outcome.as_ref().unwrap().crossings, 1_000_000);
        let error = computed.cut.as_ref().unwrap().as_ref().unwrap_err();
        assert_eq!(
            *error,
            Error::OutOfMemory {
                edges: 3_000_000,
                crossings: 7_000_000
            }
        );
        let far_vertex = Error::NonFiniteCoordinate {
            at: Location {
                operand: 1,
                polygon: 4_000,
                ring: 2,
                vertex: 123_456,
            },
            value: f64::INFINITY,
        };
        for error in [Error::TooLarge { limit: 1 << 31 }, far_vertex] {
            let mut w = Writer::default();
            w.error(&error).unwrap();
            assert_eq!(Reader::new(&w.0).error().unwrap(), error);
        }
    }

    #[test]
    fn malformed_messages_are_refused_not_trusted() {
        let region = Job::Region {
            which: Operand::Clipping,
            operand: Arc::new(holed_and_plain()),
            fill_rule: FillRule::NonZero,
        };
        let written = write_job(&region);
        assert!(read_job(&written).is_ok());
        assert!(
            read_job(&written[..written.len() - 1]).is_err(),
            "cut short"
        );
        assert!(
            read_job(&[written.clone(), vec![0.0]].concat()).is_err(),
            "too long"
        );
        assert!(read_job(&[0.0, 2.0, 0.0, 0.0]).is_err(), "no third operand");
        assert!(
            read_job(&[0.0, 0.0, 0.0, 1e300]).is_err(),
            "a count beyond the message"
        );
        assert!(
            read_derivation(&[0.0, 1.0, 0.5, 0.5, 3.0, 0.0, 0.0, 1.0]).is_err(),
            "a triangle past the one point"
        );
    }
}
