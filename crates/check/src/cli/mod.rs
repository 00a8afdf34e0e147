//! One module per subcommand: its clap `Args` and its `run`.

pub mod derive;
pub mod methods;
pub mod paper;
