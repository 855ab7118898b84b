//! A peer library's timings beside ours ([`PeerPoint`]), read from the CSV that
//! `scripts/bench_peers.py --sweep` writes ([`parse_peers`]).

/// One size of a comparison with a peer library, both sides timed in alternating rounds
/// (`scripts/bench_peers.py --sweep`).
#[derive(Debug, Clone, PartialEq)]
pub struct PeerPoint {
    /// Our workload id.
    pub workload: String,
    /// Its size parameter.
    pub size: usize,
    /// Points (or nodes) one run produces.
    pub points: usize,
    /// Our median seconds per run.
    pub ours: f64,
    /// The peer's median seconds per run.
    pub peer: f64,
    /// The peer (`scipy`, say).
    pub peer_name: String,
}

impl PeerPoint {
    /// The peer's time over ours: above 1 we are faster.
    pub fn ratio(&self) -> f64 {
        self.peer / self.ours
    }
}

/// The header of a peer comparison's CSV ([`parse_peers`]).
pub const PEER_HEADER: &str = "workload,size,points,splinelab_seconds,peer_seconds,peer";

/// Parses a peer comparison's CSV (header [`PEER_HEADER`], one size per line), as
/// `scripts/bench_peers.py --sweep` writes it.
///
/// # Errors
/// [`crate::report::Error::Parse`] for a missing or different header, a line without six
/// fields, a size or point count that is not a count, or a time that is not finite and
/// positive.
pub fn parse_peers(what: &str, text: &str) -> crate::report::Result<Vec<PeerPoint>> {
    let bad = |line: usize, message: String| crate::report::Error::Parse {
        what: what.to_string(),
        line,
        message,
    };
    let mut lines = text.lines().enumerate();
    match lines.next() {
        Some((_, h)) if h.trim() == PEER_HEADER => {}
        Some((_, h)) => return Err(bad(1, format!("header {h:?}, expected {PEER_HEADER:?}"))),
        None => return Err(bad(1, "empty: no header".into())),
    }
    let mut out = Vec::new();
    for (i, line) in lines {
        let n = i + 1;
        if line.trim().is_empty() {
            continue;
        }
        let f: Vec<&str> = line.split(',').map(str::trim).collect();
        let [workload, size, points, ours, peer, name] = f[..] else {
            return Err(bad(n, format!("{} fields, expected 6", f.len())));
        };
        let count = |what: &str, v: &str| -> crate::report::Result<usize> {
            v.parse()
                .map_err(|_| bad(n, format!("{what} {v:?} is not a count")))
        };
        let (size, points) = (count("size", size)?, count("points", points)?);
        let time = |v: &str| -> crate::report::Result<f64> {
            match v.parse::<f64>() {
                Ok(t) if t.is_finite() && t > 0.0 => Ok(t),
                _ => Err(bad(n, format!("time {v:?} is not finite and positive"))),
            }
        };
        out.push(PeerPoint {
            workload: workload.to_string(),
            size,
            points,
            ours: time(ours)?,
            peer: time(peer)?,
            peer_name: name.to_string(),
        });
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A peer CSV that is not one: typed errors naming the line.
    #[test]
    fn bad_peer_files_name_the_line() {
        let bad: Vec<(String, usize)> = vec![
            (String::new(), 1),
            ("workload,size\n".into(), 1),
            (format!("{PEER_HEADER}\nx,1,1e-3\n"), 2),
            (format!("{PEER_HEADER}\nx,-1,1,1e-3,1e-3,scipy\n"), 2),
            (format!("{PEER_HEADER}\nx,1,1.5,1e-3,1e-3,scipy\n"), 2),
            (format!("{PEER_HEADER}\n\nx,10,10,NaN,1e-3,scipy\n"), 3),
            (format!("{PEER_HEADER}\nx,10,10,1e-3,0,scipy\n"), 2),
            (format!("{PEER_HEADER}\nx,10,10,1e-3,inf,scipy\n"), 2),
        ];
        for (text, line) in bad {
            match parse_peers("peers", &text) {
                Err(crate::report::Error::Parse { line: l, .. }) => assert_eq!(l, line, "{text:?}"),
                other => panic!("{text:?}: {other:?}"),
            }
        }
    }
}
