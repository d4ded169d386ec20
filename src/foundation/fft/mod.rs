//! The half-space compliance T without storing T: a block-Toeplitz product by zero-padded 2-D
//! FFTs (the discrete-convolution FFT, "DC-FFT", of the contact literature).
//!
//! On the uniform grid the Galerkin entries are sums over element pairs,
//!
//! T_ij = c Σ_{e ∋ i (local a)} Σ_{e' ∋ j (local b)} I_ab(e' − e),
//!
//! where I_ab(d) is the pair block of [`super::kernel::Kernel::pair_block`] at the element offset d (the
//! same table the dense T is scattered from). Gathering the node values into four element
//! fields w_b[e'] = σ(node b of e'), the product is four discrete correlations per output field,
//!
//! (Tσ)_i = Σ_{e ∋ i (local a)} y_a[e],   y_a[e] = Σ_b Σ_{e'} c I_ab(e' − e) w_b[e'],
//!
//! each a pointwise product of spectra on a grid padded far enough that the circular product does
//! not wrap: 4 forward and 4 inverse real 2-D FFTs and 16 spectral products per application,
//! O(N log N) time and O(N) memory for N pressure nodes.
//!
//! Two things make the product cheaper than that count. The pair kernels are symmetric,
//! c I_ab(d) = c I_ba(−d) (as [`symmetric`] stores them), and the spectrum of a real field
//! reflected through the origin is the conjugate of its spectrum, so K̂_ba = conj(K̂_ab) where
//! the offsets a product reads are symmetric about zero — on a whole plate (a reduced model
//! reads from −(2n − 1) to n − 1 along its reduced direction, and its padding is not wide
//! enough for the reflected range): there 10 spectra are kept and the 16 products read them in
//! one pass. And a padded field is zero outside the whole plate's rows, and only the model's
//! rows are read back: the row transforms of the other rows (about half of them on a whole
//! plate) are skipped, their spectra zero.
//!
//! A symmetry-reduced model's T includes the settlement of the mirror images of its pressure
//! (see [`super::pairs`]): that is the same correlation on the whole plate with the pressure
//! extended by mirroring, σ(x) = σ(|x|) across each symmetry line. Only the model's own elements
//! are read back, so the padding needs to cover the offsets from the model to the whole plate:
//! N_d + n_d − 1 along a direction with n_d model and N_d whole-plate elements.
//!
//! On a jointed plate each node copy is one pressure unknown: the pressure is bilinear per
//! element from the element's own corner copies (the cell-corner form), so the four element
//! fields gather w_b[e'] = σ(copy at corner b of e') and the outputs scatter to the copies —
//! the same pair table, padded grid and 8 FFTs per product; only the gather and scatter maps
//! change (a gather map of 4 entries per whole-plate element).

use std::sync::{Arc, Mutex};

use realfft::num_complex::Complex;
use realfft::{ComplexToReal, RealFftPlanner, RealToComplex};
use rustfft::{Fft, FftPlanner};

use super::kernel::Kernel;
use super::pairs::{self, PairTable};
use crate::mesh::Mesh;

/// Position (i, j) of local node a inside its element, counter-clockwise from the lower left
/// ([`Mesh::element_nodes`]).
const LOCAL: [(usize, usize); 4] = [(0, 0), (1, 0), (1, 1), (0, 1)];

/// Smallest length ≥ n whose prime factors are 2, 3 and 5 (fast for rustfft), and even (fast
/// for the real transforms).
pub fn fft_size(n: usize) -> usize {
    let mut m = n.max(2);
    loop {
        let mut r = m;
        for p in [2, 3, 5] {
            while r.is_multiple_of(p) {
                r /= p;
            }
        }
        if r == 1 && m.is_multiple_of(2) {
            return m;
        }
        m += 1;
    }
}

/// Buffers of one application, reused from call to call.
struct Scratch {
    /// Four element fields (real, M1 × M2), then the four outputs.
    real: [Vec<f64>; 4],
    /// Their spectra, [k2][k1] (H2 × M1).
    spec: [Vec<Complex<f64>>; 4],
    /// The four output spectra.
    out: [Vec<Complex<f64>>; 4],
    /// One row-transform result (M1 × H2), transposed into `spec`.
    rows: Vec<Complex<f64>>,
    /// Work space of the transforms.
    work: Vec<Complex<f64>>,
}

/// The half-space compliance of a (possibly symmetry-reduced) structured mesh as a block-Toeplitz
/// operator: the spectra of the 16 pair kernels, the FFT plans and the diagonal of T.
pub struct ToeplitzCompliance {
    mesh: Mesh,
    constant: f64,
    kernel: Kernel,
    /// Padded grid M1 × M2 (elements).
    m: [usize; 2],
    /// Where the model's elements sit in the whole plate (n_d if reduced along d, else 0).
    shift: [usize; 2],
    /// Kernel spectra of H2 × M1 (H2 = M2/2 + 1): on a whole plate the 10 with a ≤ b in
    /// [`pair_index`]'s order (K̂_ba = conj(K̂_ab)), on a reduced model all 16 at a·4 + b.
    kernels: Vec<Vec<Complex<f64>>>,
    /// Whether the offsets read are symmetric about zero, so that 10 spectra are kept.
    mirrored: bool,
    /// On a jointed mesh, the unknown read at corner b of whole-plate element (I, J), at
    /// (b · N1 + I) · N2 + J; `None` on a plain grid (the node |I + b_x − shift| …).
    gather: Option<Vec<u32>>,
    diag: Vec<f64>,
    r2c: Arc<dyn RealToComplex<f64>>,
    c2r: Arc<dyn ComplexToReal<f64>>,
    fwd: Arc<dyn Fft<f64>>,
    inv: Arc<dyn Fft<f64>>,
    /// Work buffers kept between products: one set per product that ran at the same time as
    /// others (runs solved side by side share T), so that no product allocates and clears its
    /// own after the first.
    scratch: Mutex<Vec<Scratch>>,
}

impl std::fmt::Debug for ToeplitzCompliance {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("ToeplitzCompliance")
            .field("mesh", &self.mesh)
            .field("constant", &self.constant)
            .field("padded", &self.m)
            .finish_non_exhaustive()
    }
}

impl Clone for ToeplitzCompliance {
    fn clone(&self) -> Self {
        Self {
            mesh: self.mesh.clone(),
            constant: self.constant,
            kernel: self.kernel.clone(),
            m: self.m,
            shift: self.shift,
            kernels: self.kernels.clone(),
            mirrored: self.mirrored,
            gather: self.gather.clone(),
            diag: self.diag.clone(),
            r2c: self.r2c.clone(),
            c2r: self.c2r.clone(),
            fwd: self.fwd.clone(),
            inv: self.inv.clone(),
            scratch: Mutex::new(Vec::new()),
        }
    }
}

/// The pair integral of local nodes (a, b) at element offset d, averaged with its transpose
/// (b, a) at −d. The two are equal up to the quadrature's round-off (the near-field rule
/// integrates the inner element in closed form and the outer one numerically); the dense T is
/// symmetrised the same way, entry by entry.
fn symmetric(table: &PairTable, di: isize, dj: isize, a: usize, b: usize) -> f64 {
    0.5 * (table.get(di, dj, a, b) + table.get(-di, -dj, b, a))
}

/// Where the spectrum of the pair kernel (a, b), a ≤ b, is kept among the 10.
fn pair_index(a: usize, b: usize) -> usize {
    debug_assert!(a <= b && b < 4);
    a * 4 - a * (a + 1) / 2 + b
}

/// Whole-plate node positions (I, J) that the model node (i, j) stands for: itself, and its
/// mirror images across the symmetry lines.
fn preimages(mesh: &Mesh, shift: [usize; 2], i: usize, j: usize) -> Vec<(usize, usize)> {
    let along = |p: usize, s: usize, sym: bool| -> Vec<usize> {
        if !sym {
            vec![p]
        } else if p == 0 {
            vec![s]
        } else {
            vec![s + p, s - p]
        }
    };
    let xs = along(i, shift[0], mesh.sym_x);
    let ys = along(j, shift[1], mesh.sym_y);
    let mut out = Vec::with_capacity(xs.len() * ys.len());
    for &x in &xs {
        for &y in &ys {
            out.push((x, y));
        }
    }
    out
}

impl ToeplitzCompliance {
    /// Tabulate the pair kernels of `mesh` with the half-space constant `c` and transform them.
    pub fn new(mesh: &Mesh, c: f64) -> Self {
        Self::with_kernel(mesh, c, &Kernel::new(super::halfspace::Boussinesq))
    }

    /// The same for any surface kernel ([`Kernel`]) with its constant `c`.
    pub fn with_kernel(mesh: &Mesh, c: f64, kernel: &Kernel) -> Self {
        let full = mesh.full_elements();
        let table = PairTable::new(full, mesh.hx, mesh.hy, kernel);
        Self::from_table(mesh, c, kernel, &table)
    }

    pub(crate) fn from_table(mesh: &Mesh, c: f64, kernel: &Kernel, table: &PairTable) -> Self {
        let full = mesh.full_elements();
        let n = [mesh.nx, mesh.ny];
        let shift = [
            if mesh.sym_x { mesh.nx } else { 0 },
            if mesh.sym_y { mesh.ny } else { 0 },
        ];
        let m = [fft_size(full[0] + n[0] - 1), fft_size(full[1] + n[1] - 1)];
        let h2 = m[1] / 2 + 1;
        let mut real_planner = RealFftPlanner::<f64>::new();
        let r2c = real_planner.plan_fft_forward(m[1]);
        let c2r = real_planner.plan_fft_inverse(m[1]);
        let mut planner = FftPlanner::<f64>::new();
        let fwd = planner.plan_fft_forward(m[0]);
        let inv = planner.plan_fft_inverse(m[0]);
        let mut op = Self {
            mesh: mesh.clone(),
            constant: c,
            kernel: kernel.clone(),
            m,
            shift,
            kernels: Vec::new(),
            mirrored: shift == [0, 0],
            gather: gather_map(mesh, shift),
            diag: Vec::new(),
            r2c,
            c2r,
            fwd,
            inv,
            scratch: Mutex::new(Vec::new()),
        };
        let mut scratch = op.new_scratch();
        // Offsets d = (source − target) in whole-plate elements: d ∈ [−(shift + n − 1), full −
        // 1 − shift]. The correlation y[t] = Σ_s k(s − t) w[s] is the convolution with
        // k'(d) = k(−d), so k(d) is stored at index (−d) mod M.
        let lo = [
            -((shift[0] + n[0]) as isize - 1),
            -((shift[1] + n[1]) as isize - 1),
        ];
        let hi = [
            (full[0] - 1 - shift[0]) as isize,
            (full[1] - 1 - shift[1]) as isize,
        ];
        let wrap = |d: isize, len: usize| (-d).rem_euclid(len as isize) as usize;
        debug_assert_eq!(op.mirrored, lo[0] == -hi[0] && lo[1] == -hi[1]);
        let mut kernels = Vec::with_capacity(16);
        let mut field = vec![0.0; m[0] * m[1]];
        for a in 0..4 {
            for b in 0..4 {
                if op.mirrored && b < a {
                    continue;
                }
                field.iter_mut().for_each(|v| *v = 0.0);
                for di in lo[0]..=hi[0] {
                    let row = wrap(di, m[0]) * m[1];
                    for dj in lo[1]..=hi[1] {
                        field[row + wrap(dj, m[1])] = c * symmetric(table, di, dj, a, b);
                    }
                }
                let mut spec = vec![Complex::new(0.0, 0.0); h2 * m[0]];
                op.forward(&mut field, m[0], &mut spec, &mut scratch);
                kernels.push(spec);
            }
        }
        op.kernels = kernels;
        op.diag = op.diagonal(table);
        op.scratch
            .get_mut()
            .unwrap_or_else(|e| e.into_inner())
            .push(scratch);
        op
    }

    /// The mesh the operator was built for.
    pub fn mesh(&self) -> &Mesh {
        &self.mesh
    }

    /// The half-space constant c = (1 − ν_s²)/(π E_s) in the caller's units.
    pub fn constant(&self) -> f64 {
        self.constant
    }

    /// Padded FFT grid (elements along x, y).
    pub fn padded(&self) -> [usize; 2] {
        self.m
    }

    /// Number of pressure unknowns.
    pub fn len(&self) -> usize {
        self.mesh.n_nodes()
    }

    /// True when there are no pressure unknowns.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Diagonal of T.
    pub fn diag(&self) -> &[f64] {
        &self.diag
    }

    /// Bytes held: kernel spectra, one set of scratch buffers (and one more for each product
    /// that ran beside another, the most that ran at once), the diagonal.
    pub fn bytes(&self) -> usize {
        toeplitz_bytes(&self.mesh)
    }

    /// The dense matrix of the same operator ([`pairs::dense_matrix`]), for routes that need
    /// it; n² doubles.
    pub fn dense(&self) -> faer::Mat<f64> {
        pairs::dense_matrix(&self.mesh, self.constant, &self.kernel)
    }

    fn new_scratch(&self) -> Scratch {
        let [m1, m2] = self.m;
        let h2 = m2 / 2 + 1;
        let work = self
            .r2c
            .get_scratch_len()
            .max(self.c2r.get_scratch_len())
            .max(self.fwd.get_inplace_scratch_len())
            .max(self.inv.get_inplace_scratch_len());
        Scratch {
            real: std::array::from_fn(|_| vec![0.0; m1 * m2]),
            spec: std::array::from_fn(|_| vec![Complex::new(0.0, 0.0); h2 * m1]),
            out: std::array::from_fn(|_| vec![Complex::new(0.0, 0.0); h2 * m1]),
            rows: vec![Complex::new(0.0, 0.0); m1 * h2],
            work: vec![Complex::new(0.0, 0.0); work],
        }
    }

    /// Real field (M1 × M2, row-major) → spectrum [k2][k1]. Only the first `rows` rows are
    /// read: the others are taken as zero (their row transforms skipped). Destroys `field`.
    fn forward(&self, field: &mut [f64], rows: usize, spec: &mut [Complex<f64>], s: &mut Scratch) {
        let [m1, m2] = self.m;
        let h2 = m2 / 2 + 1;
        let rows = rows.min(m1);
        for i in 0..rows {
            let input = &mut field[i * m2..(i + 1) * m2];
            let output = &mut s.rows[i * h2..(i + 1) * h2];
            // Lengths match the plan by construction; the transform cannot fail.
            let _ = self.r2c.process_with_scratch(input, output, &mut s.work);
        }
        let zero = Complex::new(0.0, 0.0);
        for (k, column) in spec.chunks_exact_mut(m1).enumerate() {
            for (i, v) in column[..rows].iter_mut().enumerate() {
                *v = s.rows[i * h2 + k];
            }
            column[rows..].iter_mut().for_each(|v| *v = zero);
        }
        self.fwd.process_with_scratch(spec, &mut s.work);
    }

    /// Spectrum [k2][k1] → real field (M1 × M2), scaled by 1/(M1 M2), on the rows `read` only
    /// (the others are left as they were). Destroys `spec`.
    fn inverse(
        &self,
        spec: &mut [Complex<f64>],
        field: &mut [f64],
        read: std::ops::Range<usize>,
        s: &mut Scratch,
    ) {
        let [m1, m2] = self.m;
        let h2 = m2 / 2 + 1;
        self.inv.process_with_scratch(spec, &mut s.work);
        let scale = 1.0 / (m1 * m2) as f64;
        for (k, column) in spec.chunks_exact(m1).enumerate() {
            for i in read.clone() {
                s.rows[i * h2 + k] = column[i] * scale;
            }
        }
        for i in read {
            let input = &mut s.rows[i * h2..(i + 1) * h2];
            // A real field's spectrum is real at k2 = 0 and (M2 even) at the Nyquist index; drop
            // the round-off there, which the real inverse transform refuses.
            input[0].im = 0.0;
            input[h2 - 1].im = 0.0;
            let output = &mut field[i * m2..(i + 1) * m2];
            let _ = self.c2r.process_with_scratch(input, output, &mut s.work);
        }
    }

    /// y = T x.
    pub fn apply(&self, x: &[f64]) -> Vec<f64> {
        let mut y = vec![0.0; self.len()];
        self.apply_into(x, &mut y);
        y
    }

    /// y = T x into a caller's buffer.
    pub fn apply_into(&self, x: &[f64], y: &mut [f64]) {
        // Borrow a kept set of buffers without holding the lock while computing: a product that
        // finds none (all in use by concurrent products) makes its own, kept after it.
        let kept = self.scratch.lock().unwrap_or_else(|e| e.into_inner()).pop();
        let mut s = kept.unwrap_or_else(|| self.new_scratch());
        self.apply_with(x, y, &mut s);
        self.scratch
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .push(s);
    }

    fn apply_with(&self, x: &[f64], y: &mut [f64], s: &mut Scratch) {
        let m2 = self.m[1];
        let full = self.mesh.full_elements();
        let shift = self.shift;
        let nx1 = self.mesh.nodes_x();
        // Model node of a whole-plate node: |I − shift| along a reduced direction.
        let model = |p: usize, s: usize| p.abs_diff(s);
        // Gather the four element fields over the whole plate (mirrored pressure).
        let mut real = std::mem::take(&mut s.real);
        let mut spec = std::mem::take(&mut s.spec);
        let mut out = std::mem::take(&mut s.out);
        for (b, field) in real.iter_mut().enumerate() {
            // The gather writes every cell of the whole plate; of the rest only the padding of
            // its rows is read (the row transforms of the other rows are skipped), and the
            // last product's outputs and the transforms' scratch use leave it dirty.
            for row in field.chunks_exact_mut(m2).take(full[0]) {
                row[full[1]..].iter_mut().for_each(|v| *v = 0.0);
            }
            if let Some(gather) = &self.gather {
                let at = &gather[b * full[0] * full[1]..(b + 1) * full[0] * full[1]];
                // A cell outside a shaped plate reads no pressure (DEAD).
                for ie in 0..full[0] {
                    for je in 0..full[1] {
                        let node = at[ie * full[1] + je];
                        field[ie * m2 + je] = if node == DEAD { 0.0 } else { x[node as usize] };
                    }
                }
                continue;
            }
            let (bx, by) = LOCAL[b];
            for ie in 0..full[0] {
                let i = model(ie + bx, shift[0]);
                for je in 0..full[1] {
                    let j = model(je + by, shift[1]);
                    field[ie * m2 + je] = x[i + j * nx1];
                }
            }
        }
        for b in 0..4 {
            self.forward(&mut real[b], full[0], &mut spec[b], s);
        }
        self.products(&spec, &mut out);
        let read = shift[0]..shift[0] + self.mesh.nx;
        for (a, o) in out.iter_mut().enumerate() {
            self.inverse(o, &mut real[a], read.clone(), s);
        }
        // Scatter: node i collects y_a of each model element having it as local node a.
        y.iter_mut().for_each(|v| *v = 0.0);
        let nx = self.mesh.nx;
        for (a, field) in real.iter().enumerate() {
            let (ax, ay) = LOCAL[a];
            for ie in 0..nx {
                let row = (ie + shift[0]) * m2;
                for je in 0..self.mesh.ny {
                    let node = match self.gather {
                        Some(_) if !self.mesh.is_live(ie + je * nx) => continue,
                        Some(_) => self.mesh.element_nodes(ie + je * nx)[a],
                        None => (ie + ax) + (je + ay) * nx1,
                    };
                    y[node] += field[row + je + shift[1]];
                }
            }
        }
        s.real = real;
        s.spec = spec;
        s.out = out;
    }

    /// y_a = Σ_b K̂_ab w_b, frequency by frequency.
    fn products(&self, spec: &[Vec<Complex<f64>>; 4], out: &mut [Vec<Complex<f64>>; 4]) {
        if !self.mirrored {
            for (a, o) in out.iter_mut().enumerate() {
                let k = &self.kernels[a * 4..a * 4 + 4];
                for f in 0..o.len() {
                    o[f] = k[0][f] * spec[0][f]
                        + k[1][f] * spec[1][f]
                        + k[2][f] * spec[2][f]
                        + k[3][f] * spec[3][f];
                }
            }
            return;
        }
        // One pass over the 10 kept spectra (K̂_ba = conj(K̂_ab)).
        let k = &self.kernels;
        let [k00, k01, k02, k03, k11, k12, k13, k22, k23, k33] = [
            &k[pair_index(0, 0)],
            &k[pair_index(0, 1)],
            &k[pair_index(0, 2)],
            &k[pair_index(0, 3)],
            &k[pair_index(1, 1)],
            &k[pair_index(1, 2)],
            &k[pair_index(1, 3)],
            &k[pair_index(2, 2)],
            &k[pair_index(2, 3)],
            &k[pair_index(3, 3)],
        ];
        let [w0, w1, w2, w3] = [&spec[0], &spec[1], &spec[2], &spec[3]];
        let [o0, o1, o2, o3] = out;
        for f in 0..o0.len() {
            let (a, b, c, d) = (w0[f], w1[f], w2[f], w3[f]);
            let (p01, p02, p03) = (k01[f], k02[f], k03[f]);
            let (p12, p13, p23) = (k12[f], k13[f], k23[f]);
            o0[f] = k00[f] * a + p01 * b + p02 * c + p03 * d;
            o1[f] = p01.conj() * a + k11[f] * b + p12 * c + p13 * d;
            o2[f] = p02.conj() * a + p12.conj() * b + k22[f] * c + p23 * d;
            o3[f] = p03.conj() * a + p13.conj() * b + p23.conj() * c + k33[f] * d;
        }
    }

    /// T_ij from the pair table, summing the model element pairs and their mirror images.
    fn entry(&self, table: &PairTable, i: usize, j: usize) -> f64 {
        let nx1 = self.mesh.nodes_x();
        let (pi, qi) = (i % nx1, i / nx1);
        let (pj, qj) = (j % nx1, j / nx1);
        let full = self.mesh.full_elements();
        let mut sum = 0.0;
        for a in 0..4 {
            let (ax, ay) = LOCAL[a];
            if pi < ax || qi < ay || pi - ax >= self.mesh.nx || qi - ay >= self.mesh.ny {
                continue;
            }
            let e0 = (
                (pi - ax + self.shift[0]) as isize,
                (qi - ay + self.shift[1]) as isize,
            );
            for (fi, fj) in preimages(&self.mesh, self.shift, pj, qj) {
                for b in 0..4 {
                    let (bx, by) = LOCAL[b];
                    if fi < bx || fj < by || fi - bx >= full[0] || fj - by >= full[1] {
                        continue;
                    }
                    let e1 = ((fi - bx) as isize, (fj - by) as isize);
                    sum += symmetric(table, e1.0 - e0.0, e1.1 - e0.1, a, b);
                }
            }
        }
        self.constant * sum
    }

    fn diagonal(&self, table: &PairTable) -> Vec<f64> {
        match &self.gather {
            Some(gather) => self.jointed_diagonal(table, gather),
            None => (0..self.len()).map(|i| self.entry(table, i, i)).collect(),
        }
    }

    /// T_ii of a jointed mesh from the pair table: c Σ over the model elements e0 holding copy
    /// i (at corner a) and the whole-plate elements e1 reading it (at corner b, through the
    /// gather map: the copy itself and its mirror images) of I_ab(e1 − e0).
    fn jointed_diagonal(&self, table: &PairTable, gather: &[u32]) -> Vec<f64> {
        let full = self.mesh.full_elements();
        let per = full[0] * full[1];
        let mut readers: Vec<Vec<(isize, isize, usize)>> = vec![Vec::new(); self.len()];
        for (k, &node) in gather.iter().enumerate().filter(|(_, &n)| n != DEAD) {
            let (b, cell) = (k / per, k % per);
            readers[node as usize].push(((cell / full[1]) as isize, (cell % full[1]) as isize, b));
        }
        let nx = self.mesh.nx;
        let topo = self.mesh.topo.as_ref();
        (0..self.len())
            .map(|i| {
                let mut sum = 0.0;
                for &(e0, a) in topo.map_or(&[][..], |t| t.incident(i)) {
                    let p0 = (
                        (e0 % nx + self.shift[0]) as isize,
                        (e0 / nx + self.shift[1]) as isize,
                    );
                    for &(p1x, p1y, b) in &readers[i] {
                        sum += symmetric(table, p1x - p0.0, p1y - p0.1, a, b);
                    }
                }
                self.constant * sum
            })
            .collect()
    }
}

/// The gather map's entry for a cell outside a shaped plate: no node, no pressure.
const DEAD: u32 = u32::MAX;

/// The gather map of a jointed or shaped mesh (see [`ToeplitzCompliance`]'s `gather`): whole-plate element
/// (I, J) is the model element at |I − shift| (mirrored: shift − 1 − I) with its corners
/// reflected; `None` on a plain grid.
fn gather_map(mesh: &Mesh, shift: [usize; 2]) -> Option<Vec<u32>> {
    mesh.topo.as_ref()?;
    let full = mesh.full_elements();
    let mut gather = vec![0u32; 4 * full[0] * full[1]];
    let fold = |p: usize, s: usize| {
        if p >= s {
            (p - s, false)
        } else {
            (s - 1 - p, true)
        }
    };
    for b in 0..4 {
        for ie in 0..full[0] {
            let (mi, fx) = fold(ie, shift[0]);
            for je in 0..full[1] {
                let (mj, fy) = fold(je, shift[1]);
                let mut corner = b;
                if fx {
                    corner = pairs::MIRROR_X[corner];
                }
                if fy {
                    corner = pairs::MIRROR_Y[corner];
                }
                let e = mi + mj * mesh.nx;
                gather[(b * full[0] + ie) * full[1] + je] = if mesh.is_live(e) {
                    mesh.element_nodes(e)[corner] as u32
                } else {
                    DEAD
                };
            }
        }
    }
    Some(gather)
}

/// Bytes a [`ToeplitzCompliance`] of `mesh` holds: 16 kernel spectra (10 on a whole plate) and
/// 8 work arrays of the padded grid, the pair table while it is built (16 doubles per
/// whole-plate offset), and the diagonal.
pub fn toeplitz_bytes(mesh: &Mesh) -> usize {
    let full = mesh.full_elements();
    let m = [
        fft_size(full[0] + mesh.nx - 1),
        fft_size(full[1] + mesh.ny - 1),
    ];
    let h2 = m[1] / 2 + 1;
    let kernels = if mesh.sym_x || mesh.sym_y { 16 } else { 10 };
    let spectra = (kernels + 4 + 4 + 1) * h2 * m[0] * 16;
    let real = 4 * m[0] * m[1] * 8;
    let table = full[0] * full[1] * 16 * 8;
    let gather = if mesh.topo.is_some() {
        full[0] * full[1] * 4 * 4
    } else {
        0
    };
    spectra + real + table + gather + mesh.n_nodes() * 8
}

#[cfg(test)]
mod tests;
