//! The graph of the polygon's sides (module docs of [`super`]): which candidates a side may
//! join within the tolerance, found by one forward and one backward cone sweep from each
//! candidate ([`Shortcuts::new`]), and the shortest paths and cycles over it.

use super::cone::{Cone, V};

/// The most (candidate, point) pairs the forward sweeps visit: beyond, the spacing is doubled until
/// they fit (the shortcuts' memory is four bytes each).
pub const MAX_SHORTCUTS: usize = 1 << 25;

/// The most work of the closed shortest path: passes of 256 starts times the sides and
/// candidates each pass visits (beyond, the spacing is doubled).
pub const MAX_CYCLE_WORK: usize = 1 << 26;

/// A distance that no path reaches (paths have fewer than [`MAX_CANDIDATES`] sides).
pub(super) const UNREACHED: u32 = u32::MAX / 2;

/// Starts computed together in the closed shortest path (one lane each).
pub(super) const LANES: usize = 256;

#[derive(Debug, Clone, Copy)]
pub(super) struct Item {
    pub(super) p: V,
    /// Its arc position.
    pub(super) s: f64,
    pub(super) vertex: bool,
    pub(super) candidate: bool,
}

/// A count of sides in the closed shortest path's lanes: bytes while paths are short.
pub(super) trait Lane: Copy + Ord {
    /// No path (or one as long).
    const FAR: Self;
    const ZERO: Self;
    /// One side more (saturating at [`Lane::FAR`]).
    fn next(self) -> Self;
    fn wide(self) -> u32;
}

impl Lane for u8 {
    const FAR: u8 = u8::MAX;
    const ZERO: u8 = 0;
    fn next(self) -> u8 {
        self.saturating_add(1)
    }
    fn wide(self) -> u32 {
        u32::from(self)
    }
}

impl Lane for u32 {
    const FAR: u32 = UNREACHED;
    const ZERO: u32 = 0;
    fn next(self) -> u32 {
        (self + 1).min(UNREACHED)
    }
    fn wide(self) -> u32 {
        self
    }
}

/// The allowed shortcuts (module docs): for each candidate, the offsets back to the
/// candidates with a side to it.
pub(super) struct Shortcuts {
    n: usize,
    closed: bool,
    /// `preds[first[v]..first[v + 1]]`: offsets `d` of the sides `(v − d) → v`, increasing,
    /// except the sides along one reference segment ([`Along`]).
    first: Vec<usize>,
    preds: Vec<u32>,
    /// How each candidate joins the candidates before it on its reference segment.
    along: Vec<Along>,
    /// The largest forward offset of a side from each candidate.
    reach: Vec<u32>,
}

/// The sides between two candidates of one reference segment (its end vertices included)
/// are all allowed — the outline between them is that straight stretch — and are not
/// listed: each path scan carries the least distance over the segment so far (quadratic
/// lists on long straight sides otherwise).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Along {
    /// No candidate before it on its segment: no side along one.
    None,
    /// Sides from every candidate since the segment's first (a run that goes on).
    Run,
    /// Sides from every candidate since the segment's first, which it ends: a reference
    /// vertex, where the next run starts.
    End,
}

impl Along {
    /// The least over the run after this candidate: the run goes on, or starts here.
    #[inline(always)]
    pub(super) fn carry<L: Lane>(self, run: L, here: L) -> L {
        match self {
            Along::Run => run.min(here),
            Along::None | Along::End => here,
        }
    }

    /// The distance the run gives this candidate (one side more than the run's least).
    #[inline(always)]
    pub(super) fn reached<L: Lane>(self, run: L) -> L {
        match self {
            Along::None => L::FAR,
            Along::Run | Along::End => run.next(),
        }
    }
}

/// The outline as the cone sweeps read it: the items in units that bring the coordinates
/// within `[−1, 1]`, the candidates' positions, and per item the steps to the reference
/// vertices around it.
pub(super) struct Sweeps<'a> {
    items: &'a [Item],
    /// The items' points, scaled.
    p: Vec<V>,
    /// The tolerance, scaled.
    eps: f64,
    closed: bool,
    /// The candidates' positions among the items.
    at: Vec<usize>,
    /// Candidates among the items before each position, unrolled once for closed outlines.
    cum: Vec<usize>,
    /// Steps from each item to the next reference vertex after it (`usize::MAX`: none; an
    /// open outline's end).
    next: Vec<usize>,
    /// Steps from each item back to the reference vertex before it (`usize::MAX`: none).
    prev: Vec<usize>,
}

/// The forward sweeps: the sides along the first segment implied (an offset `t0`), then bit
/// `t − t0 − 1` of row `i` says candidate `i + t` is reachable forward.
pub(super) struct Forward {
    bits: Vec<u64>,
    /// Per candidate: its first word, `t0` and the last offset swept.
    rows: Vec<(usize, usize, usize)>,
    /// The largest forward offset of a side from each candidate.
    reach: Vec<u32>,
}

impl Forward {
    /// Whether candidate `i + t` is reachable forward from candidate `i`.
    pub(super) fn has(&self, i: usize, t: usize) -> bool {
        let (start, t0, len) = self.rows[i];
        t > t0 && t <= len && self.bits[start + (t - t0 - 1) / 64] >> ((t - t0 - 1) % 64) & 1 == 1
    }
}

impl<'a> Sweeps<'a> {
    pub(super) fn of(items: &'a [Item], eps: f64, closed: bool) -> Sweeps<'a> {
        // a power of two: exact, and no square overflows
        let largest = items.iter().map(|i| i.p.amax()).fold(0.0, f64::max);
        let unit = if largest > 0.0 {
            2f64.powi(-(largest.log2().ceil() as i32).clamp(-1000, 1000))
        } else {
            1.0
        };
        let m = items.len();
        let wrap = |k: usize| if k >= m { k - m } else { k };
        let mut cum = vec![0usize; 2 * m + 1];
        for x in 0..2 * m {
            cum[x + 1] = cum[x] + usize::from(items[wrap(x)].candidate);
        }
        let mut next = vec![usize::MAX; m];
        let mut prev = vec![usize::MAX; m];
        let mut seen = None;
        for x in (0..if closed { 2 * m } else { m }).rev() {
            if x < m {
                next[x] = seen.map_or(usize::MAX, |y: usize| y - x);
            }
            if items[wrap(x)].vertex {
                seen = Some(x);
            }
        }
        seen = None;
        for x in 0..if closed { 2 * m } else { m } {
            if x >= m || !closed {
                let k = wrap(x);
                prev[k] = seen.map_or(usize::MAX, |y: usize| x - y);
            }
            if items[wrap(x)].vertex {
                seen = Some(x);
            }
        }
        Sweeps {
            items,
            p: items.iter().map(|i| i.p * unit).collect(),
            eps: eps * unit,
            closed,
            at: (0..m).filter(|&k| items[k].candidate).collect(),
            cum,
            next,
            prev,
        }
    }

    pub(super) fn wrap(&self, k: usize) -> usize {
        let m = self.items.len();
        if k >= m {
            k - m
        } else {
            k
        }
    }

    /// Every candidate's forward sweep; `None` beyond [`MAX_SHORTCUTS`] points visited.
    pub(super) fn forward(&self) -> Option<Forward> {
        let (items, p, eps) = (self.items, &self.p, self.eps);
        let (n, m) = (self.at.len(), items.len());
        let mut bits: Vec<u64> = Vec::new();
        let mut rows: Vec<(usize, usize, usize)> = Vec::with_capacity(n);
        let mut reach = vec![0u32; n];
        let mut visited = 0usize;
        for (i, &a) in self.at.iter().enumerate() {
            let start = bits.len();
            let steps = if self.closed { m - 1 } else { m - 1 - a };
            let mut cone = Cone::FULL;
            // along the segment to its end vertex: no vertex between, every side allowed
            let jump = self.next[a].min(steps);
            let t0 = self.cum[a + jump + 1] - self.cum[a + 1];
            reach[i] = t0 as u32;
            if jump >= 1 {
                let e = self.wrap(a + jump);
                cone.pass(p[e] - p[a], items[e].vertex, eps);
            }
            let mut t = t0;
            let mut step = jump + 1;
            while step <= steps && !cone.empty {
                let k = self.wrap(a + step);
                // a vertex narrows the cone; the points along the segment after it do not,
                // and those in the cone are one interval of them
                let (run, (lo, hi)) = if items[k].vertex {
                    let inside = cone.pass(p[k] - p[a], true, eps);
                    (1, (0, usize::from(inside)))
                } else {
                    let run = self.next[k].min(steps + 1 - step);
                    (
                        run,
                        cone.interval(run, |x| p[self.wrap(a + step + x)] - p[a]),
                    )
                };
                let (first, last) = (t - t0, t - t0 + usize::from(items[k].candidate) * run);
                bits.resize(start + last.div_ceil(64), 0);
                for bit in first + lo..(first + hi).min(last) {
                    // no side of zero length (an outline through the same point twice, or an
                    // open one that ends where it starts): a polygon's consecutive points
                    // differ, and one point fewer draws the same
                    if p[self.wrap(a + step + bit - first)] != p[a] {
                        bits[start + bit / 64] |= 1 << (bit % 64);
                    }
                }
                t += last - first;
                step += run;
                visited = visited.saturating_add(1 + hi - lo);
            }
            if visited > MAX_SHORTCUTS {
                return None;
            }
            rows.push((start, t0, t));
        }
        Some(Forward { bits, rows, reach })
    }

    /// Every candidate's backward sweep, each side kept when the forward sweep reaches it too
    /// (past the segment's sides): the offsets of the sides into each candidate, listed by
    /// `first`, and how each joins its segment ([`Along`]); `forward.reach` raised to the
    /// sides kept.
    pub(super) fn backward(&self, forward: &mut Forward) -> (Vec<usize>, Vec<u32>, Vec<Along>) {
        let (items, p, eps) = (self.items, &self.p, self.eps);
        let (n, m) = (self.at.len(), items.len());
        let mut first = Vec::with_capacity(n + 1);
        let mut preds: Vec<u32> = Vec::new();
        let mut along = Vec::with_capacity(n);
        for (j, &b) in self.at.iter().enumerate() {
            first.push(preds.len());
            let steps = if self.closed { m - 1 } else { b };
            let jump = self.prev[b].min(steps);
            let unrolled = b + m;
            let t0 = self.cum[unrolled] - self.cum[unrolled - jump];
            along.push(match (t0, items[b].vertex) {
                (0, _) => Along::None,
                (_, true) => Along::End,
                (_, false) => Along::Run,
            });
            let mut cone = Cone::FULL;
            if jump >= 1 {
                let e = self.wrap(unrolled - jump);
                cone.pass(p[e] - p[b], items[e].vertex, eps);
            }
            let mut t = t0;
            let mut step = jump + 1;
            while step <= steps && !cone.empty {
                let k = self.wrap(unrolled - step);
                let (run, (lo, hi)) = if items[k].vertex {
                    let inside = cone.pass(p[k] - p[b], true, eps);
                    (1, (0, usize::from(inside)))
                } else {
                    let run = self.prev[k].min(steps + 1 - step);
                    (
                        run,
                        cone.interval(run, |x| p[self.wrap(unrolled - step - x)] - p[b]),
                    )
                };
                if items[k].candidate {
                    for x in lo..hi {
                        let t = t + x + 1;
                        let i = if j >= t { j - t } else { j + n - t };
                        let moved = p[self.wrap(unrolled - step - x)] != p[b];
                        if moved && forward.has(i, t) {
                            preds.push(t as u32);
                            forward.reach[i] = forward.reach[i].max(t as u32);
                        }
                    }
                    t += run;
                }
                step += run;
            }
        }
        first.push(preds.len());
        (first, preds, along)
    }
}

impl Shortcuts {
    /// The shortcuts among the candidates of `items` within `eps`; `None` if the forward
    /// sweeps visit more than [`MAX_SHORTCUTS`] points.
    pub(super) fn new(items: &[Item], eps: f64, closed: bool) -> Option<Shortcuts> {
        let outline = Sweeps::of(items, eps, closed);
        let mut forward = outline.forward()?;
        let (first, preds, along) = outline.backward(&mut forward);
        Some(Shortcuts {
            n: outline.at.len(),
            closed,
            first,
            preds,
            along,
            reach: forward.reach,
        })
    }

    pub(super) fn preds(&self, v: usize) -> &[u32] {
        &self.preds[self.first[v]..self.first[v + 1]]
    }

    /// Open: the candidates of the fewest sides from the first to the last, at least
    /// `min_points` of them.
    pub(super) fn shortest_path(&self, min_points: usize) -> Option<Vec<usize>> {
        let n = self.n;
        let mut dist = vec![UNREACHED; n];
        let mut parent = vec![usize::MAX; n];
        dist[0] = 0;
        // the least distance along the current segment and where
        let mut run = (0, 0);
        for v in 1..n {
            if self.along[v] != Along::None && run.0 + 1 < dist[v] {
                dist[v] = run.0 + 1;
                parent[v] = run.1;
            }
            for &d in self.preds(v) {
                let u = v - d as usize;
                if dist[u] + 1 < dist[v] {
                    dist[v] = dist[u] + 1;
                    parent[v] = u;
                }
            }
            if self.along[v] != Along::Run || dist[v] < run.0 {
                run = (dist[v], v);
            }
        }
        if dist[n - 1] >= UNREACHED {
            return None;
        }
        if (dist[n - 1] as usize) + 1 < min_points {
            return self.at_least(0, n - 1, min_points - 1);
        }
        let mut path = vec![n - 1];
        while let Some(&v) = path.last().filter(|&&v| v != 0) {
            path.push(parent[v]);
        }
        path.reverse();
        Some(path)
    }

    /// Closed: the candidates of the shortest closed path, at least `min_points` of them
    /// (module docs); `None` beyond [`MAX_CYCLE_WORK`], `Some(None)` if there is none.
    pub(super) fn shortest_cycle(&self, min_points: usize) -> Option<Option<Vec<usize>>> {
        let n = self.n;
        // the candidate k passed by the fewest sides: cover[k] counts the starts a with a
        // side from a beyond k (a difference array over the cyclic positions)
        let mut diff = vec![0i64; n + 1];
        for a in 0..n {
            let r = self.reach[a] as usize;
            if r >= 2 {
                // k = a + 1 ..= a + r − 1, wrapped
                let (s, e) = (a + 1, a + r);
                if s >= n {
                    diff[s - n] += 1;
                    diff[e - n] -= 1;
                } else if e <= n {
                    diff[s] += 1;
                    diff[e] -= 1;
                } else {
                    diff[s] += 1;
                    diff[n] -= 1;
                    diff[0] += 1;
                    diff[e - n] -= 1;
                }
            }
        }
        let mut k = 0;
        let mut best = i64::MAX;
        let mut acc = 0;
        for (i, d) in diff.iter().take(n).enumerate() {
            acc += d;
            if acc < best {
                best = acc;
                k = i;
            }
        }
        // the starts, as offsets back from k (0: k itself)
        let mut back: Vec<usize> = (0..n)
            .filter_map(|a| {
                let off = (k + n - a) % n;
                (off == 0 || off < self.reach[a] as usize).then_some(off)
            })
            .collect();
        back.sort_unstable_by(|x, y| y.cmp(x));
        let passes = back.len().div_ceil(LANES);
        if passes.saturating_mul(self.preds.len() + self.n) > MAX_CYCLE_WORK {
            return None;
        }
        Some(self.cycle_from_starts(k, &back, min_points))
    }

    /// The shortest closed path over the starts `back` (offsets back from `k`, decreasing).
    pub(super) fn cycle_from_starts(
        &self,
        k: usize,
        back: &[usize],
        min_points: usize,
    ) -> Option<Vec<usize>> {
        let n = self.n;
        // bytes first (as many lanes to an instruction as fit), wider if a path is as long
        let mut answer = self.least_cycle::<u8>(k, back);
        if answer.is_none_or(|(l, _)| l >= u8::FAR.wide()) {
            answer = self.least_cycle::<u32>(k, back);
        }
        let (length, off) = answer?;
        if (length as usize) < min_points {
            // fewer sides than a polygon needs (a thin outline): the fewest of at least
            // `min_points` from every start
            let mut path = back
                .iter()
                .filter_map(|&off| {
                    let start = (k + n - off) % n;
                    self.at_least(start, start + n, min_points)
                })
                .min_by_key(|p| p.len())?;
            path.pop();
            return Some(path);
        }
        self.path_from((k + n - off) % n)
    }

    /// The least of [`Shortcuts::cycles`] over the starts `back` and its start's offset.
    pub(super) fn least_cycle<L: Lane>(&self, k: usize, back: &[usize]) -> Option<(u32, usize)> {
        let mut answer: Option<(u32, usize)> = None;
        for chunk in back.chunks(LANES) {
            for (lane, length) in self.cycles::<L>(k, chunk).into_iter().enumerate() {
                let length = length.wide();
                if length < UNREACHED && answer.is_none_or(|(l, _)| length < l) {
                    answer = Some((length, chunk[lane]));
                }
            }
        }
        answer
    }

    /// The fewest sides of a closed path from each start (`k` less each offset of `back`,
    /// decreasing) back to itself, all in one pass over the positions unrolled from the
    /// first start to the last start plus `n` ([`Lane::FAR`] for none, or as many as that).
    pub(super) fn cycles<L: Lane>(&self, k: usize, back: &[usize]) -> Vec<L> {
        let n = self.n;
        let lanes = back.len();
        // rows in a ring of a power of two positions, a distance per lane
        let window =
            (self.preds.iter().copied().max().unwrap_or(1) as usize + 1).next_power_of_two();
        let first = k as i64 - back[0] as i64;
        let last = k as i64 + n as i64 - *back.last().unwrap_or(&0) as i64;
        let mut rows = vec![L::FAR; window * lanes];
        let mut out = vec![L::FAR; lanes];
        let slot = |p: i64| ((p - first) as usize & (window - 1)) * lanes;
        let mut row = vec![L::FAR; lanes];
        // the least distance along the current segment, per lane
        let mut run = vec![L::FAR; lanes];
        for p in first..=last {
            let v = p.rem_euclid(n as i64) as usize;
            let along = self.along[v];
            for (r, &s) in row.iter_mut().zip(&run) {
                *r = along.reached(s);
            }
            for &d in self.preds(v) {
                let q = p - d as i64;
                if q < first {
                    continue;
                }
                let src = &rows[slot(q)..slot(q) + lanes];
                for (r, &s) in row.iter_mut().zip(src) {
                    *r = (*r).min(s.next());
                }
            }
            for (lane, &off) in back.iter().enumerate() {
                let start = k as i64 - off as i64;
                if p == start {
                    row[lane] = L::ZERO;
                } else if p == start + n as i64 {
                    out[lane] = row[lane];
                }
            }
            for (r, &h) in run.iter_mut().zip(&row) {
                *r = along.carry(*r, h);
            }
            let at = slot(p);
            rows[at..at + lanes].copy_from_slice(&row);
        }
        out
    }

    /// The shortest closed path from `start` (its candidates, `start` once).
    pub(super) fn path_from(&self, start: usize) -> Option<Vec<usize>> {
        let n = self.n;
        let mut dist = vec![UNREACHED; n + 1];
        let mut parent = vec![usize::MAX; n + 1];
        dist[0] = 0;
        let mut run = (0, 0);
        for p in 1..=n {
            let v = (start + p) % n;
            let along = self.along[v];
            if along != Along::None && run.0 + 1 < dist[p] {
                dist[p] = run.0 + 1;
                parent[p] = run.1;
            }
            for &d in self.preds(v) {
                let Some(q) = p.checked_sub(d as usize) else {
                    continue;
                };
                if dist[q] + 1 < dist[p] {
                    dist[p] = dist[q] + 1;
                    parent[p] = q;
                }
            }
            if along != Along::Run || dist[p] < run.0 {
                run = (dist[p], p);
            }
        }
        if dist[n] >= UNREACHED {
            return None;
        }
        let mut path = Vec::new();
        let mut p = parent[n];
        while p != 0 {
            path.push((start + p) % n);
            p = parent[p];
        }
        path.push(start);
        path.reverse();
        Some(path)
    }

    /// The fewest sides, at least `min_sides`, from unrolled position `from` to `to`
    /// (breadth-first, layer by layer): the candidates of the path, both ends included.
    pub(super) fn at_least(&self, from: usize, to: usize, min_sides: usize) -> Option<Vec<usize>> {
        let span = to - from;
        let mut layers: Vec<Vec<u32>> = Vec::new();
        let mut current = vec![u32::MAX; span + 1];
        current[0] = 0;
        for _ in 0..span {
            let mut next = vec![u32::MAX; span + 1];
            // a position of the current segment in the current layer
            let mut run = (current[0] != u32::MAX).then_some(0);
            for (p, parent) in next.iter_mut().enumerate().skip(1) {
                let v = (from + p) % self.n;
                let along = self.along[v];
                let reached = self
                    .preds(v)
                    .iter()
                    .filter_map(|&d| p.checked_sub(d as usize))
                    .find(|&q| current[q] != u32::MAX)
                    .or(run.filter(|_| along != Along::None));
                if let Some(q) = reached {
                    *parent = q as u32;
                }
                let here = (current[p] != u32::MAX).then_some(p);
                run = match along {
                    Along::Run => run.or(here),
                    Along::None | Along::End => here,
                };
            }
            layers.push(std::mem::replace(&mut current, next));
            if current[span] != u32::MAX && layers.len() >= min_sides {
                let mut path = vec![span];
                let mut p = span;
                for layer in (1..=layers.len()).rev() {
                    let q = if layer == layers.len() {
                        current[p]
                    } else {
                        layers[layer][p]
                    } as usize;
                    path.push(q);
                    p = q;
                }
                path.reverse();
                let wrap = |p: usize| {
                    if self.closed {
                        (from + p) % self.n
                    } else {
                        from + p
                    }
                };
                return Some(path.into_iter().map(wrap).collect());
            }
            if current.iter().all(|&q| q == u32::MAX) {
                return None;
            }
        }
        None
    }
}
