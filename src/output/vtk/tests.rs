//! Round-trip tests of the VTU writer: parse the XML back and decode every array.
use std::collections::HashMap;

use quick_xml::events::{BytesStart, Event};
use quick_xml::Reader;
use quick_xml::XmlVersion;

use super::*;
use crate::post::test_fixtures::{bump, jointed};

/// A `DataArray` read back from a file.
struct ArrayRead {
    /// The element the array sits in (`PointData`, `CellData`, `Points`, `Cells`).
    parent: String,
    /// Its attributes.
    attrs: HashMap<String, String>,
    /// The values as bytes, after the length header.
    payload: Vec<u8>,
}

impl ArrayRead {
    fn attr(&self, key: &str) -> &str {
        self.attrs.get(key).map_or("", String::as_str)
    }
}

/// A `.vtu` read back: the attributes of every other element by name, and the arrays.
struct VtuRead {
    elements: HashMap<String, HashMap<String, String>>,
    arrays: Vec<ArrayRead>,
}

impl VtuRead {
    fn attr(&self, element: &str, key: &str) -> Option<&str> {
        self.elements.get(element)?.get(key).map(String::as_str)
    }

    fn arrays_in(&self, parent: &str) -> Vec<&ArrayRead> {
        self.arrays.iter().filter(|a| a.parent == parent).collect()
    }

    fn array(&self, parent: &str, name: &str) -> &ArrayRead {
        self.arrays
            .iter()
            .find(|a| a.parent == parent && a.attrs.get("Name").map(String::as_str) == Some(name))
            .unwrap_or_else(|| panic!("vtu: no array {name} in {parent}"))
    }
}

fn attributes(e: &BytesStart) -> HashMap<String, String> {
    e.attributes()
        .map(|a| {
            let a = a.expect("vtu: well-formed attribute");
            let key = String::from_utf8(a.key.as_ref().to_vec()).expect("vtu: utf-8 key");
            let value = a
                .normalized_value(XmlVersion::Explicit1_0)
                .expect("vtu: value");
            (key, value.into_owned())
        })
        .collect()
}

/// Parse a `.vtu` with quick-xml's reader (which rejects mismatched end tags) and decode
/// every `DataArray`, checking its UInt64 length header against the bytes that follow.
fn read_vtu(path: &Path) -> VtuRead {
    let text = std::fs::read_to_string(path).expect("vtu: read");
    let mut reader = Reader::from_str(&text);
    let mut read = VtuRead {
        elements: HashMap::new(),
        arrays: Vec::new(),
    };
    let mut stack: Vec<String> = Vec::new();
    loop {
        match reader.read_event().expect("vtu: well-formed XML") {
            Event::Start(e) => {
                let name = String::from_utf8(e.name().as_ref().to_vec()).expect("utf-8");
                if name == "DataArray" {
                    read.arrays.push(ArrayRead {
                        parent: stack.last().cloned().unwrap_or_default(),
                        attrs: attributes(&e),
                        payload: Vec::new(),
                    });
                } else {
                    read.elements.insert(name.clone(), attributes(&e));
                }
                stack.push(name);
            }
            Event::Empty(e) => {
                let name = String::from_utf8(e.name().as_ref().to_vec()).expect("utf-8");
                read.elements.insert(name, attributes(&e));
            }
            Event::Text(t) if stack.last().map(String::as_str) == Some("DataArray") => {
                let raw = BASE64
                    .decode(t.decode().expect("vtu: text").trim())
                    .expect("vtu: base64");
                let (header, payload) = raw.split_at(8);
                let header = u64::from_le_bytes(header.try_into().expect("8 bytes"));
                assert_eq!(header, payload.len() as u64, "vtu: DataArray length header");
                read.arrays.last_mut().expect("open DataArray").payload = payload.to_vec();
            }
            Event::End(_) => {
                stack.pop();
            }
            Event::Eof => break,
            _ => {}
        }
    }
    assert!(stack.is_empty(), "vtu: unclosed elements {stack:?}");
    read
}

fn f64s(a: &ArrayRead) -> Vec<f64> {
    assert_eq!(a.attr("type"), "Float64", "vtu: type of {}", a.attr("Name"));
    a.payload
        .chunks_exact(8)
        .map(|c| f64::from_le_bytes(c.try_into().expect("8 bytes")))
        .collect()
}

fn i64s(a: &ArrayRead) -> Vec<i64> {
    assert_eq!(a.attr("type"), "Int64", "vtu: type of {}", a.attr("Name"));
    a.payload
        .chunks_exact(8)
        .map(|c| i64::from_le_bytes(c.try_into().expect("8 bytes")))
        .collect()
}

fn names(arrays: &[&ArrayRead]) -> Vec<String> {
    arrays.iter().map(|a| a.attr("Name").to_string()).collect()
}

// Values go through the file as raw little-endian bytes, so every comparison below is
// exact: the reference is the input field itself (or hand-derived numbering).
#[test]
fn vtu_round_trips() {
    let (f, e) = bump();
    let dir = tempfile::tempdir().expect("tempdir");
    let path = dir.path().join("plate.vtu");
    write_vtu(&path, &f, &e).expect("write");
    let vtu = read_vtu(&path);

    assert_eq!(vtu.attr("VTKFile", "type"), Some("UnstructuredGrid"));
    assert_eq!(vtu.attr("VTKFile", "byte_order"), Some("LittleEndian"));
    assert_eq!(vtu.attr("VTKFile", "header_type"), Some("UInt64"));
    assert_eq!(vtu.attr("Piece", "NumberOfPoints"), Some("15"));
    assert_eq!(vtu.attr("Piece", "NumberOfCells"), Some("8"));
    assert_eq!(vtu.attr("PointData", "Scalars"), Some("sigma"));
    assert_eq!(vtu.attr("PointData", "Vectors"), Some("displacement"));
    assert_eq!(vtu.attr("CellData", "Scalars"), Some("mx"));

    let point = vtu.arrays_in("PointData");
    assert_eq!(
        names(&point),
        [
            "w",
            "psi_x",
            "psi_y",
            "pressure",
            "gap",
            "V",
            "sigma",
            "s1_bottom",
            "s1_top",
            "contact",
            "displacement"
        ]
    );
    for (name, want) in [
        ("w", &f.w),
        ("psi_x", &f.psi_x),
        ("psi_y", &f.psi_y),
        ("pressure", &f.pressure),
        ("gap", &f.gap),
        ("V", &f.v),
        ("sigma", &f.sigma),
        ("s1_bottom", &f.s1_bottom),
        ("s1_top", &f.s1_top),
    ] {
        let a = vtu.array("PointData", name);
        assert_eq!(
            a.attr("NumberOfComponents"),
            "1",
            "vtu: components of {name}"
        );
        assert_eq!(&f64s(a), want, "vtu: point array {name}");
    }
    let contact = vtu.array("PointData", "contact");
    assert_eq!(contact.attr("type"), "Int32");
    let want: Vec<u8> = f
        .contact
        .iter()
        .flat_map(|&c| i32::from(c).to_le_bytes())
        .collect();
    assert_eq!(contact.payload, want, "vtu: contact flags");
    assert!(f.contact.contains(&true) && f.contact.contains(&false));
    let disp = vtu.array("PointData", "displacement");
    assert_eq!(disp.attr("NumberOfComponents"), "3");
    let want: Vec<f64> = f.w.iter().flat_map(|&w| [0.0, 0.0, -w]).collect();
    assert_eq!(f64s(disp), want, "vtu: displacement = (0, 0, -w)");

    let cell = vtu.arrays_in("CellData");
    assert_eq!(
        names(&cell),
        [
            "mx",
            "my",
            "mxy",
            "qx",
            "qy",
            "sx_bottom",
            "sy_bottom",
            "sxy_bottom",
            "s1_bottom",
            "s2_bottom",
            "angle_bottom",
            "sx_top",
            "sy_top",
            "sxy_top",
            "s1_top",
            "s2_top",
            "angle_top"
        ]
    );
    for (name, want) in [("s1_bottom", &e.bottom.s1), ("angle_top", &e.top.angle)] {
        assert_eq!(
            &f64s(vtu.array("CellData", name)),
            want,
            "vtu: cell array {name}"
        );
    }
    for (name, want) in [
        ("mx", &e.mx),
        ("my", &e.my),
        ("mxy", &e.mxy),
        ("qx", &e.qx),
        ("qy", &e.qy),
    ] {
        assert_eq!(
            &f64s(vtu.array("CellData", name)),
            want,
            "vtu: cell array {name}"
        );
    }

    let points = vtu.arrays_in("Points");
    assert_eq!(points.len(), 1);
    assert_eq!(points[0].attr("NumberOfComponents"), "3");
    let xyz = f64s(points[0]);
    let want: Vec<f64> = (0..15).flat_map(|k| [f.x[k], f.y[k], 0.0]).collect();
    assert_eq!(xyz, want, "vtu: points (x, y, 0)");

    // 4 × 2 elements, 5 nodes per row: element (ie, je) has nodes n, n + 1, n + 6, n + 5
    // with n = ie + 5 je, written out by hand.
    let conn = i64s(vtu.array("Cells", "connectivity"));
    #[rustfmt::skip]
    let want = [
        0, 1, 6, 5,   1, 2, 7, 6,   2, 3, 8, 7,   3, 4, 9, 8,
        5, 6, 11, 10, 6, 7, 12, 11, 7, 8, 13, 12, 8, 9, 14, 13,
    ];
    assert_eq!(conn, want, "vtu: connectivity");
    assert_eq!(
        i64s(vtu.array("Cells", "offsets")),
        [4, 8, 12, 16, 20, 24, 28, 32],
        "vtu: offsets"
    );
    let types = vtu.array("Cells", "types");
    assert_eq!(types.attr("type"), "UInt8");
    // 9 is VTK_QUAD in VTK's vtkCellType.h.
    assert_eq!(types.payload, [9; 8], "vtu: cell types");

    // Counter-clockwise: the shoelace area of every quad, from the points read back, is
    // positive.
    for (k, quad) in conn.chunks_exact(4).enumerate() {
        let p = |i: usize| {
            let n = quad[i % 4] as usize;
            (xyz[3 * n], xyz[3 * n + 1])
        };
        let twice_area: f64 = (0..4)
            .map(|i| {
                let ((x0, y0), (x1, y1)) = (p(i), p(i + 1));
                x0 * y1 - x1 * y0
            })
            .sum();
        assert!(
            twice_area > 0.0,
            "vtu: quad {k} is clockwise ({twice_area})"
        );
    }
}

#[test]
fn vtu_without_elements_and_bad_sizes() {
    let (f, _) = bump();
    let dir = tempfile::tempdir().expect("tempdir");
    let path = dir.path().join("nodal.vtu");
    write_vtu(&path, &f, &ElementField::default()).expect("write");
    let vtu = read_vtu(&path);
    assert_eq!(vtu.attr("Piece", "NumberOfCells"), Some("8"));
    assert!(
        !vtu.elements.contains_key("CellData"),
        "vtu: empty cell data omitted"
    );
    assert!(vtu.arrays_in("CellData").is_empty());
    assert_eq!(vtu.arrays_in("PointData").len(), 11);

    // Bad sizes are rejected before the file is created.
    let invalid = |r: Result<()>| match r {
        Err(Error::Io { source, .. }) => source.kind() == std::io::ErrorKind::InvalidInput,
        _ => false,
    };
    let bad = dir.path().join("bad.vtu");
    let mut g = f.clone();
    g.gap.pop();
    assert!(
        invalid(write_vtu(&bad, &g, &ElementField::default())),
        "short gap"
    );
    let (_, mut e) = bump();
    e.qy.pop();
    assert!(invalid(write_vtu(&bad, &f, &e)), "short qy");
    let mut h = f.clone();
    h.nx = usize::MAX;
    assert!(
        invalid(write_vtu(&bad, &h, &ElementField::default())),
        "huge grid"
    );
    assert!(!bad.exists(), "vtu: no file after a size error");

    // Unwritable location.
    let missing = dir.path().join("no/such/dir/p.vtu");
    assert!(matches!(
        write_vtu(&missing, &f, &ElementField::default()),
        Err(Error::Io { source, .. }) if source.kind() == std::io::ErrorKind::NotFound
    ));
}

/// A jointed plate: every node copy is a point (the 15 grid nodes and the 3 copies of the + side
/// of the joint), the cells of column 2 name the copies at their left corners, and each cell
/// carries its panel — ParaView draws each side with its own values.
#[test]
fn vtu_of_a_jointed_plate_has_every_copy() {
    let (f, e) = jointed();
    let dir = tempfile::tempdir().expect("tempdir");
    let path = dir.path().join("plate.vtu");
    write_vtu(&path, &f, &e).expect("write");
    let vtu = read_vtu(&path);
    assert_eq!(vtu.attr("Piece", "NumberOfPoints"), Some("18"));
    assert_eq!(vtu.attr("Piece", "NumberOfCells"), Some("8"));
    assert_eq!(f64s(vtu.array("PointData", "w")), f.w, "w of every copy");
    let points = f64s(vtu.arrays_in("Points")[0]);
    assert_eq!(
        &points[3 * 15..3 * 16],
        &[f.x[2], f.y[2], 0.0],
        "copy 15 at node 2"
    );
    let cells = i64s(vtu.array("Cells", "connectivity"));
    // Element (2, 0): nodes 2 → copy 15, 3, 8, 7 → copy 16 (hand-numbered, 5 nodes a row).
    assert_eq!(&cells[8..12], &[15, 3, 8, 16]);
    // Element (1, 0) keeps the grid nodes on its right: the − side.
    assert_eq!(&cells[4..8], &[1, 2, 7, 6]);
    let panel = vtu.array("CellData", "panel");
    assert_eq!(panel.attr("type"), "Int32");
    let want: Vec<u8> = [0, 0, 1, 1, 0, 0, 1, 1]
        .iter()
        .flat_map(|&p: &i32| p.to_le_bytes())
        .collect();
    assert_eq!(panel.payload, want);
    // A corner table naming a copy the arrays do not have is refused.
    let mut g = f.clone();
    if let Some(c) = g.corners.as_mut() {
        c[2][0] = 99;
    }
    assert!(write_vtu(&dir.path().join("bad.vtu"), &g, &e).is_err());
}

/// A map summed over many solves (the damage): the jointed grid with cell data only — the given
/// arrays (the first the active scalars) and the panels, no point data — and an array without
/// one value per element refused before the file exists.
#[test]
fn cell_vtu_holds_the_grid_and_the_cell_arrays_only() {
    let (f, _) = jointed();
    let dir = tempfile::tempdir().expect("tempdir");
    let path = dir.path().join("damage.vtu");
    let bottom: Vec<f64> = (0..8).map(|k| 0.125 * k as f64).collect();
    let top: Vec<f64> = (0..8).map(|k| 1e-3 * (k * k) as f64).collect();
    write_cell_vtu(
        &path,
        &f,
        &[("damage_bottom", &bottom), ("damage_top", &top)],
    )
    .expect("write");
    let vtu = read_vtu(&path);
    assert_eq!(vtu.attr("Piece", "NumberOfPoints"), Some("18"));
    assert_eq!(vtu.attr("Piece", "NumberOfCells"), Some("8"));
    assert!(
        vtu.arrays_in("PointData").is_empty(),
        "no solve's nodal fields"
    );
    assert!(!vtu.elements.contains_key("PointData"));
    assert_eq!(vtu.attr("CellData", "Scalars"), Some("damage_bottom"));
    assert_eq!(f64s(vtu.array("CellData", "damage_bottom")), bottom);
    assert_eq!(f64s(vtu.array("CellData", "damage_top")), top);
    assert_eq!(
        names(&vtu.arrays_in("CellData")),
        ["damage_bottom", "damage_top", "panel"]
    );
    // The same connectivity as the solve's file: element (2, 0) names the joint's copies.
    assert_eq!(
        &i64s(vtu.array("Cells", "connectivity"))[8..12],
        &[15, 3, 8, 16]
    );
    let bad = dir.path().join("bad.vtu");
    let short = &top[..7];
    assert!(matches!(
        write_cell_vtu(&bad, &f, &[("damage_top", short)]),
        Err(Error::Io { source, .. }) if source.kind() == std::io::ErrorKind::InvalidInput
    ));
    assert!(!bad.exists());
}
