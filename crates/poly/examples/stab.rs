use std::time::Instant;
fn main() {
    for path in std::env::args().skip(1) {
        let src = std::fs::read_to_string(&path).unwrap();
        let m = poly::Method::parse(&path, &src).unwrap();
        let d = poly::derive(&m).unwrap();
        let mut best = std::time::Duration::MAX;
        let mut r = None;
        for _ in 0..5 {
            let t = Instant::now();
            r = Some(poly::stability::analyze(&d.charpoly).unwrap());
            best = best.min(t.elapsed());
        }
        let r = r.unwrap();
        let r2 = poly::stability::analyze_derivation(&d, &Default::default()).unwrap();
        println!(
            "{path}: deg {} analyze min {:?} | {} {:?} P: {:?}",
            r.degree,
            best,
            r.stability.name(),
            r.phi_max().map(|p| p.to_string()),
            r2.bounded_at_phi_max()
        );
        if std::env::var("V").is_ok() {
            println!(
                "  classes: {:?}",
                r.intervals
                    .iter()
                    .map(|i| (i.lo.to_decimal(4), i.class.name(), i.counts))
                    .collect::<Vec<_>>()
            );
            println!(
                "  stable: {:?}",
                r.stable_intervals
                    .iter()
                    .map(|s| (s.lo.to_decimal(4), s.hi.as_ref().map(|h| h.to_decimal(4))))
                    .collect::<Vec<_>>()
            );
            println!("  critical points: {}", r.critical_points.len());
        }
    }
}
