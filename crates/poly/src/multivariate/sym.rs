//! Interned symbol names (`Phi`, `D`, `z`, ...).
//!
//! A [`Sym`] is a small copyable id; the name lives in a process-wide table
//! that only grows. Symbols compare by id for speed inside monomials, while
//! printing orders terms by name so that output never depends on the order
//! in which names were first seen.

use std::collections::HashMap;
use std::fmt;
use std::sync::{Mutex, OnceLock};

/// A named indeterminate of a [`crate::Poly`].
#[derive(Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Sym(u32);

struct Table {
    names: Vec<&'static str>,
    ids: HashMap<&'static str, u32>,
}

fn table() -> &'static Mutex<Table> {
    static TABLE: OnceLock<Mutex<Table>> = OnceLock::new();
    TABLE.get_or_init(|| Mutex::new(Table { names: Vec::new(), ids: HashMap::new() }))
}

impl Sym {
    /// The symbol with this name, created on first use.
    pub fn new(name: &str) -> Sym {
        let mut t = table().lock().unwrap_or_else(|e| e.into_inner());
        if let Some(&id) = t.ids.get(name) {
            return Sym(id);
        }
        // Names are few (one per symbol a user ever writes), so leaking them
        // buys `&'static str` names without lifetimes on every polynomial.
        let leaked: &'static str = Box::leak(name.to_owned().into_boxed_str());
        let id = t.names.len() as u32;
        t.names.push(leaked);
        t.ids.insert(leaked, id);
        Sym(id)
    }

    /// The symbol's name.
    pub fn name(self) -> &'static str {
        let t = table().lock().unwrap_or_else(|e| e.into_inner());
        t.names[self.0 as usize]
    }

    /// The step-size symbol Φ = ω₀T, spelled `Phi` in `.zm` files.
    pub fn phi() -> Sym {
        Sym::new("Phi")
    }

    /// w = hλ, the step of the scalar test equation y' = λy (a complex
    /// number), spelled `w` in `.zm` files.
    pub fn w() -> Sym {
        Sym::new("w")
    }

    /// The z-transform variable.
    pub fn z() -> Sym {
        Sym::new("z")
    }
}

impl fmt::Debug for Sym {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl fmt::Display for Sym {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}
