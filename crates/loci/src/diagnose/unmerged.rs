//! The equations of a group without substitution: every equality between parameters stays
//! an explicit row, so that every row belongs to one constraint (or one entity's implicit
//! condition) that a report can name.

use super::report::Member;
use crate::equations::{compile_unmerged, compile_unmerged_only, Kernel, Owner, Rows};
use crate::error::ModelError;
use crate::model::{GroupId, System};

/// The size of the move off a point where an equation that does not hold has no gradient,
/// relative to its residual and to each unknown moved (Newton's own nudge).
const NUDGE: f64 = 1e-3;

/// Marks a parameter that is a constant of the group.
pub(crate) const CONSTANT: u32 = u32::MAX;

/// One kernel's place in the Jacobian.
pub(crate) struct Block {
    /// First row.
    pub row0: usize,
    /// First Jacobian value (a dense `rows x cols.len()` block, row-major).
    pub jv0: usize,
    /// Unknown local slots of the kernel, and the column of each.
    pub active: Vec<u16>,
    pub cols: Vec<u32>,
}

/// All equations of a group, unmerged, with the sparsity of their Jacobian.
pub(crate) struct Equations<'s> {
    /// The system and group they were compiled from.
    pub sys: &'s System,
    pub group: GroupId,
    pub kernels: Vec<Kernel>,
    /// The kernels of entities' implicit conditions, ascending.
    pub implicit: Vec<usize>,
    /// Per kernel: the columns of its entity's own parameters (a carried point's
    /// coordinates, a normal's quaternion), empty for a constraint's kernel or an entity
    /// without parameters of its own (an arc).
    pub own_cols: Vec<Vec<u32>>,
    pub blocks: Vec<Block>,
    /// Per parameter (in [`System::params`] order): its column, or [`CONSTANT`].
    pub col_of_param: Vec<u32>,
    /// Per column: the parameter.
    pub param_of_col: Vec<usize>,
    /// Per row: its kernel.
    pub row_kernel: Vec<u32>,
    pub rows: usize,
    /// Per column: `(row, index into the Jacobian values)`.
    pub columns: Vec<Vec<(u32, u32)>>,
    pub nnz: usize,
}

/// The equations linearised at a point, with rows scaled to unit length.
pub(crate) struct Linear {
    /// Residuals.
    pub r: Vec<f64>,
    /// Jacobian values, each row divided by its length.
    pub jn: Vec<f64>,
    /// One over the length of each Jacobian row (0 for an empty row).
    pub inv: Vec<f64>,
}

impl Linear {
    /// The normalised residual of `row`.
    pub fn rn(&self, row: usize) -> f64 {
        self.r[row] * self.inv[row]
    }
}

impl<'s> Equations<'s> {
    /// Compiles `group` of `sys`; `values` (the starting values) pick branches and the
    /// positions `where_dragged` keeps, exactly as the solver does.
    pub fn new(sys: &'s System, group: GroupId, values: &[f64]) -> Result<Self, ModelError> {
        Self::from_kernels(sys, group, compile_unmerged(sys, group, values, false)?)
    }

    /// The equations of the constraints and entities `keep` accepts only.
    pub fn only(
        sys: &'s System,
        group: GroupId,
        values: &[f64],
        keep: &dyn Fn(Owner) -> bool,
    ) -> Result<Self, ModelError> {
        Self::from_kernels(
            sys,
            group,
            compile_unmerged_only(sys, group, values, false, keep)?,
        )
    }

    fn from_kernels(
        sys: &'s System,
        group: GroupId,
        kernels: Vec<Kernel>,
    ) -> Result<Self, ModelError> {
        let params = sys.params();
        let mut col_of_param = vec![CONSTANT; params.len()];
        let mut param_of_col = Vec::new();
        for (i, p) in params.iter().enumerate() {
            if p.group == group {
                col_of_param[i] = param_of_col.len() as u32;
                param_of_col.push(i);
            }
        }
        let mut columns: Vec<Vec<(u32, u32)>> = vec![Vec::new(); param_of_col.len()];
        let mut blocks = Vec::with_capacity(kernels.len());
        let mut row_kernel = Vec::new();
        let (mut row, mut jv) = (0usize, 0usize);
        for (ki, k) in kernels.iter().enumerate() {
            let mut active = Vec::new();
            let mut cols = Vec::new();
            for (s, &p) in k.locals.iter().enumerate() {
                let c = col_of_param[p as usize];
                if c != CONSTANT {
                    active.push(s as u16);
                    cols.push(c);
                }
            }
            for r in 0..k.rows {
                for (ci, &c) in cols.iter().enumerate() {
                    columns[c as usize].push(((row + r) as u32, (jv + r * cols.len() + ci) as u32));
                }
                row_kernel.push(ki as u32);
            }
            let w = cols.len();
            blocks.push(Block {
                row0: row,
                jv0: jv,
                active,
                cols,
            });
            row += k.rows;
            jv += k.rows * w;
        }
        let implicit = (0..kernels.len())
            .filter(|&k| matches!(kernels[k].owner, Owner::Entity(_)))
            .collect();
        let own_cols = kernels
            .iter()
            .map(|k| match k.owner {
                Owner::Entity(e) => sys.entity(e).map_or_else(Vec::new, |ent| {
                    ent.kind
                        .params()
                        .iter()
                        .filter_map(|&p| sys.param_index(p))
                        .map(|i| col_of_param[i])
                        .filter(|&c| c != CONSTANT)
                        .collect()
                }),
                Owner::Constraint(_) => Vec::new(),
            })
            .collect();
        Ok(Self {
            sys,
            group,
            kernels,
            implicit,
            own_cols,
            blocks,
            col_of_param,
            param_of_col,
            row_kernel,
            rows: row,
            columns,
            nnz: jv,
        })
    }

    /// The owner of a kernel, as reported.
    pub fn member(&self, kernel: usize) -> Member {
        match self.kernels[kernel].owner {
            Owner::Constraint(c) => Member::Constraint(c),
            Owner::Entity(e) => Member::Entity(e),
        }
    }

    /// The kernel of `m`, if it has equations here.
    pub fn kernel_of(&self, m: Member) -> Option<usize> {
        let o = match m {
            Member::Constraint(c) => Owner::Constraint(c),
            Member::Entity(e) => Owner::Entity(e),
        };
        self.kernels.iter().position(|k| k.owner == o)
    }

    /// The entries `(column, index into the Jacobian values)` of `row`.
    pub fn row_entries(&self, row: usize) -> impl Iterator<Item = (u32, u32)> + '_ {
        let b = &self.blocks[self.row_kernel[row] as usize];
        let r = row - b.row0;
        let w = b.cols.len();
        b.cols
            .iter()
            .enumerate()
            .map(move |(ci, &c)| (c, (b.jv0 + r * w + ci) as u32))
    }

    /// Residuals only, at `values` (one per parameter).
    pub fn residuals(&self, values: &[f64], r: &mut [f64]) {
        let mut xs = Vec::new();
        for (k, b) in self.kernels.iter().zip(&self.blocks) {
            k.gather(values, &mut xs);
            let mut out = Rows::new();
            k.eq.eval(&xs, &mut out);
            r[b.row0..b.row0 + k.rows].copy_from_slice(&out.v[..k.rows]);
        }
    }

    /// Residuals and the row-normalised Jacobian at `values`. Derivatives that are not finite
    /// (a distance between coincident points) count as zero: such a row constrains nothing
    /// to first order.
    pub fn linearise(&self, values: &[f64]) -> Linear {
        let mut r = vec![0.0; self.rows];
        let mut jv = vec![0.0; self.nnz];
        let mut xs = Vec::new();
        for (k, b) in self.kernels.iter().zip(&self.blocks) {
            k.gather(values, &mut xs);
            let w = b.cols.len();
            if w == 0 {
                // Constants only: no derivatives to take, just the values.
                let mut out = Rows::new();
                k.eq.eval(&xs, &mut out);
                r[b.row0..b.row0 + k.rows].copy_from_slice(&out.v[..k.rows]);
                continue;
            }
            k.eq.jacobian_active(
                &xs,
                &b.active,
                &mut r[b.row0..b.row0 + k.rows],
                &mut jv[b.jv0..b.jv0 + k.rows * w],
            );
        }
        let mut inv = vec![0.0; self.rows];
        for v in &mut jv {
            if !v.is_finite() {
                *v = 0.0;
            }
        }
        for col in &self.columns {
            for &(row, idx) in col {
                inv[row as usize] += jv[idx as usize] * jv[idx as usize];
            }
        }
        for v in &mut inv {
            *v = if *v > 0.0 { 1.0 / v.sqrt() } else { 0.0 };
        }
        for col in &self.columns {
            for &(row, idx) in col {
                jv[idx as usize] *= inv[row as usize];
            }
        }
        Linear { r, jn: jv, inv }
    }

    /// The equations linearised off `values`, when an equation that does not hold there
    /// (beyond `tol`) has unknowns but no gradient: at a point where the unknowns of every
    /// such equation are moved by a small amount in a generic direction, as Newton moves them.
    /// `None` when there is none.
    ///
    /// A distance between two points that coincidences elsewhere have put on top of each
    /// other has no direction where the solve stopped: its row is empty, so it stood alone as
    /// its own circuit, which holds alone, and the conflict it takes part in went unnamed (a
    /// 3D sketch with points 5 = 10 and 10 = 11 and 1.2 between 5 and 11: `did_not_converge`
    /// where SolveSpace names the distance). Off that point the row has a direction, the
    /// coincidences' rows span it, and the circuit of the three is the conflict. What the
    /// circuits propose is still solved alone before it is named, so the move can add no
    /// false claim.
    pub fn linearise_off_singular(&self, values: &[f64], lin: &Linear, tol: f64) -> Option<Linear> {
        let mut moved: Option<Vec<f64>> = None;
        let mut done = vec![false; self.param_of_col.len()];
        for i in 0..self.rows {
            let r = lin.r[i];
            if lin.inv[i] != 0.0 || r.abs() <= tol || !r.is_finite() {
                continue;
            }
            let size = NUDGE * r.abs().max(1.0);
            for (c, _) in self.row_entries(i) {
                let c = c as usize;
                if std::mem::replace(&mut done[c], true) {
                    continue;
                }
                let x = moved.get_or_insert_with(|| values.to_vec());
                let p = self.param_of_col[c];
                x[p] += size * values[p].abs().max(1.0) * crate::solve::newton::generic(c, 0);
            }
        }
        moved.map(|x| self.linearise(&x))
    }

    /// `out = Jn v` (rows).
    pub fn mul(&self, lin: &Linear, v: &[f64], out: &mut [f64]) {
        out.iter_mut().for_each(|x| *x = 0.0);
        for (c, col) in self.columns.iter().enumerate() {
            let vc = v[c];
            if vc != 0.0 {
                for &(row, idx) in col {
                    out[row as usize] += lin.jn[idx as usize] * vc;
                }
            }
        }
    }

    /// `out = Jnᵀ y` (columns).
    pub fn mul_t(&self, lin: &Linear, y: &[f64], out: &mut [f64]) {
        for (c, col) in self.columns.iter().enumerate() {
            out[c] = col
                .iter()
                .map(|&(row, idx)| lin.jn[idx as usize] * y[row as usize])
                .sum();
        }
    }
}
