//! Benchmarks of the `splinelab bench` subcommand, one JSON line each:
//!
//! - `workloads.rs`: the workloads ([`WORKLOADS`], [`Workload`], [`workload`]) and their memory
//!   traffic ([`traffic`]);
//! - `run.rs`: timing one at a size ([`run`], [`run_sized`], [`sweep`], [`BenchResult`]);
//! - `peers.rs`: a peer library's timings ([`PeerPoint`], [`parse_peers`]);
//! - `figure.rs`: the scaling figure ([`scaling_figure`]).

mod figure;
mod peers;
mod run;
mod workloads;

pub use figure::scaling_figure;
pub use peers::{parse_peers, PeerPoint, PEER_HEADER};
pub use run::{run, run_sized, sweep, BenchResult};
pub use workloads::{traffic, workload, Runner, Workload, WORKLOADS};
