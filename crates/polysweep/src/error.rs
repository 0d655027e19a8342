//! The one error type. Bad input names where it is: operand, polygon, ring and vertex.

use crate::geometry::{MAX_COORDINATE, MIN_COORDINATE};
use std::fmt;

/// Where a bad vertex is: indices into the operands passed to the operation (0 = subject, 1 = clipping for the
/// binary operations), the polygon within the operand, the ring within the polygon (0 = exterior, 1.. = holes)
/// and the vertex within the ring.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Location {
    pub operand: usize,
    pub polygon: usize,
    pub ring: usize,
    pub vertex: usize,
}

impl fmt::Display for Location {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "operand {}, polygon {}, ring {}, vertex {}",
            self.operand, self.polygon, self.ring, self.vertex
        )
    }
}

/// Why an operation could not be carried out.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum Error {
    /// A coordinate is NaN or infinite.
    NonFiniteCoordinate { at: Location, value: f64 },
    /// A coordinate's magnitude is outside the range the exact predicates are proven for (see
    /// [`crate::MAX_COORDINATE`] and [`crate::MIN_COORDINATE`]).
    CoordinateOutOfRange { at: Location, value: f64 },
    /// The sweep would need more than `limit` events (two per input edge, four more per crossing): more than one
    /// sweep can name with its 32-bit indices. No vertex is to blame; it takes about 100 GB of memory to get here.
    TooLarge { limit: usize },
    /// The operation needed more memory than it could get (in wasm32, more than its 4 GiB), with `edges` input
    /// edges and `crossings` found when it ran out. The library stays usable.
    OutOfMemory { edges: usize, crossings: usize },
}

impl Error {
    /// The vertex the error is about, if it is about one.
    pub fn location(&self) -> Option<Location> {
        match self {
            Error::NonFiniteCoordinate { at, .. } | Error::CoordinateOutOfRange { at, .. } => {
                Some(*at)
            }
            Error::TooLarge { .. } | Error::OutOfMemory { .. } => None,
        }
    }

    /// This error with its location renumbered by `renumber` (where an operation's operands are parts of the
    /// caller's: features of a layer, lines).
    pub(crate) fn relocated(self, renumber: impl FnOnce(Location) -> Location) -> Error {
        match self {
            Error::NonFiniteCoordinate { at, value } => Error::NonFiniteCoordinate {
                at: renumber(at),
                value,
            },
            Error::CoordinateOutOfRange { at, value } => Error::CoordinateOutOfRange {
                at: renumber(at),
                value,
            },
            other => other,
        }
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::NonFiniteCoordinate { at, value } => {
                write!(f, "{at}: coordinate {value} is not a finite number")
            }
            Error::CoordinateOutOfRange { at, value } => write!(
                f,
                "{at}: coordinate {value:e} is out of range (its magnitude must be 0 or between {:e} and {:e})",
                MIN_COORDINATE,
                MAX_COORDINATE
            ),
            Error::TooLarge { limit } => write!(
                f,
                "the operation needs more than {limit} sweep events (two per edge, four more per crossing), the most \
                 one sweep can hold"
            ),
            Error::OutOfMemory { edges, crossings } => write!(
                f,
                "out of memory: the operation on {edges} edges ran out of memory with {crossings} crossings found"
            ),
        }
    }
}

impl std::error::Error for Error {}
