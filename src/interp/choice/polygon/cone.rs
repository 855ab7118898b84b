//! The cone of directions from a point within the tolerance of every vertex swept so far
//! (Chan & Chin; module docs of [`super`]), and the interval of a straight run of points that
//! it holds.

use nalgebra::Vector2;

pub(super) type V = Vector2<f64>;

pub(super) fn cross(a: V, b: V) -> f64 {
    a.x * b.y - a.y * b.x
}

/// The directions from a point whose rays pass within the tolerance of every vertex swept
/// (module docs, **Cones**): all of them until a vertex lies farther than the tolerance,
/// then the arc counter-clockwise from `lo` and clockwise from `hi` (narrower than π, unit
/// vectors), or none.
#[derive(Debug, Clone, Copy)]
pub(super) struct Cone {
    lo: V,
    hi: V,
    /// No vertex has narrowed it yet.
    pub(super) full: bool,
    /// No direction is left.
    pub(super) empty: bool,
}

/// Whether `d` lies in the arc from `lo` counter-clockwise to `hi` (narrower than π).
pub(super) fn in_arc(lo: V, hi: V, d: V) -> bool {
    cross(lo, d) >= 0.0 && cross(d, hi) >= 0.0
}

impl Cone {
    /// Every direction.
    pub(super) const FULL: Cone = Cone {
        lo: V::new(1.0, 0.0),
        hi: V::new(1.0, 0.0),
        full: true,
        empty: false,
    };

    /// One point passed by a sweep, at `d` from the apex: whether the ray towards it is in
    /// the cone (a side of zero length, `d = 0`, only while the cone is full: an outline
    /// through the same point twice), the cone then narrowed by it if it is a vertex (to the
    /// rays within `eps` of it: the directions within `asin(eps/|d|)` of `d`).
    #[inline(always)]
    pub(super) fn pass(&mut self, d: V, vertex: bool, eps: f64) -> bool {
        if self.full {
            if vertex {
                self.narrow(d, eps);
            }
            return true;
        }
        let (c1, c2) = (cross(self.lo, d), cross(d, self.hi));
        let inside = c1 >= 0.0 && c2 >= 0.0 && d != V::zeros();
        // the rays along both edges pass within eps of d: so does every ray between (both
        // arcs narrower than π), and the cone stays as it is
        let kept =
            c1.abs() <= eps && c2.abs() <= eps && self.lo.dot(&d) >= 0.0 && self.hi.dot(&d) >= 0.0;
        if vertex && !kept {
            self.narrow(d, eps);
        }
        inside
    }

    /// The points `d(0), …, d(run − 1)` (from the apex, in order along a straight line) that
    /// lie in the cone, as an interval of their indices: the cone is the intersection of two
    /// half-planes through the apex, and each holds a prefix or a suffix of points along a
    /// line, found by bisection (a point at the apex, where both hold, is the caller's to
    /// leave out: it is in the cone only while the cone is full).
    pub(super) fn interval(&self, run: usize, d: impl Fn(usize) -> V) -> (usize, usize) {
        if self.full {
            return (0, run);
        }
        if self.empty || run == 0 {
            return (0, 0);
        }
        let (lo1, hi1) = half_interval(run, |x| cross(self.lo, d(x)) >= 0.0);
        let (lo2, hi2) = half_interval(run, |x| cross(d(x), self.hi) >= 0.0);
        let lo = lo1.max(lo2);
        (lo, hi1.min(hi2).max(lo))
    }

    /// The cone narrowed to the rays that pass within `eps` of `w` (module docs).
    pub(super) fn narrow(&mut self, w: V, eps: f64) {
        let r = (w.x * w.x + w.y * w.y).sqrt();
        if r.is_nan() || r <= eps {
            return;
        }
        let u = w / r;
        let s = eps / r;
        let c = ((1.0 - s) * (1.0 + s)).sqrt();
        let lo = V::new(u.x * c + u.y * s, u.y * c - u.x * s);
        let hi = V::new(u.x * c - u.y * s, u.y * c + u.x * s);
        if self.full {
            *self = Cone {
                lo,
                hi,
                full: false,
                empty: false,
            };
            return;
        }
        // two arcs narrower than π meet in one arc, which starts at the start of one of them
        // lying in the other, and ends likewise
        let (a, b) = (self.lo, self.hi);
        let start = if in_arc(a, b, lo) {
            Some(lo)
        } else {
            in_arc(lo, hi, a).then_some(a)
        };
        let end = if in_arc(a, b, hi) {
            Some(hi)
        } else {
            in_arc(lo, hi, b).then_some(b)
        };
        match (start, end) {
            (Some(lo), Some(hi)) => {
                self.lo = lo;
                self.hi = hi;
            }
            _ => self.empty = true,
        }
    }
}

/// The indices `0..run` where `f` holds, given that it holds on a prefix or a suffix (a
/// half-plane along a line): its ends, then a bisection for the change.
pub(super) fn half_interval(run: usize, f: impl Fn(usize) -> bool) -> (usize, usize) {
    match (f(0), f(run - 1)) {
        (true, true) => (0, run),
        (false, false) => (0, 0),
        (head, _) => {
            // f(lo) == head != f(hi)
            let (mut lo, mut hi) = (0, run - 1);
            while hi - lo > 1 {
                let mid = lo + (hi - lo) / 2;
                if f(mid) == head {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            if head {
                (0, hi)
            } else {
                (hi, run)
            }
        }
    }
}
