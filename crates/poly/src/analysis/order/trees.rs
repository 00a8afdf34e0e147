//! Rooted trees, generated once and cached: the monocolored trees of
//! Runge–Kutta order conditions (up to order [`MAX_TREE_ORDER`]), the
//! bicolored trees of partitioned methods on general partitioned systems,
//! and the bicolored trees whose adjacent vertices alternate colour (the
//! separable systems q' = f(p), p' = g(q) of splittings).
//!
//! Notation: a tree is its root's bracket around its children's strings,
//! the children sorted by (node count, then string). A monocolored vertex
//! (and a q-vertex, of f) is `[`…`]`, a p-vertex (of g) is `(`…`)`: `[]`
//! is f, `[[]]` is f'f, `[[][]]` is f''(f,f), `[[[]]]` is f'f'f.
//!
//! A forest lists its trees by (order, notation); a tree's children are
//! indices into the same list, non-decreasing, so a tree of order n is a
//! multiset of earlier trees of total order n − 1, and the generator
//! enumerates exactly those multisets. The counts are tested against
//! OEIS A000081 (1, 1, 2, 4, 9, 20, 48, 115, 286, 719, 1842) and A000151
//! (2, 4, 14, 52, 214, 916, 4116).

use std::collections::HashMap;
use std::sync::OnceLock;

use crate::error::{Error, ErrorKind};

/// The largest order of the monocolored trees generated: Runge–Kutta
/// conditions are checked up to it, so an order is proven exactly up to
/// `MAX_TREE_ORDER − 1` and "at least `MAX_TREE_ORDER`" past that.
pub const MAX_TREE_ORDER: usize = 11;

/// The largest order of the bicolored trees (general partitioned systems)
/// generated: 4116 trees of order 7.
pub const MAX_BICOLORED_ORDER: usize = 7;

/// The largest order of the alternating bicolored trees (separable
/// systems) generated.
pub const MAX_SEPARABLE_ORDER: usize = 9;

/// One rooted tree of a cached forest.
#[derive(Clone, Debug)]
pub struct Tree {
    order: usize,
    colour: u8,
    children: Vec<u32>,
    notation: String,
    differential: String,
    density: u64,
    symmetry: u64,
}

impl Tree {
    /// The number of vertices |t|.
    pub fn order(&self) -> usize {
        self.order
    }

    /// The notation: `[[][]]`, children sorted by (node count, string).
    pub fn notation(&self) -> &str {
        &self.notation
    }

    /// The elementary differential F(t), readable: `f''(f,f'f)`. For a
    /// bicolored tree, `f` for a q-vertex and `g` for a p-vertex, with the
    /// derivatives' arguments in the same order.
    pub fn differential(&self) -> &str {
        &self.differential
    }

    /// The density γ(t) = |t| · ∏ γ(children).
    pub fn density(&self) -> u64 {
        self.density
    }

    /// The symmetry σ(t): the order of t's automorphism group.
    pub fn symmetry(&self) -> u64 {
        self.symmetry
    }

    /// The colour of the root: 0 for q (or the one colour), 1 for p.
    pub fn colour(&self) -> u8 {
        self.colour
    }

    /// The children, as indices into the tree's forest.
    pub(crate) fn children(&self) -> &[u32] {
        &self.children
    }
}

/// All trees up to an order, by (order, notation).
#[derive(Debug)]
pub(crate) struct Forest {
    pub(crate) trees: Vec<Tree>,
    /// `levels[n]` is the index range of the trees of order n.
    levels: Vec<std::ops::Range<usize>>,
    by_children: HashMap<(u8, Vec<u32>), u32>,
}

/// Which trees a forest holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Kind {
    /// One colour: Runge–Kutta methods.
    Mono,
    /// Two colours, any children: partitioned methods.
    Bicolored,
    /// Two colours alternating along every edge: splittings.
    Alternating,
}

impl Forest {
    fn generate(kind: Kind, max: usize) -> Forest {
        let colours: u8 = if kind == Kind::Mono { 1 } else { 2 };
        let mut f = Forest { trees: Vec::new(), levels: Vec::new(), by_children: HashMap::new() };
        f.levels.push(0..0);
        for n in 1..=max {
            let start = f.trees.len();
            let mut level: Vec<Tree> = Vec::new();
            for c in 0..colours {
                let candidates: Vec<u32> = (0..start as u32)
                    .filter(|&i| kind != Kind::Alternating || f.trees[i as usize].colour != c)
                    .collect();
                let mut chosen = Vec::new();
                f.multisets(&candidates, 0, n - 1, &mut chosen, &mut |children| {
                    level.push(f.node(c, children.to_vec()))
                });
            }
            level.sort_by(|a, b| a.notation.cmp(&b.notation));
            for (k, t) in level.into_iter().enumerate() {
                f.by_children.insert((t.colour, t.children.clone()), (start + k) as u32);
                f.trees.push(t);
            }
            f.levels.push(start..f.trees.len());
        }
        f
    }

    /// Every non-decreasing choice from `candidates[from..]` of total order
    /// `remaining`, passed to `emit`.
    fn multisets(
        &self,
        candidates: &[u32],
        from: usize,
        remaining: usize,
        chosen: &mut Vec<u32>,
        emit: &mut dyn FnMut(&[u32]),
    ) {
        if remaining == 0 {
            emit(chosen);
            return;
        }
        for k in from..candidates.len() {
            let o = self.trees[candidates[k] as usize].order;
            if o > remaining {
                break;
            }
            chosen.push(candidates[k]);
            self.multisets(candidates, k, remaining - o, chosen, emit);
            chosen.pop();
        }
    }

    /// The tree with root colour `colour` and these children (sorted here).
    fn node(&self, colour: u8, mut children: Vec<u32>) -> Tree {
        children.sort_unstable();
        let kids: Vec<&Tree> = children.iter().map(|&i| &self.trees[i as usize]).collect();
        let (open, close, letter) = if colour == 0 { ('[', ']', "f") } else { ('(', ')', "g") };
        let mut notation = String::from(open);
        for k in &kids {
            notation.push_str(&k.notation);
        }
        notation.push(close);
        let order = 1 + kids.iter().map(|k| k.order).sum::<usize>();
        let density = order as u64 * kids.iter().map(|k| k.density).product::<u64>();
        let mut symmetry = kids.iter().map(|k| k.symmetry).product::<u64>();
        let mut run = 1u64;
        for w in children.windows(2) {
            if w[0] == w[1] {
                run += 1;
                symmetry *= run;
            } else {
                run = 1;
            }
        }
        let m = kids.len();
        let primes = if m <= 3 { "'".repeat(m) } else { format!("^({m})") };
        let differential = match m {
            0 => letter.to_owned(),
            1 => format!("{letter}{primes}{}", kids[0].differential),
            _ => {
                let args: Vec<&str> = kids.iter().map(|k| k.differential.as_str()).collect();
                format!("{letter}{primes}({})", args.join(","))
            }
        };
        Tree { order, colour, children, notation, differential, density, symmetry }
    }

    /// The trees of order `n` (empty past the forest's maximum).
    pub(crate) fn level(&self, n: usize) -> &[Tree] {
        self.levels.get(n).map_or(&[], |r| &self.trees[r.clone()])
    }

    /// The index range of the trees of order `n`.
    pub(crate) fn range(&self, n: usize) -> std::ops::Range<usize> {
        self.levels.get(n).cloned().unwrap_or(0..0)
    }

    /// The largest order held.
    pub(crate) fn max_order(&self) -> usize {
        self.levels.len() - 1
    }

    /// The index of the tree with this root colour and these children.
    pub(crate) fn find(&self, colour: u8, mut children: Vec<u32>) -> Option<u32> {
        children.sort_unstable();
        self.by_children.get(&(colour, children)).copied()
    }

    /// The trees made by grafting tree `tau` onto each vertex of tree `u`
    /// in turn (one entry per vertex; `None` past the forest's maximum).
    pub(crate) fn graft_all(&self, u: u32, tau: u32) -> Vec<Option<u32>> {
        let t = &self.trees[u as usize];
        let mut out = Vec::with_capacity(t.order);
        let mut at_root = t.children.clone();
        at_root.push(tau);
        out.push(self.find(t.colour, at_root));
        for (k, &child) in t.children.iter().enumerate() {
            for g in self.graft_all(child, tau) {
                out.push(g.and_then(|g| {
                    let mut kids = t.children.clone();
                    kids[k] = g;
                    self.find(t.colour, kids)
                }));
            }
        }
        out
    }
}

/// The cached forest of a kind, generated on first use.
pub(crate) fn forest(kind: Kind) -> &'static Forest {
    static MONO: OnceLock<Forest> = OnceLock::new();
    static BI: OnceLock<Forest> = OnceLock::new();
    static ALT: OnceLock<Forest> = OnceLock::new();
    match kind {
        Kind::Mono => MONO.get_or_init(|| Forest::generate(kind, MAX_TREE_ORDER)),
        Kind::Bicolored => BI.get_or_init(|| Forest::generate(kind, MAX_BICOLORED_ORDER)),
        Kind::Alternating => ALT.get_or_init(|| Forest::generate(kind, MAX_SEPARABLE_ORDER)),
    }
}

/// The monocolored rooted trees of order `n`, by notation; an error
/// ([`ErrorKind::TreeOrder`]) past [`MAX_TREE_ORDER`].
///
/// ```
/// let t = poly::advanced::order::trees(3)?;
/// let names: Vec<&str> = t.iter().map(|t| t.notation()).collect();
/// assert_eq!(names, ["[[[]]]", "[[][]]"]);
/// assert_eq!(t[1].differential(), "f''(f,f)");
/// assert_eq!((t[1].density(), t[1].symmetry()), (3, 2));
/// # Ok::<(), poly::Error>(())
/// ```
pub fn trees(n: usize) -> Result<&'static [Tree], Error> {
    if n > MAX_TREE_ORDER {
        return Err(Error::analysis(
            ErrorKind::TreeOrder,
            format!("trees of order {n}: expected an order of at most {MAX_TREE_ORDER}"),
        ));
    }
    Ok(forest(Kind::Mono).level(n))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn counts_match_oeis() {
        let mono: Vec<usize> = (1..=11).map(|n| forest(Kind::Mono).level(n).len()).collect();
        assert_eq!(mono, [1, 1, 2, 4, 9, 20, 48, 115, 286, 719, 1842]);
        let bi: Vec<usize> = (1..=7).map(|n| forest(Kind::Bicolored).level(n).len()).collect();
        assert_eq!(bi, [2, 4, 14, 52, 214, 916, 4116]);
        let alt: Vec<usize> = (1..=9).map(|n| forest(Kind::Alternating).level(n).len()).collect();
        assert_eq!(alt, [2, 2, 4, 8, 18, 40, 96, 230, 572]);
    }

    /// n!/(γ(t)σ(t)) is the number of increasing labellings of t, and the
    /// increasing trees on n vertices number (n − 1)!.
    #[test]
    fn densities_and_symmetries_count_labellings() {
        let mut fact = 1u64;
        for n in 1..=11u64 {
            let total: u64 = forest(Kind::Mono)
                .level(n as usize)
                .iter()
                .map(|t| {
                    let nf: u64 = (1..=n).product();
                    assert_eq!(nf % (t.density * t.symmetry), 0);
                    nf / (t.density * t.symmetry)
                })
                .sum();
            assert_eq!(total, fact, "order {n}");
            fact *= n;
        }
    }

    #[test]
    fn notation_and_differentials() {
        let l4: Vec<(&str, &str)> =
            forest(Kind::Mono).level(4).iter().map(|t| (t.notation(), t.differential())).collect();
        assert_eq!(
            l4,
            [
                ("[[[[]]]]", "f'f'f'f"),
                ("[[[][]]]", "f'f''(f,f)"),
                ("[[][[]]]", "f''(f,f'f)"),
                ("[[][][]]", "f'''(f,f,f)")
            ]
        );
        let f = forest(Kind::Mono);
        // Grafting f onto each vertex of f'f: f''(f,f) at the root, f'f'f above.
        let u = f.find(0, vec![0]).unwrap();
        let got: Vec<&str> = f
            .graft_all(u, 0)
            .into_iter()
            .map(|g| f.trees[g.unwrap() as usize].notation())
            .collect();
        assert_eq!(got, ["[[][]]", "[[[]]]"]);
        assert!(trees(12).is_err());
    }
}
