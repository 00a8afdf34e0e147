//! One module per subcommand: its clap `Args` and its `run`.

pub mod advise;
pub mod derive;
pub mod drift;
pub mod emit;
pub mod equiv;
pub mod from_tableau;
pub mod map;
pub mod methods;
pub mod output;
pub mod overview;
pub mod paper;
pub mod plot;
pub mod scene;
pub mod stability;
pub mod tradeoff;
pub mod values;
pub mod verify;
