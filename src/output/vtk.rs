//! ParaView output: the whole plate as an XML unstructured grid (`.vtu`) of bilinear quads with
//! nodal fields, a displacement vector for "Warp By Vector" and element stress resultants.
//!
//! The file is written element by element with quick-xml's writer. Every `DataArray` is in
//! VTK's uncompressed `binary` format: the base64 encoding of one byte stream that holds the
//! payload length in bytes (UInt64, the file's `header_type`) followed by the values, all little
//! endian — the layout VTK's own `vtkXMLWriter` produces.

use std::fs::File;
use std::io::{self, BufWriter, Write};
use std::path::Path;

use base64::engine::general_purpose::STANDARD as BASE64;
use base64::Engine as _;
use quick_xml::events::{BytesDecl, BytesText, Event};
use quick_xml::Writer;

use crate::error::{Error, Result};
use crate::post::{ElementField, FullField};

/// VTK's cell type number of the four-node quadrilateral, `VTK_QUAD` in `vtkCellType.h`.
const VTK_QUAD: u8 = 9;

/// An error about the file at `path` with an I/O-style message.
fn io_error(path: &Path, kind: std::io::ErrorKind, message: String) -> Error {
    Error::Io {
        path: path.display().to_string(),
        source: std::io::Error::new(kind, message),
    }
}

/// A number type of a VTK `DataArray`.
trait Scalar: Copy {
    /// VTK's name of the type (the `type` attribute).
    const VTK_TYPE: &'static str;
    /// Append the little-endian bytes of `self` to `out`.
    fn put(self, out: &mut Vec<u8>);
}

impl Scalar for f64 {
    const VTK_TYPE: &'static str = "Float64";
    fn put(self, out: &mut Vec<u8>) {
        out.extend_from_slice(&self.to_le_bytes());
    }
}

impl Scalar for i64 {
    const VTK_TYPE: &'static str = "Int64";
    fn put(self, out: &mut Vec<u8>) {
        out.extend_from_slice(&self.to_le_bytes());
    }
}

impl Scalar for i32 {
    const VTK_TYPE: &'static str = "Int32";
    fn put(self, out: &mut Vec<u8>) {
        out.extend_from_slice(&self.to_le_bytes());
    }
}

impl Scalar for u8 {
    const VTK_TYPE: &'static str = "UInt8";
    fn put(self, out: &mut Vec<u8>) {
        out.push(self);
    }
}

/// Write the whole plate as a VTK XML unstructured grid (`.vtu`, binary-inline base64, little
/// endian, format version 1.0) that ParaView opens.
///
/// * Points: (x, y, 0) of every node of `field`, node index i + j (nx + 1).
/// * Cells: one `VTK_QUAD` per element, nodes (i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)
///   (counter-clockwise), cell index ie + je nx.
/// * Point data: `w`, `psi_x`, `psi_y`, `pressure`, `gap`, `V`, `sigma` (active scalars),
///   `contact` (Int32, 1 in contact, 0 lifted) and the vector `displacement` = (0, 0, −w)
///   (active vectors; w is positive downward, so "Warp By Vector" shows the deflected shape
///   with z up).
/// * Cell data: `mx` (active scalars), `my`, `mxy`, `qx`, `qy` from `elements`. If `elements`
///   holds no values at all (e.g. `ElementField::default()`), the cell data are omitted.
///
/// The file is always written as XML whatever the extension of `path`; use `.vtu`.
///
/// # Errors
/// [`Error::Io`] if the file cannot be written, or (kind `InvalidInput`) if the arrays of
/// `field` do not all have (nx + 1)(ny + 1) entries or those of `elements` nx ny entries.
pub fn write_vtu(path: &Path, field: &FullField, elements: &ElementField) -> Result<()> {
    let sizes = check(path, field, elements)?;
    let io = |source| Error::Io {
        path: path.display().to_string(),
        source,
    };
    let mut out = BufWriter::new(File::create(path).map_err(io)?);
    write_xml(&mut out, field, elements, &sizes).map_err(io)?;
    out.flush().map_err(io)
}

/// The checked sizes of the grid.
struct Sizes {
    /// (nx + 1)(ny + 1).
    nodes: usize,
    /// nx ny.
    cells: usize,
    /// Whether `elements` holds values (then all five arrays have `cells` entries).
    with_cells: bool,
}

/// Check that every array has one entry per node or per element.
fn check(path: &Path, field: &FullField, elements: &ElementField) -> Result<Sizes> {
    let (nx, ny) = (field.nx, field.ny);
    let sizes = nx
        .checked_add(1)
        .zip(ny.checked_add(1))
        .and_then(|(a, b)| a.checked_mul(b))
        .zip(nx.checked_mul(ny));
    let Some((n_nodes, n_cells)) = sizes else {
        return Err(io_error(
            path,
            std::io::ErrorKind::InvalidInput,
            format!("grid of {nx} × {ny} elements is too large"),
        ));
    };

    let nodal: [(&str, usize); 12] = [
        ("x", field.x.len()),
        ("y", field.y.len()),
        ("s", field.s.len()),
        ("t", field.t.len()),
        ("w", field.w.len()),
        ("psi_x", field.psi_x.len()),
        ("psi_y", field.psi_y.len()),
        ("pressure", field.pressure.len()),
        ("gap", field.gap.len()),
        ("V", field.v.len()),
        ("sigma", field.sigma.len()),
        ("contact", field.contact.len()),
    ];
    if let Some((name, len)) = nodal.iter().find(|(_, len)| *len != n_nodes) {
        return Err(io_error(
            path,
            std::io::ErrorKind::InvalidInput,
            format!(
                "nodal array `{name}` has {len} entries, the {nx} × {ny} element grid has \
                 {n_nodes} nodes"
            ),
        ));
    }

    let with_cells = cell_arrays(elements).iter().any(|(_, v)| !v.is_empty());
    if with_cells {
        if let Some((name, v)) = cell_arrays(elements)
            .iter()
            .find(|(_, v)| v.len() != n_cells)
        {
            return Err(io_error(
                path,
                std::io::ErrorKind::InvalidInput,
                format!(
                    "element array `{name}` has {} entries, the grid has {n_cells} elements",
                    v.len()
                ),
            ));
        }
    }
    Ok(Sizes {
        nodes: n_nodes,
        cells: n_cells,
        with_cells,
    })
}

/// The cell data arrays, the active scalars first.
fn cell_arrays(elements: &ElementField) -> [(&'static str, &[f64]); 5] {
    [
        ("mx", &elements.mx),
        ("my", &elements.my),
        ("mxy", &elements.mxy),
        ("qx", &elements.qx),
        ("qy", &elements.qy),
    ]
}

/// The whole `.vtu` document; the arrays have the lengths in `sizes`.
fn write_xml<W: Write>(
    out: W,
    field: &FullField,
    elements: &ElementField,
    sizes: &Sizes,
) -> io::Result<()> {
    let mut xml = Writer::new_with_indent(out, b' ', 2);
    xml.write_event(Event::Decl(BytesDecl::new("1.0", None, None)))?;
    let (nodes, cells) = (sizes.nodes.to_string(), sizes.cells.to_string());
    xml.create_element("VTKFile")
        .with_attributes([
            ("type", "UnstructuredGrid"),
            ("version", "1.0"),
            ("byte_order", "LittleEndian"),
            ("header_type", "UInt64"),
        ])
        .write_inner_content(|xml| {
            xml.create_element("UnstructuredGrid")
                .write_inner_content(|xml| {
                    xml.create_element("Piece")
                        .with_attributes([
                            ("NumberOfPoints", nodes.as_str()),
                            ("NumberOfCells", cells.as_str()),
                        ])
                        .write_inner_content(|xml| piece(xml, field, elements, sizes))
                        .map(drop)
                })
                .map(drop)
        })
        .map(drop)
}

/// The content of the one `Piece`: point data, cell data, points and cells.
fn piece<W: Write>(
    xml: &mut Writer<W>,
    field: &FullField,
    elements: &ElementField,
    sizes: &Sizes,
) -> io::Result<()> {
    let nodal: [(&str, &[f64]); 7] = [
        ("w", &field.w),
        ("psi_x", &field.psi_x),
        ("psi_y", &field.psi_y),
        ("pressure", &field.pressure),
        ("gap", &field.gap),
        ("V", &field.v),
        ("sigma", &field.sigma),
    ];
    xml.create_element("PointData")
        .with_attributes([("Scalars", "sigma"), ("Vectors", "displacement")])
        .write_inner_content(|xml| {
            for (name, values) in nodal {
                data_array(xml, Some(name), 1, values.iter().copied())?;
            }
            let contact = field.contact.iter().map(|&c| i32::from(c));
            data_array(xml, Some("contact"), 1, contact)?;
            let displacement = field.w.iter().flat_map(|&w| [0.0, 0.0, -w]);
            data_array(xml, Some("displacement"), 3, displacement)
        })?;

    if sizes.with_cells {
        xml.create_element("CellData")
            .with_attribute(("Scalars", "mx"))
            .write_inner_content(|xml| {
                for (name, values) in cell_arrays(elements) {
                    data_array(xml, Some(name), 1, values.iter().copied())?;
                }
                Ok(())
            })?;
    }

    xml.create_element("Points").write_inner_content(|xml| {
        let points = field
            .x
            .iter()
            .zip(&field.y)
            .flat_map(|(&x, &y)| [x, y, 0.0]);
        data_array(xml, None, 3, points)
    })?;

    // Node and offset numbers fit in i64: they are below the length of an allocated array.
    let nnx = (field.nx + 1) as i64;
    let quads = (0..field.ny as i64).flat_map(|je| {
        (0..field.nx as i64).map(move |ie| {
            let n00 = ie + je * nnx;
            [n00, n00 + 1, n00 + 1 + nnx, n00 + nnx]
        })
    });
    xml.create_element("Cells").write_inner_content(|xml| {
        data_array(xml, Some("connectivity"), 1, quads.flatten())?;
        let offsets = (1..=sizes.cells as i64).map(|k| 4 * k);
        data_array(xml, Some("offsets"), 1, offsets)?;
        let types = std::iter::repeat_n(VTK_QUAD, sizes.cells);
        data_array(xml, Some("types"), 1, types)
    })?;
    Ok(())
}

/// One `DataArray` element in `binary` format (see the module documentation).
fn data_array<W: Write, T: Scalar>(
    xml: &mut Writer<W>,
    name: Option<&str>,
    components: usize,
    values: impl IntoIterator<Item = T>,
) -> io::Result<()> {
    const HEADER: usize = std::mem::size_of::<u64>();
    let mut raw = vec![0; HEADER];
    for v in values {
        v.put(&mut raw);
    }
    let payload = (raw.len() - HEADER) as u64;
    raw[..HEADER].copy_from_slice(&payload.to_le_bytes());

    let mut element = xml
        .create_element("DataArray")
        .with_attribute(("type", T::VTK_TYPE));
    if let Some(name) = name {
        element = element.with_attribute(("Name", name));
    }
    let components = components.to_string();
    element
        .with_attributes([
            ("NumberOfComponents", components.as_str()),
            ("format", "binary"),
        ])
        .write_text_content(BytesText::new(&BASE64.encode(&raw)))?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use std::collections::HashMap;

    use quick_xml::events::{BytesStart, Event};
    use quick_xml::Reader;
    use quick_xml::XmlVersion;

    use super::*;
    use crate::post::test_fixtures::bump;

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
                .find(|a| {
                    a.parent == parent && a.attrs.get("Name").map(String::as_str) == Some(name)
                })
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
        assert_eq!(names(&cell), ["mx", "my", "mxy", "qx", "qy"]);
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
        assert_eq!(vtu.arrays_in("PointData").len(), 9);

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
}
