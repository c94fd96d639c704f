//! Dense linear solve with row and column equilibration, shared by the contact solvers' N×N
//! systems (half-space `auto`, spectral layer): takes A and r, hands on x with A x = r (zeros when
//! A is singular). Rows and columns are scaled to a largest entry of 1 before nalgebra's
//! full-pivot LU, because the columns of fast creep modes scale like 1/μⱼ.

use nalgebra::{DMatrix, DVector};

/// Solve `a x = r` after row and column equilibration (zeros when singular).
pub(crate) fn solve_equilibrated(mut a: DMatrix<f64>, mut r: DVector<f64>) -> DVector<f64> {
    let size = r.len();
    // row and column equilibration
    for i in 0..size {
        let s = (0..size).map(|j| a[(i, j)].abs()).fold(0.0, f64::max);
        if s > 0.0 && s.is_finite() {
            for j in 0..size {
                a[(i, j)] /= s;
            }
            r[i] /= s;
        }
    }
    let mut colscale = vec![1.0; size];
    for (j, cs) in colscale.iter_mut().enumerate() {
        let s = (0..size).map(|i| a[(i, j)].abs()).fold(0.0, f64::max);
        if s > 0.0 && s.is_finite() {
            *cs = s;
            for i in 0..size {
                a[(i, j)] /= s;
            }
        }
    }
    let mut x = a
        .full_piv_lu()
        .solve(&r)
        .unwrap_or_else(|| DVector::zeros(size));
    for j in 0..size {
        x[j] /= colscale[j];
    }
    x
}
