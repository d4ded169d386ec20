//! Result files: CSV tables, the JSON summary, the ParaView grid and the SVG/PNG charts.

pub mod plot;
pub mod vtk;
