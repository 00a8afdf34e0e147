//! Generated `.zm` programs for the benches and the tests of large
//! derivations, and small programs several crates' tests share.

/// False Euler in three substeps of Φ/3, each reading the new v: at Φ = 3
/// each substep is 1, P = −I and χ = (z + 1)², a double root on the unit
/// circle that is bounded; at Φ = 6 χ is the same but P a Jordan block.
pub const FALSE_EULER_3: &str = "\
method false_euler_3
state v y
v = v - Phi/3*y
y = y + Phi/3*v
v = v - Phi/3*y
y = y + Phi/3*v
v = v - Phi/3*y
y = y + Phi/3*v
";

/// RK4 applied to a chain of `n` unit masses joined by unit springs to
/// each other and to two fixed walls, with Phi = ω₀T as the step. The
/// state is each mass's velocity `v{i}` and position `y{i}`; the four
/// stages are temporaries, so the program has `8n` stage lines, `4n` stage
/// arguments and `2n` updates.
pub fn rk4_chain(n: usize) -> String {
    let mut s = format!("method rk4_chain_{n}\nstate");
    for i in 1..=n {
        s += &format!(" v{i} y{i}");
    }
    s.push('\n');
    // The force on mass i from positions named `{pre}{j}`: unit springs to
    // the neighbours, the walls at 0 and n + 1 fixed.
    let force = |pre: &str, i: usize| {
        let mut f = format!("-2*{pre}{i}");
        if i > 1 {
            f += &format!(" + {pre}{}", i - 1);
        }
        if i < n {
            f += &format!(" + {pre}{}", i + 1);
        }
        f
    };
    for stage in 1..=4 {
        let (ys, vs) = if stage == 1 {
            ("y".to_owned(), "v".to_owned())
        } else {
            (format!("ys{stage}_"), format!("vs{stage}_"))
        };
        for i in 1..=n {
            s += &format!("kv{stage}_{i} = Phi*({})\n", force(&ys, i));
            s += &format!("ky{stage}_{i} = Phi*{vs}{i}\n");
        }
        if stage < 4 {
            let w = if stage < 3 { "0.5*" } else { "" };
            for i in 1..=n {
                s += &format!("vs{}_{i} = v{i} + {w}kv{stage}_{i}\n", stage + 1);
                s += &format!("ys{}_{i} = y{i} + {w}ky{stage}_{i}\n", stage + 1);
            }
        }
    }
    for i in 1..=n {
        s += &format!("v{i} = v{i} + (kv1_{i} + 2*kv2_{i} + 2*kv3_{i} + kv4_{i})/6\n");
        s += &format!("y{i} = y{i} + (ky1_{i} + 2*ky2_{i} + 2*ky3_{i} + ky4_{i})/6\n");
    }
    s
}

/// Symplectic Euler with its velocity update threaded through a chain of
/// `n ≥ 2` temporaries, each reading the two before it
/// (`t_k = 2 t_{k−1} − t_{k−2}`), so every one holds `v − Phi*y` and the
/// method is the two-line `v = v - Phi*y; y = y + Phi*v`.
pub fn temporary_chain(n: usize) -> String {
    assert!(n >= 2, "the chain has at least two temporaries");
    let mut s = format!("method temporary_chain_{n}\nstate v y\nt0 = v - Phi*y\nt1 = t0\n");
    for k in 2..n {
        s += &format!("t{k} = 2*t{} - t{}\n", k - 1, k - 2);
    }
    s += &format!("v = t{}\ny = y + Phi*v\n", n - 1);
    s
}
