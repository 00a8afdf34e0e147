//! Scenes from triangle meshes: `zcheck scene-from-mesh FILE.obj` and
//! `advise --scene FILE.obj`. Every vertex a face uses becomes a particle
//! with `pos`, its mass the area density times a third of the area of its
//! triangles; every edge becomes a spring; optionally, a bending spring
//! joins the two far corners of the triangles on each side of an interior
//! edge; vertices are fixed by group name (`g` / `o`) or by a box.
//!
//! The reader takes the OBJ subset a mesh needs (`v`, `f`, `g`, `o`; the
//! rest is skipped) and keeps every line number, so a degenerate triangle,
//! an index out of range or a malformed number is reported at its
//! file:line:column. DESIGN.md says why it is not `tobj`.

use std::collections::{BTreeMap, BTreeSet};
use std::fmt::Write as _;
use std::path::Path;

use crate::error::Error;

/// How a mesh becomes a scene.
#[derive(Clone, Debug, clap::Args)]
pub(crate) struct MeshOptions {
    /// Area density of the surface, kg/m² (a mesh only).
    #[arg(long)]
    pub density: Option<f64>,
    /// Stiffness of every edge spring, N/m (a mesh only).
    #[arg(long)]
    pub stiffness: Option<f64>,
    /// Add bending springs of this stiffness (N/m) across every interior
    /// edge (a mesh only).
    #[arg(long)]
    pub bending: Option<f64>,
    /// Damping ratio of every spring (a mesh only).
    #[arg(long)]
    pub spring_ratio: Option<f64>,
    /// Fix the vertices of this OBJ group or object (`g`/`o` name); may be
    /// repeated (a mesh only).
    #[arg(long = "fix-group")]
    pub fix_group: Vec<String>,
    /// Fix the vertices inside the box XMIN,YMIN,ZMIN,XMAX,YMAX,ZMAX (a mesh
    /// only).
    #[arg(long, value_delimiter = ',', value_name = "XMIN,YMIN,ZMIN,XMAX,YMAX,ZMAX")]
    pub fix_box: Option<Vec<f64>>,
    /// The scene's tick rate, Hz (a mesh only; default 60).
    #[arg(long = "tick-hz")]
    pub tick_hz: Option<f64>,
}

/// One face as read: its vertices (0-based) and where it stands.
struct Face {
    vertices: Vec<usize>,
    line: usize,
    groups: Vec<String>,
}

/// The largest OBJ file read, bytes.
const MAX_MESH_BYTES: u64 = 256 << 20;

/// Reads `path` and writes the scene TOML for it.
pub(crate) fn scene_toml(path: &Path, opts: &MeshOptions) -> Result<String, Error> {
    let shown = path.display().to_string();
    let meta =
        std::fs::metadata(path).map_err(|e| Error::io(format!("{shown}: cannot read"), e))?;
    if meta.len() > MAX_MESH_BYTES {
        return Err(Error::usage(format!(
            "{shown}: {} bytes: expected a mesh of at most {MAX_MESH_BYTES} bytes",
            meta.len()
        )));
    }
    let bytes = std::fs::read(path).map_err(|e| Error::io(format!("{shown}: cannot read"), e))?;
    let text = String::from_utf8(bytes).map_err(|e| {
        let good = e.utf8_error().valid_up_to();
        let (line, col) =
            crate::error::line_col(&String::from_utf8_lossy(&e.as_bytes()[..good]), good);
        Error::file(&shown, line, col, "invalid UTF-8: expected a text OBJ file")
    })?;
    scene_from_text(&shown, &text, opts)
}

fn positive(what: &str, v: Option<f64>) -> Result<f64, Error> {
    match v {
        Some(x) if x.is_finite() && x > 0.0 => Ok(x),
        Some(x) => Err(Error::usage(format!("{what} {x}: expected a finite number > 0"))),
        None => Err(Error::usage(format!("a mesh scene needs {what}"))),
    }
}

/// The scene TOML of the OBJ text (`shown` names the file in errors).
pub(crate) fn scene_from_text(
    shown: &str,
    text: &str,
    opts: &MeshOptions,
) -> Result<String, Error> {
    let density = positive("--density KG_PER_M2", opts.density)?;
    let stiffness = positive("--stiffness N_PER_M", opts.stiffness)?;
    let bending = match opts.bending {
        Some(b) => Some(positive("--bending N_PER_M", Some(b))?),
        None => None,
    };
    if let Some(r) = opts.spring_ratio {
        if !(r.is_finite() && (0.0..1.0).contains(&r)) {
            return Err(Error::usage(format!("--spring-ratio {r}: expected 0 <= ratio < 1")));
        }
    }
    let tick = positive("--tick-hz HZ", Some(opts.tick_hz.unwrap_or(60.0)))?;
    let (positions, faces) = read_obj(shown, text)?;
    // Triangles (polygons fanned from their first corner), each checked.
    let scale2 = bbox_diagonal2(&positions).max(f64::MIN_POSITIVE);
    let mut triangles: Vec<[usize; 3]> = Vec::new();
    let mut area = vec![0.0f64; positions.len()];
    for f in &faces {
        for k in 1..f.vertices.len() - 1 {
            let t = [f.vertices[0], f.vertices[k], f.vertices[k + 1]];
            let a = triangle_area(&positions, t);
            if a.is_nan() || a * a <= 1e-24 * scale2 * scale2 {
                return Err(Error::file(
                    shown,
                    f.line,
                    1,
                    &format!(
                        "degenerate triangle (vertices {}, {}, {}): its area is {a:e}, expected a triangle of non-zero area",
                        t[0] + 1,
                        t[1] + 1,
                        t[2] + 1
                    ),
                ));
            }
            for &v in &t {
                area[v] += a / 3.0;
            }
            triangles.push(t);
        }
    }
    // Fixed vertices: by group, by box.
    let groups: BTreeSet<&str> =
        faces.iter().flat_map(|f| f.groups.iter().map(String::as_str)).collect();
    let mut fixed = vec![false; positions.len()];
    for g in &opts.fix_group {
        if !groups.contains(g.as_str()) {
            let known: Vec<&str> = groups.iter().copied().collect();
            return Err(Error::usage(format!(
                "--fix-group {g}: {shown} has no group or object `{g}`: expected one of {}",
                if known.is_empty() {
                    "(none: the file has no `g` or `o` line)".to_owned()
                } else {
                    known.join(", ")
                }
            )));
        }
        for f in faces.iter().filter(|f| f.groups.iter().any(|x| x == g)) {
            for &v in &f.vertices {
                fixed[v] = true;
            }
        }
    }
    if let Some(b) = &opts.fix_box {
        if b.len() != 6
            || b.iter().any(|x| !x.is_finite())
            || b[0] > b[3]
            || b[1] > b[4]
            || b[2] > b[5]
        {
            return Err(Error::usage(format!(
                "--fix-box {}: expected XMIN,YMIN,ZMIN,XMAX,YMAX,ZMAX with each min <= max",
                b.iter().map(|x| x.to_string()).collect::<Vec<_>>().join(",")
            )));
        }
        for (v, p) in positions.iter().enumerate() {
            if (0..3).all(|k| b[k] <= p[k] && p[k] <= b[k + 3]) {
                fixed[v] = true;
            }
        }
    }
    // Edges, with the triangles on each side; bending pairs across
    // interior edges.
    let mut edges: BTreeMap<(usize, usize), Vec<usize>> = BTreeMap::new();
    for t in &triangles {
        for k in 0..3 {
            let (a, b) = (t[k], t[(k + 1) % 3]);
            edges.entry((a.min(b), a.max(b))).or_default().push(t[(k + 2) % 3]);
        }
    }
    let mut springs: BTreeMap<(usize, usize), f64> =
        edges.keys().map(|&e| (e, stiffness)).collect();
    if let Some(kb) = bending {
        for opposite in edges.values().filter(|o| o.len() == 2) {
            let (a, b) = (opposite[0].min(opposite[1]), opposite[0].max(opposite[1]));
            if a != b {
                springs.entry((a, b)).or_insert(kb);
            }
        }
    }
    let used: BTreeSet<usize> = triangles.iter().flatten().copied().collect();
    let mut out = String::new();
    let _ = writeln!(
        out,
        "# Generated by zcheck scene-from-mesh from {shown}: {} particles, {} triangles, {} springs\n# ({} kg/m², {stiffness} N/m per edge{}).",
        used.len(),
        triangles.len(),
        springs.len(),
        density,
        bending.map_or(String::new(), |b| format!(", {b} N/m bending"))
    );
    let _ = writeln!(out, "tick_hz = {tick}\nduration_s = 1");
    for &v in &used {
        let p = positions[v];
        let _ = writeln!(
            out,
            "[[mass]]\nname = \"v{}\"\nkg = {}\npos = [{}, {}, {}]{}",
            v + 1,
            density * area[v],
            p[0],
            p[1],
            p[2],
            if fixed[v] { "\nfixed = true" } else { "" }
        );
    }
    for (&(a, b), k) in &springs {
        let _ = writeln!(
            out,
            "[[spring]]\nbetween = [\"v{}\", \"v{}\"]\nstiffness = {k}",
            a + 1,
            b + 1
        );
        if let Some(r) = opts.spring_ratio {
            let _ = writeln!(out, "ratio = {r}");
        }
    }
    Ok(out)
}

fn bbox_diagonal2(p: &[[f64; 3]]) -> f64 {
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    for q in p {
        for k in 0..3 {
            lo[k] = lo[k].min(q[k]);
            hi[k] = hi[k].max(q[k]);
        }
    }
    (0..3).map(|k| (hi[k] - lo[k]).powi(2)).sum()
}

fn triangle_area(p: &[[f64; 3]], t: [usize; 3]) -> f64 {
    let (a, b, c) = (p[t[0]], p[t[1]], p[t[2]]);
    let u = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
    let v = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
    let n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
    0.5 * (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt()
}

/// The vertices and faces of OBJ text, located.
fn read_obj(shown: &str, text: &str) -> Result<(Vec<[f64; 3]>, Vec<Face>), Error> {
    let mut positions: Vec<[f64; 3]> = Vec::new();
    let mut faces: Vec<Face> = Vec::new();
    let mut groups: Vec<String> = Vec::new();
    for (i, raw) in text.lines().enumerate() {
        let line_no = i + 1;
        let line = raw.split('#').next().unwrap_or("");
        let mut words = line.split_whitespace();
        let Some(kind) = words.next() else { continue };
        // The column of each word, for messages.
        let col_of = |w: &str| (w.as_ptr() as usize - raw.as_ptr() as usize) + 1;
        match kind {
            "v" => {
                let mut p = [0.0; 3];
                for (k, slot) in p.iter_mut().enumerate() {
                    let Some(w) = words.next() else {
                        return Err(Error::file(
                            shown,
                            line_no,
                            raw.len() + 1,
                            &format!("vertex with {k} coordinates: expected `v X Y Z`"),
                        ));
                    };
                    *slot = w.parse::<f64>().ok().filter(|x| x.is_finite()).ok_or_else(|| {
                        Error::file(
                            shown,
                            line_no,
                            col_of(w),
                            &format!("`{w}`: expected a finite number"),
                        )
                    })?;
                }
                positions.push(p);
            }
            "f" => {
                let mut vertices = Vec::new();
                for w in words {
                    let index = w.split('/').next().unwrap_or("");
                    let n: i64 = index.parse().map_err(|_| {
                        Error::file(
                            shown,
                            line_no,
                            col_of(w),
                            &format!(
                                "`{w}`: expected a vertex index (`i`, `i/t`, `i//n` or `i/t/n`)"
                            ),
                        )
                    })?;
                    let len = positions.len() as i64;
                    let v = if n > 0 { n - 1 } else { len + n };
                    if n == 0 || v < 0 || v >= len {
                        return Err(Error::file(
                            shown,
                            line_no,
                            col_of(w),
                            &format!("vertex index {n}: expected 1 to {len} (or -1 to -{len}), a vertex defined above"),
                        ));
                    }
                    vertices.push(v as usize);
                }
                if vertices.len() < 3 {
                    return Err(Error::file(
                        shown,
                        line_no,
                        1,
                        &format!("a face of {} vertices: expected at least 3", vertices.len()),
                    ));
                }
                faces.push(Face { vertices, line: line_no, groups: groups.clone() });
            }
            "g" | "o" => {
                groups = words.map(str::to_owned).collect();
            }
            _ => {}
        }
    }
    if faces.is_empty() {
        let lines = text.lines().count().max(1);
        return Err(Error::file(
            shown,
            lines,
            1,
            &format!(
                "no faces ({} vertices, no `f` line): expected a triangle mesh",
                positions.len()
            ),
        ));
    }
    Ok((positions, faces))
}

impl MeshOptions {
    /// Whether any mesh option is given (they belong to a mesh only).
    pub(crate) fn any(&self) -> bool {
        self.density.is_some()
            || self.stiffness.is_some()
            || self.bending.is_some()
            || self.spring_ratio.is_some()
            || !self.fix_group.is_empty()
            || self.fix_box.is_some()
            || self.tick_hz.is_some()
    }
}

/// Whether a scene path names an OBJ mesh.
pub(crate) fn is_mesh(path: &Path) -> bool {
    path.extension().is_some_and(|e| e.eq_ignore_ascii_case("obj"))
}
