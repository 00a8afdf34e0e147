//! Scenes from triangle meshes (issue 25): `zcheck scene-from-mesh` and
//! `advise --scene FILE.obj`, held against quantities computed here from
//! the geometry, and every bad mesh refused at its place.

use std::path::PathBuf;

use crate::run::zcheck;
use serde_json::Value;

fn write(name: &str, text: &str) -> String {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("mesh");
    std::fs::create_dir_all(&dir).expect("temp dir");
    let path = dir.join(name);
    std::fs::write(&path, text).expect("write");
    path.to_str().expect("utf-8").to_owned()
}

/// A flat n×m grid of vertices `h` apart in z = 0, each square split along
/// its diagonal, with the first column in group `edge` and the rest in
/// `body`.
fn grid(nx: usize, ny: usize, h: f64) -> String {
    let mut s = String::new();
    for j in 0..ny {
        for i in 0..nx {
            s += &format!("v {} {} 0\n", h * i as f64, h * j as f64);
        }
    }
    let id = |i: usize, j: usize| j * nx + i + 1;
    for (group, cols) in [("edge", 0..1), ("body", 1..nx - 1)] {
        s += &format!("g {group}\n");
        for j in 0..ny - 1 {
            for i in cols.clone() {
                let (a, b, c, d) = (id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
                s += &format!("f {a} {b} {c}\nf {a}/1 {c}/2/3 {d}//4\n");
            }
        }
    }
    s
}

/// The scene `scene-from-mesh` writes for `args` (it must succeed).
#[track_caller]
fn scene(args: &[&str]) -> String {
    let mut all = vec!["scene-from-mesh"];
    all.extend(args);
    let (code, out, err) = zcheck(&all);
    assert_eq!(code, 0, "{args:?}: {err}");
    out
}

/// The scene TOML's masses and springs: (Σ kg, number of fixed masses,
/// number of springs, number of masses).
fn tally(toml_text: &str) -> (f64, usize, usize, usize) {
    assert!(!toml_text.is_empty(), "no scene written");
    let v: toml::Table = toml::from_str(toml_text).expect("the scene is TOML");
    let masses = v["mass"].as_array().expect("masses");
    let kg: f64 = masses.iter().map(|m| m["kg"].as_float().expect("kg")).sum();
    let fixed =
        masses.iter().filter(|m| m.get("fixed").and_then(|f| f.as_bool()) == Some(true)).count();
    (kg, fixed, v["spring"].as_array().expect("springs").len(), masses.len())
}

/// A 4×3 grid of 0.1 m: area 0.3 × 0.2, so its mass is the density times
/// 0.06; 3·2·2 + 2·... edges counted from the grid; the `edge` group fixes
/// the first two columns' vertices (its squares touch both), the box the
/// first column only.
#[test]
fn a_flat_grid_becomes_the_scene_its_geometry_says() {
    let (nx, ny) = (4usize, 3usize);
    let path = write("grid.obj", &grid(nx, ny, 0.1));
    let (code, out, err) =
        zcheck(&["scene-from-mesh", &path, "--density", "0.5", "--stiffness", "20"]);
    assert_eq!(code, 0, "{err}");
    let (kg, fixed, springs, masses) = tally(&out);
    assert!((kg - 0.5 * 0.3 * 0.2).abs() < 1e-12, "{kg}");
    assert_eq!((fixed, masses), (0, nx * ny));
    let edges = (nx - 1) * ny + nx * (ny - 1) + (nx - 1) * (ny - 1);
    assert_eq!(springs, edges);
    // Bending: one spring per interior edge (every edge but the boundary's).
    let boundary = 2 * (nx - 1) + 2 * (ny - 1);
    let out = scene(&[&path, "--density", "0.5", "--stiffness", "20", "--bending", "2"]);
    assert_eq!(tally(&out).2, edges + (edges - boundary));
    let out = scene(&[&path, "--density", "0.5", "--stiffness", "20", "--fix-group", "edge"]);
    assert_eq!(tally(&out).1, 2 * ny);
    let out =
        scene(&[&path, "--density", "0.5", "--stiffness", "20", "--fix-box=-1,-1,-1,0.05,1,1"]);
    assert_eq!(tally(&out).1, ny);
}

/// The example sail (a bowed 7×5 mesh, its luff pinned by a box): 30 free
/// particles in 3D, every candidate's simulation agreeing with its
/// prediction, read straight from the OBJ or from the scene it writes, with
/// the same answer.
#[test]
fn the_sail_example_agrees_with_simulation_from_the_obj_and_from_its_scene() {
    let sail = format!("{}/scenes/sail.obj", env!("CARGO_MANIFEST_DIR"));
    let opts =
        ["--density", "0.2", "--stiffness", "2", "--bending", "0.2", "--fix-box", "0,0,-1,0,1,1"];
    let mut args = vec!["advise", "--scene", sail.as_str(), "--format", "json", "--simulate-all"];
    args.extend(opts);
    let (code, out, err) = zcheck(&args);
    assert_eq!(code, 0, "{err}");
    let v: Value = serde_json::from_str(&out).expect("json");
    assert_eq!(v["dof"], 90);
    let mut checked = 0;
    for c in v["candidates"].as_array().unwrap() {
        if c["substeps_accurate"].is_u64() {
            assert_eq!(c["simulated"]["agree"], true, "{c}");
            checked += 1;
        }
    }
    assert!(checked >= 4, "{checked}");
    let mut args = vec!["scene-from-mesh", sail.as_str()];
    args.extend(opts);
    let (_, scene, _) = zcheck(&args);
    let path = write("sail.toml", &scene);
    let (_, out2, _) = zcheck(&["advise", "--scene", &path, "--format", "json", "--no-simulate"]);
    let w: Value = serde_json::from_str(&out2).expect("json");
    assert_eq!(w["recommended"], v["recommended"]);
    assert_eq!(w["modes"].as_array().unwrap().len(), v["modes"].as_array().unwrap().len());
}

/// Bad meshes and options: located, exit 2, no panic.
#[test]
fn bad_meshes_are_refused_at_their_place() {
    let ok = ["--density", "1", "--stiffness", "1"];
    for (name, text, extra, says) in [
        (
            "degenerate.obj",
            "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nf 1 2 4\nf 1 2 3\n",
            &[][..],
            "degenerate.obj:6:1: degenerate triangle (vertices 1, 2, 3)",
        ),
        (
            "repeated.obj",
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 2\n",
            &[],
            "repeated.obj:4:1: degenerate triangle",
        ),
        (
            "nofaces.obj",
            "# a point cloud\nv 0 0 0\nv 1 0 0\n",
            &[],
            "nofaces.obj:3:1: no faces (2 vertices",
        ),
        ("empty.obj", "", &[], "empty.obj:1:1: no faces"),
        (
            "range.obj",
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n",
            &[],
            "range.obj:4:7: vertex index 7: expected 1 to 3",
        ),
        ("number.obj", "v 0 0 0\nv 1 x 0\n", &[], "number.obj:2:5: `x`: expected a finite number"),
        (
            "group.obj",
            "g a\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
            &["--fix-group", "top"],
            "has no group or object `top`: expected one of a",
        ),
        (
            "box.obj",
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
            &["--fix-box", "1,0,0,0,1,1"],
            "--fix-box 1,0,0,0,1,1: expected",
        ),
    ] {
        let path = write(name, text);
        let mut args = vec!["scene-from-mesh", path.as_str()];
        args.extend(ok);
        args.extend(extra);
        let (code, _, err) = zcheck(&args);
        assert_eq!(code, 2, "{name}: {err}");
        assert!(err.contains(says), "{name}: {err}");
        assert!(!err.contains("panicked"), "{name}: {err}");
    }
    let path = write("fine.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    let (code, _, err) = zcheck(&["scene-from-mesh", &path, "--stiffness", "1"]);
    assert_eq!(code, 2);
    assert!(err.contains("a mesh scene needs --density"), "{err}");
    let (code, _, err) = zcheck(&["scene-from-mesh", &path, "--density", "0", "--stiffness", "1"]);
    assert_eq!(code, 2);
    assert!(err.contains("--density KG_PER_M2 0: expected a finite number > 0"), "{err}");
    let chain = format!("{}/scenes/chain10.toml", env!("CARGO_MANIFEST_DIR"));
    let (code, _, err) = zcheck(&["advise", "--scene", &chain, "--density", "1"]);
    assert_eq!(code, 2);
    assert!(err.contains("describe a mesh: expected --scene FILE.obj"), "{err}");
}
