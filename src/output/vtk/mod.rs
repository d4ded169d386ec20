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
/// * Points: (x, y, 0) of every node copy of `field`: the grid nodes i + j (nx + 1), then the
///   extra copies along the joints that cut a jointed plate (at the same coordinates as their
///   grid node), so each side of a joint is its own point and ParaView shows the step.
/// * Cells: one `VTK_QUAD` per element, its own corners counter-clockwise from (i, j)
///   ([`FullField::element_nodes`]), cell index ie + je nx.
/// * Point data: `w`, `psi_x`, `psi_y`, `pressure`, `gap`, `V`, `sigma` (active scalars),
///   `s1_bottom`, `s1_top` (the faces' largest principal stresses recovered at the nodes),
///   `contact` (Int32, 1 in contact, 0 lifted) and the vector `displacement` = (0, 0, −w)
///   (active vectors; w is positive downward, so "Warp By Vector" shows the deflected shape
///   with z up).
/// * Cell data: `mx` (active scalars), `my`, `mxy`, `qx`, `qy` and the bottom and top faces'
///   stresses (`sx_bottom`, …, `s1_top`, `angle_top`) from `elements`, and on a plate with
///   panels the `panel` (Int32, column + row · columns) of each element. If `elements` holds
///   no values at all (e.g. `ElementField::default()`), the cell data are omitted.
///
/// The file is always written as XML whatever the extension of `path`; use `.vtu`.
///
/// # Errors
/// [`Error::Io`] if the file cannot be written, or (kind `InvalidInput`) if the arrays of
/// `field` do not all have one entry per node copy, those of `elements` nx ny entries, or the
/// corner table names a copy the arrays do not have.
pub fn write_vtu(path: &Path, field: &FullField, elements: &ElementField) -> Result<()> {
    let sizes = check(path, field, elements)?;
    let content = Content {
        nodal: true,
        cells: cell_arrays(elements),
    };
    write_file(path, field, &content, &sizes)
}

/// Write the plate's grid (points and cells as [`write_vtu`]) with cell data only: `cells`, one
/// value per element (index ie + je nx), the first the active scalars, and the `panel` of each
/// element on a plate with panels. For maps that are not one solve's fields (the damage summed
/// over many solves): no point data, so no solve's deflection is shown with them.
///
/// # Errors
/// As [`write_vtu`]: a grid whose corner table does not match, or a cell array without one
/// entry per element.
pub fn write_cell_vtu(
    path: &Path,
    field: &FullField,
    cells: &[(&'static str, &[f64])],
) -> Result<()> {
    check_cells(path, cells, field.nx.saturating_mul(field.ny))?;
    // The grid's own checks: its nodal arrays and corner table (no element values of a solve).
    let sizes = check(path, field, &ElementField::default())?;
    let content = Content {
        nodal: false,
        cells: cells.to_vec(),
    };
    write_file(
        path,
        field,
        &content,
        &Sizes {
            with_cells: !cells.is_empty(),
            ..sizes
        },
    )
}

/// What a file holds beside the grid: the nodal fields of a solve or none, and the cell arrays
/// (the first the active scalars).
struct Content<'a> {
    nodal: bool,
    cells: Vec<(&'static str, &'a [f64])>,
}

fn write_file(path: &Path, field: &FullField, content: &Content<'_>, sizes: &Sizes) -> Result<()> {
    let io = |source| Error::Io {
        path: path.display().to_string(),
        source,
    };
    let mut out = BufWriter::new(File::create(path).map_err(io)?);
    write_xml(&mut out, field, content, sizes).map_err(io)?;
    out.flush().map_err(io)
}

/// The checked sizes of the grid.
struct Sizes {
    /// (nx + 1)(ny + 1) and the extra copies.
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
        .and_then(|g| g.checked_add(field.extra_grid.len()))
        .zip(nx.checked_mul(ny));
    let Some((n_nodes, n_cells)) = sizes else {
        return Err(io_error(
            path,
            std::io::ErrorKind::InvalidInput,
            format!("grid of {nx} × {ny} elements is too large"),
        ));
    };

    let nodal: [(&str, usize); 14] = [
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
        ("s1_bottom", field.s1_bottom.len()),
        ("s1_top", field.s1_top.len()),
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

    let corners_ok = field
        .corners
        .as_ref()
        .is_none_or(|c| c.len() == n_cells && c.iter().flatten().all(|&k| k < n_nodes))
        && (field.panel.is_empty() || field.panel.len() == n_cells);
    if !corners_ok {
        return Err(io_error(
            path,
            std::io::ErrorKind::InvalidInput,
            format!("the corner table or the panels do not match the {nx} × {ny} element grid"),
        ));
    }

    let with_cells = cell_arrays(elements).iter().any(|(_, v)| !v.is_empty());
    if with_cells {
        check_cells(path, &cell_arrays(elements), n_cells)?;
    }
    Ok(Sizes {
        nodes: n_nodes,
        cells: n_cells,
        with_cells,
    })
}

/// Every cell array has one value per element.
fn check_cells(path: &Path, cells: &[(&str, &[f64])], n_cells: usize) -> Result<()> {
    match cells.iter().find(|(_, v)| v.len() != n_cells) {
        Some((name, v)) => Err(io_error(
            path,
            std::io::ErrorKind::InvalidInput,
            format!(
                "element array `{name}` has {} entries, the grid has {n_cells} elements",
                v.len()
            ),
        )),
        None => Ok(()),
    }
}

/// The cell data arrays, the active scalars (`mx`) first: the columns of elements.csv but the
/// centre coordinates (moments, shear forces, the faces' stresses).
fn cell_arrays(elements: &ElementField) -> Vec<(&'static str, &[f64])> {
    elements
        .columns()
        .into_iter()
        .filter(|(name, _, _)| !matches!(*name, "x" | "y"))
        .map(|(name, _, values)| (name, values))
        .collect()
}

/// The whole `.vtu` document; the arrays have the lengths in `sizes`.
fn write_xml<W: Write>(
    out: W,
    field: &FullField,
    content: &Content<'_>,
    sizes: &Sizes,
) -> io::Result<()> {
    let mut xml = Writer::new_with_indent(out, b' ', 2);
    xml.write_event(Event::Decl(BytesDecl::new("1.0", None, None)))?;
    let kept = plate_points(field).map_or(sizes.nodes, |(_, n)| n);
    let (nodes, cells) = (kept.to_string(), plate_cells(field, sizes).to_string());
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
                        .write_inner_content(|xml| piece(xml, field, content, sizes))
                        .map(drop)
                })
                .map(drop)
        })
        .map(drop)
}

/// A shaped plate's points: each node's number among the plate's (−1 off it) and their
/// count; `None` on a plate that is its whole rectangle (every point written).
fn plate_points(field: &FullField) -> Option<(Vec<i64>, usize)> {
    if field.plate.is_empty() {
        return None;
    }
    let mut next = 0;
    let number = field
        .node_on_plate()
        .into_iter()
        .map(|on| match on {
            true => {
                next += 1;
                next - 1
            }
            false => -1,
        })
        .collect();
    Some((number, next as usize))
}

/// The cells written: the grid's, less those outside a shaped plate.
fn plate_cells(field: &FullField, sizes: &Sizes) -> usize {
    match field.plate.is_empty() {
        true => sizes.cells,
        false => field.plate.iter().filter(|&&p| p).count(),
    }
}

/// The entries of a per-element array that belong to plate cells.
fn on_plate<'a, T>(field: &'a FullField, values: &'a [T]) -> impl Iterator<Item = &'a T> + 'a {
    values
        .iter()
        .enumerate()
        .filter(|(k, _)| field.plate.get(*k).copied().unwrap_or(true))
        .map(|(_, v)| v)
}

/// The content of the one `Piece`: point data, cell data, points and cells.
fn piece<W: Write>(
    xml: &mut Writer<W>,
    field: &FullField,
    content: &Content<'_>,
    sizes: &Sizes,
) -> io::Result<()> {
    if content.nodal {
        point_data(xml, field)?;
    }
    if sizes.with_cells {
        let active = content.cells.first().map_or("panel", |(name, _)| *name);
        xml.create_element("CellData")
            .with_attribute(("Scalars", active))
            .write_inner_content(|xml| {
                for (name, values) in &content.cells {
                    data_array(xml, Some(name), 1, on_plate(field, values).copied())?;
                }
                if !field.panel.is_empty() {
                    // Panel ids are below the element count: they fit in i32 for any grid
                    // that fits in memory; saturate rather than wrap otherwise.
                    let panel = on_plate(field, &field.panel)
                        .map(|&p| i32::try_from(p).unwrap_or(i32::MAX));
                    data_array(xml, Some("panel"), 1, panel)?;
                }
                Ok(())
            })?;
    }

    // A shaped plate's points are its own nodes only, renumbered in order, and its cells
    // outside it are not written.
    let kept = plate_points(field);
    let keep = |k: usize| kept.as_ref().is_none_or(|(number, _)| number[k] >= 0);
    xml.create_element("Points").write_inner_content(|xml| {
        let points = field
            .x
            .iter()
            .zip(&field.y)
            .enumerate()
            .filter(|(k, _)| keep(*k))
            .flat_map(|(_, (&x, &y))| [x, y, 0.0]);
        data_array(xml, None, 3, points)
    })?;

    // Node and offset numbers fit in i64: they are below the length of an allocated array.
    let number = |n: usize| kept.as_ref().map_or(n as i64, |(number, _)| number[n]);
    let quads = (0..field.ny).flat_map(|je| {
        (0..field.nx)
            .filter(move |&ie| field.is_plate(ie, je))
            .map(move |ie| field.element_nodes(ie, je).map(number))
    });
    let n_cells = plate_cells(field, sizes);
    xml.create_element("Cells").write_inner_content(|xml| {
        data_array(xml, Some("connectivity"), 1, quads.flatten())?;
        let offsets = (1..=n_cells as i64).map(|k| 4 * k);
        data_array(xml, Some("offsets"), 1, offsets)?;
        let types = std::iter::repeat_n(VTK_QUAD, n_cells);
        data_array(xml, Some("types"), 1, types)
    })?;
    Ok(())
}

/// A solve's nodal fields, the pressure `sigma` the active scalars and the displacement the
/// active vectors.
fn point_data<W: Write>(xml: &mut Writer<W>, field: &FullField) -> io::Result<()> {
    let nodal: [(&str, &[f64]); 9] = [
        ("w", &field.w),
        ("psi_x", &field.psi_x),
        ("psi_y", &field.psi_y),
        ("pressure", &field.pressure),
        ("gap", &field.gap),
        ("V", &field.v),
        ("sigma", &field.sigma),
        ("s1_bottom", &field.s1_bottom),
        ("s1_top", &field.s1_top),
    ];
    xml.create_element("PointData")
        .with_attributes([("Scalars", "sigma"), ("Vectors", "displacement")])
        .write_inner_content(|xml| {
            // A shaped plate's own nodes only (as its points).
            let on = field.node_on_plate();
            let kept = |v: &'_ [f64]| -> Vec<f64> {
                v.iter()
                    .zip(&on)
                    .filter(|(_, &o)| o)
                    .map(|(&x, _)| x)
                    .collect()
            };
            for (name, values) in nodal {
                data_array(xml, Some(name), 1, kept(values))?;
            }
            let contact = field
                .contact
                .iter()
                .zip(&on)
                .filter(|(_, &o)| o)
                .map(|(&c, _)| i32::from(c));
            data_array(xml, Some("contact"), 1, contact)?;
            let displacement = kept(&field.w).into_iter().flat_map(|w| [0.0, 0.0, -w]);
            data_array(xml, Some("displacement"), 3, displacement)
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
mod tests;
