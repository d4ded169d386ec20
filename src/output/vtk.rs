//! ParaView output: the whole plate as an XML unstructured grid (`.vtu`) of bilinear quads with
//! nodal fields, a displacement vector for "Warp By Vector" and element stress resultants.

use std::path::Path;

use vtkio::model::{
    Attribute, Attributes, ByteOrder, CellType, Cells, DataArray, DataSet, ElementType, IOBuffer,
    UnstructuredGridPiece, Version, VertexNumbers, Vtk,
};

use crate::error::{Error, Result};
use crate::post::{ElementField, FullField};

/// An error about the file at `path` with an I/O-style message.
fn io_error(path: &Path, kind: std::io::ErrorKind, message: String) -> Error {
    Error::Io {
        path: path.display().to_string(),
        source: std::io::Error::new(kind, message),
    }
}

/// A named one-component array of doubles.
fn generic(name: &str, data: Vec<f64>) -> Attribute {
    Attribute::DataArray(DataArray {
        name: name.to_string(),
        elem: ElementType::Generic(1),
        data: IOBuffer::F64(data),
    })
}

/// A named one-component array of doubles tagged as the active scalars.
fn scalars(name: &str, data: Vec<f64>) -> Attribute {
    Attribute::DataArray(DataArray {
        name: name.to_string(),
        elem: ElementType::Scalars {
            num_comp: 1,
            lookup_table: None,
        },
        data: IOBuffer::F64(data),
    })
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
    let vtk = build(path, field, elements)?;
    let mut bytes = Vec::new();
    vtk.write_xml(&mut bytes).map_err(|e| {
        io_error(
            path,
            std::io::ErrorKind::Other,
            format!("VTK XML encoding failed: {e}"),
        )
    })?;
    std::fs::write(path, bytes).map_err(|source| Error::Io {
        path: path.display().to_string(),
        source,
    })
}

/// The VTK model of the plate.
fn build(path: &Path, field: &FullField, elements: &ElementField) -> Result<Vtk> {
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

    let nodal: [(&str, &[f64]); 10] = [
        ("x", &field.x),
        ("y", &field.y),
        ("s", &field.s),
        ("t", &field.t),
        ("w", &field.w),
        ("psi_x", &field.psi_x),
        ("psi_y", &field.psi_y),
        ("pressure", &field.pressure),
        ("gap", &field.gap),
        ("V", &field.v),
    ];
    let bad_nodal = nodal
        .iter()
        .map(|(name, v)| (*name, v.len()))
        .chain([
            ("sigma", field.sigma.len()),
            ("contact", field.contact.len()),
        ])
        .find(|(_, len)| *len != n_nodes);
    if let Some((name, len)) = bad_nodal {
        return Err(io_error(
            path,
            std::io::ErrorKind::InvalidInput,
            format!(
                "nodal array `{name}` has {len} entries, the {nx} × {ny} element grid has \
                 {n_nodes} nodes"
            ),
        ));
    }

    let cell_arrays: [(&str, &[f64]); 5] = [
        ("mx", &elements.mx),
        ("my", &elements.my),
        ("mxy", &elements.mxy),
        ("qx", &elements.qx),
        ("qy", &elements.qy),
    ];
    let with_cells = cell_arrays.iter().any(|(_, v)| !v.is_empty());
    if with_cells {
        if let Some((name, v)) = cell_arrays.iter().find(|(_, v)| v.len() != n_cells) {
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

    let points: Vec<f64> = (0..n_nodes)
        .flat_map(|k| [field.x[k], field.y[k], 0.0])
        .collect();

    let nnx = (nx + 1) as u64;
    let mut connectivity = Vec::with_capacity(4 * n_cells);
    let mut offsets = Vec::with_capacity(n_cells);
    for je in 0..ny as u64 {
        for ie in 0..nx as u64 {
            let n00 = ie + je * nnx;
            connectivity.extend_from_slice(&[n00, n00 + 1, n00 + 1 + nnx, n00 + nnx]);
            offsets.push(connectivity.len() as u64);
        }
    }

    let displacement: Vec<f64> = field.w.iter().flat_map(|&w| [0.0, 0.0, -w]).collect();
    let point = vec![
        generic("w", field.w.clone()),
        generic("psi_x", field.psi_x.clone()),
        generic("psi_y", field.psi_y.clone()),
        generic("pressure", field.pressure.clone()),
        generic("gap", field.gap.clone()),
        generic("V", field.v.clone()),
        scalars("sigma", field.sigma.clone()),
        Attribute::DataArray(DataArray {
            name: "contact".to_string(),
            elem: ElementType::Generic(1),
            data: IOBuffer::I32(field.contact.iter().map(|&c| i32::from(c)).collect()),
        }),
        Attribute::DataArray(DataArray {
            name: "displacement".to_string(),
            elem: ElementType::Vectors,
            data: IOBuffer::F64(displacement),
        }),
    ];
    let cell = if with_cells {
        cell_arrays
            .iter()
            .enumerate()
            .map(|(k, (name, v))| {
                if k == 0 {
                    scalars(name, v.to_vec())
                } else {
                    generic(name, v.to_vec())
                }
            })
            .collect()
    } else {
        Vec::new()
    };

    Ok(Vtk {
        version: Version::new((1, 0)),
        title: String::from("liftoff plate"),
        byte_order: ByteOrder::LittleEndian,
        file_path: None,
        data: DataSet::inline(UnstructuredGridPiece {
            points: IOBuffer::F64(points),
            cells: Cells {
                cell_verts: VertexNumbers::XML {
                    connectivity,
                    offsets,
                },
                types: vec![CellType::Quad; n_cells],
            },
            data: Attributes { point, cell },
        }),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use vtkio::model::UnstructuredGridPiece;

    use crate::post::test_fixtures::bump;

    fn first_piece(vtk: Vtk) -> UnstructuredGridPiece {
        match vtk.data {
            DataSet::UnstructuredGrid { pieces, .. } => pieces
                .into_iter()
                .next()
                .expect("one piece")
                .into_loaded_piece_data(None)
                .expect("inline piece"),
            other => panic!("not an unstructured grid: {other:?}"),
        }
    }

    #[test]
    fn vtu_round_trips() {
        let (f, e) = bump();
        let dir = tempfile::tempdir().expect("tempdir");
        let path = dir.path().join("plate.vtu");
        write_vtu(&path, &f, &e).expect("write");
        let text = std::fs::read_to_string(&path).expect("read");
        assert!(text.contains("UnstructuredGrid"));

        let piece = first_piece(Vtk::import(&path).expect("import"));
        assert_eq!(piece.num_points(), 15);
        assert_eq!(piece.cells.num_cells(), 8);
        assert!(piece.cells.types.iter().all(|&t| t == CellType::Quad));
        match &piece.cells.cell_verts {
            VertexNumbers::XML {
                connectivity,
                offsets,
            } => {
                assert_eq!(&connectivity[..4], &[0, 1, 6, 5]);
                assert_eq!(offsets.len(), 8);
                assert_eq!(offsets.last(), Some(&32));
            }
            VertexNumbers::Legacy { .. } => panic!("expected XML cell numbering"),
        }
        let names: Vec<&str> = piece.data.point.iter().map(|a| a.name()).collect();
        for want in [
            "w",
            "psi_x",
            "psi_y",
            "pressure",
            "gap",
            "V",
            "sigma",
            "contact",
            "displacement",
        ] {
            assert!(names.contains(&want), "missing point array {want}");
        }
        let cells: Vec<&str> = piece.data.cell.iter().map(|a| a.name()).collect();
        assert_eq!(cells, ["mx", "my", "mxy", "qx", "qy"]);

        // Values survive: the displacement of node 7 (centre) is (0, 0, −w).
        let disp = piece
            .data
            .point
            .iter()
            .find_map(|a| match a {
                Attribute::DataArray(d) if d.name == "displacement" => {
                    d.data.clone().cast_into::<f64>()
                }
                _ => None,
            })
            .expect("displacement");
        assert_eq!(disp.len(), 45);
        assert!((disp[3 * 7 + 2] + f.w[7]).abs() < 1e-15);
    }

    #[test]
    fn vtu_without_elements_and_bad_sizes() {
        let (f, _) = bump();
        let dir = tempfile::tempdir().expect("tempdir");
        let path = dir.path().join("nodal.vtu");
        write_vtu(&path, &f, &ElementField::default()).expect("write");
        let piece = first_piece(Vtk::import(&path).expect("import"));
        assert_eq!(piece.cells.num_cells(), 8);
        assert!(piece.data.cell.is_empty());

        let mut g = f.clone();
        g.gap.pop();
        assert!(write_vtu(&path, &g, &ElementField::default()).is_err());
        let (_, mut e) = bump();
        e.qy.pop();
        assert!(write_vtu(&path, &f, &e).is_err());
        // Unwritable location.
        let missing = dir.path().join("no/such/dir/p.vtu");
        assert!(matches!(
            write_vtu(&missing, &f, &ElementField::default()),
            Err(Error::Io { .. })
        ));
    }
}
