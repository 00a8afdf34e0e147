//! Integration tests of the `zcheck` application, built as one test binary:
//! each module runs one subcommand end to end (or its library half).

mod advise_cli;
mod cli_derive;
mod design_cli;
mod double_root_cli;
mod drift;
mod emit;
mod equiv_cli;
mod extremes;
mod front_door;
mod fuzz_corpus;
mod hostile;
mod interrupt;
mod limit_class;
mod measured_cost;
mod mesh_cli;
mod order_cli;
mod params_cli;
mod plot_cli;
mod region_cli;
mod run;
mod scene_advise;
mod scene_cli;
mod solvers_cli;
mod sparse_scene;
use testkit::snapshot;
mod stability_cli;
mod tableau;
mod verify_cli;
mod warnings_cli;
