//! The program's commands beyond the outputs: [`user`], the subcommands on a user's own
//! data (`fit`, `fewest`, `surface`).

pub mod user;
