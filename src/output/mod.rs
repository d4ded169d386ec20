//! Result files: CSV tables, the JSON summary, the ParaView grid and the SVG/PNG charts.
//!
//! [`write_all`] stages every file in a hidden directory inside the output directory and
//! renames them into place only when all were written, so a failed run never leaves a
//! half-written file or a half-updated directory behind.

pub mod chart;
pub mod studies;

pub mod tables;
pub mod vtk;

use std::path::{Path, PathBuf};

use crate::error::{Error, Result};
use crate::post::Report;
pub use crate::summary::{Summary, Times};

fn io(path: &Path) -> impl FnOnce(std::io::Error) -> Error + '_ {
    move |source| Error::Io {
        path: path.display().to_string(),
        source,
    }
}

/// Create `dir` if needed and check that files can be created in it — before any solving.
pub fn prepare_dir(dir: &Path) -> Result<()> {
    std::fs::create_dir_all(dir).map_err(io(dir))?;
    let probe = tempfile::Builder::new()
        .prefix(".liftoff-write-check")
        .tempfile_in(dir)
        .map_err(io(dir))?;
    drop(probe);
    Ok(())
}

/// A set of files written into a staging directory and moved into place together.
pub struct Staged {
    dir: PathBuf,
    staging: tempfile::TempDir,
    names: Vec<String>,
}

impl Staged {
    /// Start staging files for `dir` (which must exist).
    pub fn new(dir: &Path) -> Result<Self> {
        let staging = tempfile::Builder::new()
            .prefix(".liftoff-staging")
            .tempdir_in(dir)
            .map_err(io(dir))?;
        Ok(Self {
            dir: dir.to_path_buf(),
            staging,
            names: Vec::new(),
        })
    }

    /// Path in the staging area for a file that will be called `name`.
    pub fn path(&mut self, name: &str) -> PathBuf {
        self.names.push(name.to_string());
        self.staging.path().join(name)
    }

    /// Write text to a staged file.
    pub fn write_text(&mut self, name: &str, text: &str) -> Result<()> {
        let p = self.path(name);
        std::fs::write(&p, text).map_err(io(&p))
    }

    /// Move every staged file into the output directory; returns the final paths.
    pub fn commit(self) -> Result<Vec<PathBuf>> {
        let mut out = Vec::new();
        for name in &self.names {
            let from = self.staging.path().join(name);
            let to = self.dir.join(name);
            std::fs::rename(&from, &to).map_err(io(&to))?;
            out.push(to);
        }
        Ok(out)
    }
}

/// Write the standard result set of one solve into `dir`: summary.json, nodes.csv,
/// elements.csv, profiles.csv, plate.vtu, profiles.svg, contact.svg and contact.png.
pub fn write_all(dir: &Path, report: &Report, summary: &Summary) -> Result<Vec<PathBuf>> {
    let mut st = Staged::new(dir)?;
    st.write_text("summary.json", &summary.to_json()?)?;
    let p = st.path("nodes.csv");
    tables::write_nodes(&p, &report.field)?;
    let p = st.path("elements.csv");
    tables::write_elements(&p, &report.elements)?;
    let p = st.path("profiles.csv");
    tables::write_profiles(&p, &report.profiles)?;
    let p = st.path("plate.vtu");
    vtk::write_vtu(&p, &report.field, &report.elements)?;
    let title = format!("{} — {}", summary.title, summary.headline());
    let units = chart::Units::new(summary.physical, summary.dimensionless.mu);
    let p = st.path("profiles.svg");
    chart::write_profiles_svg(&p, &report.profiles, &title, &units)?;
    let svg = st.path("contact.svg");
    let png = st.path("contact.png");
    chart::write_contact_map(
        &svg,
        &png,
        &report.field,
        &title,
        &units,
        &chart::Overlay::default(),
    )?;
    st.commit()
}
