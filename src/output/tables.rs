//! CSV tables: nodes, element resultants, profiles.

use std::path::Path;

use crate::error::{Error, Result};
use crate::post::{ElementField, FullField, Profile};

fn csv_err(path: &Path, e: csv::Error) -> Error {
    Error::Io {
        path: path.display().to_string(),
        source: std::io::Error::other(e.to_string()),
    }
}

/// nodes.csv: x,y,s,t,w,psi_x,psi_y,pressure,gap,V,sigma,contact (whole plate).
pub fn write_nodes(path: &Path, f: &FullField) -> Result<()> {
    let mut w = csv::Writer::from_path(path).map_err(|e| csv_err(path, e))?;
    w.write_record([
        "x", "y", "s", "t", "w", "psi_x", "psi_y", "pressure", "gap", "V", "sigma", "contact",
    ])
    .map_err(|e| csv_err(path, e))?;
    for i in 0..f.x.len() {
        let row = [
            f.x[i],
            f.y[i],
            f.s[i],
            f.t[i],
            f.w[i],
            f.psi_x[i],
            f.psi_y[i],
            f.pressure[i],
            f.gap[i],
            f.v[i],
            f.sigma[i],
        ];
        let mut rec: Vec<String> = row.iter().map(|v| format!("{v:.9e}")).collect();
        rec.push(if f.contact[i] { "1" } else { "0" }.to_string());
        w.write_record(&rec).map_err(|e| csv_err(path, e))?;
    }
    w.flush().map_err(|e| Error::Io {
        path: path.display().to_string(),
        source: e,
    })
}

/// elements.csv: x,y,mx,my,mxy,qx,qy at element centres.
pub fn write_elements(path: &Path, e: &ElementField) -> Result<()> {
    let mut w = csv::Writer::from_path(path).map_err(|er| csv_err(path, er))?;
    w.write_record(["x", "y", "mx", "my", "mxy", "qx", "qy"])
        .map_err(|er| csv_err(path, er))?;
    for i in 0..e.x.len() {
        let row = [e.x[i], e.y[i], e.mx[i], e.my[i], e.mxy[i], e.qx[i], e.qy[i]];
        let rec: Vec<String> = row.iter().map(|v| format!("{v:.9e}")).collect();
        w.write_record(&rec).map_err(|er| csv_err(path, er))?;
    }
    w.flush().map_err(|er| Error::Io {
        path: path.display().to_string(),
        source: er,
    })
}

/// profiles.csv: line,coord,s,t,V,sigma.
pub fn write_profiles(path: &Path, profiles: &[Profile]) -> Result<()> {
    let mut w = csv::Writer::from_path(path).map_err(|e| csv_err(path, e))?;
    w.write_record(["line", "coord", "s", "t", "V", "sigma"])
        .map_err(|e| csv_err(path, e))?;
    for p in profiles {
        for q in &p.points {
            w.write_record([
                p.line.to_string(),
                format!("{:.9e}", q.coord),
                format!("{:.9e}", q.s),
                format!("{:.9e}", q.t),
                format!("{:.9e}", q.v),
                format!("{:.9e}", q.sigma),
            ])
            .map_err(|e| csv_err(path, e))?;
        }
    }
    w.flush().map_err(|e| Error::Io {
        path: path.display().to_string(),
        source: e,
    })
}
