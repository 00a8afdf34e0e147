//! The answers: what each command computes, as typed values and the JSON
//! and text documents it prints, for every front end alike: the command
//! line (`cli/` parses the arguments and prints), the Python module
//! (`api`) and the proof report (`paper`). Nothing here parses a command
//! line or writes to stdout.
//!
//! One word per concept, as in `poly`: the *plane* is the complex w-plane
//! of y' = λy (`poly`'s `plane`; the `zcheck region` command), the
//! *region* is the exact stability region in (Φ, a parameter) (`poly`'s
//! `region`; the `zcheck map` command, over one parameter or two).

pub(crate) mod advice;
pub(crate) mod derive;
pub(crate) mod design;
pub(crate) mod equiv;
pub(crate) mod exact;
pub(crate) mod families;
pub(crate) mod order;
pub(crate) mod plane;
pub(crate) mod region;
pub(crate) mod stability;
pub(crate) mod verify;
