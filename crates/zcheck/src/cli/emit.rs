//! `zcheck emit`: a method's step as a Rust or C function to paste into an
//! engine (`zcheck::emit`).

use std::process::ExitCode;

use crate::emit::{emit, Binding, Lang};
use crate::error::Error;
use crate::load::{self, LoadedMethod};
use poly::{Sym, Q};

/// The language to emit.
#[derive(Clone, Copy, clap::ValueEnum)]
pub(crate) enum Language {
    Rust,
    C,
}

/// Arguments of `zcheck emit`.
#[derive(clap::Args)]
pub(crate) struct Args {
    /// A built-in method name, a path to a `.zm` file, or a `.toml` file.
    pub method: String,
    #[arg(long, value_enum)]
    pub lang: Language,
    /// Fold the constants at this Phi (exact: integer, fraction or decimal);
    /// without it Phi, and every other parameter, is an argument.
    #[arg(long, allow_hyphen_values = true)]
    pub phi: Option<crate::values::Exact>,
    /// With --phi: a value for another parameter, `NAME=VALUE`; repeatable
    /// (a tableau's parameters take theirs with or without --phi).
    #[arg(long = "param", value_name = "NAME=VALUE")]
    pub params: Vec<String>,
}

pub(crate) fn run(args: Args) -> Result<ExitCode, Error> {
    let loaded = LoadedMethod::load_with(&args.method, &load::values_of(&args.params))?;
    let params = load::unclaimed(&args.params, |s| load::arg_name(s), &[&loaded]);
    let method = loaded.method();
    let lang = match args.lang {
        Language::Rust => Lang::Rust,
        Language::C => Lang::C,
    };
    let binding = match &args.phi {
        None => {
            if !params.is_empty() {
                return Err(Error::usage(
                    "--param needs --phi: without --phi every parameter is an argument",
                ));
            }
            Binding::Parametric
        }
        Some(phi) => {
            let mut given: Vec<(String, Q)> = vec![("Phi".to_owned(), phi.value.clone())];
            for p in &params {
                given.push(crate::values::parse_param(p)?);
            }
            let mut values: Vec<(Sym, Q)> = Vec::new();
            for sym in method.params() {
                let Some((_, v)) = given.iter().find(|(n, _)| n == sym.name()) else {
                    return Err(Error::usage(format!(
                        "method {} needs --param {}=VALUE",
                        method.name(),
                        sym.name()
                    )));
                };
                values.push((*sym, v.clone()));
            }
            for (n, _) in &given {
                if !method.params().iter().any(|s| s.name() == n) {
                    return Err(Error::usage(format!(
                        "--param {n}=...: method {} has no parameter {n}",
                        method.name()
                    )));
                }
            }
            Binding::Folded(values)
        }
    };
    super::output::emit(&emit(method, lang, &binding)?)?;
    Ok(ExitCode::SUCCESS)
}
